// The plots follow the widgets' theme: a QCustomPlot's background, axes, grids, tick labels
// and legends take their colours from its palette (base, text), again whenever the palette
// changes (the light/dark theme switched). The data colours (palette.h) are chosen to read on
// both backgrounds and are left alone.
#pragma once

#include <QColor>

class QCPScatterStyle;
class QCustomPlot;
class QPalette;

namespace hatpic::plottheme {

//! The text of a legend entry whose series is hidden (readable, but receding, on both themes).
inline const QColor kHiddenLegendText(160, 160, 160);

//! Colours the plot's frame from `palette` (not its data) and replots.
void apply(QCustomPlot *plot, const QPalette &palette);
//! Applies the plot's palette now and after every palette change.
void follow(QCustomPlot *plot);
//! `fa` (0…1) of `a`, the rest of `b`: a theme colour derived from two of the palette's.
QColor mix(const QColor &a, const QColor &b, double fa);
//! Whether `palette` is a dark one: its window colour is darker than mid-grey.
bool isDark(const QPalette &palette);
//! The live operating point's disc (stiffness view, XY view): palette::kLivePoint ringed in the
//! theme's text colour, so that it stands out on the light and on the dark background.
QCPScatterStyle livePointStyle(const QPalette &palette);

} // namespace hatpic::plottheme
