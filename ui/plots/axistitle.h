// A plot's quantity and unit written level in a corner of its axis rect, on the background's
// colour, in place of a label along the axis: it takes no room of its own, so two short plots
// stacked (the stiffness view at 1280×720, the Bode plot) never have their titles collide.
// plottheme::apply gives it the theme's text and background colours.
#pragma once

#include <QString>
#include <Qt>

class QCPAxisRect;
class QCPItemText;

namespace hatpic {

//! Object name of every corner title (how the theme finds them).
inline constexpr char kCornerTitleName[] = "cornerTitle";

//! Writes `text` in `corner` of `rect` (one corner title per rect: a second call replaces the
//! text) and returns the item.
QCPItemText *setCornerTitle(QCPAxisRect *rect, const QString &text,
                            Qt::Alignment corner = Qt::AlignTop | Qt::AlignRight);
//! The corner title of `rect`, or null.
QCPItemText *cornerTitle(const QCPAxisRect *rect);

} // namespace hatpic
