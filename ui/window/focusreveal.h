// The keyboard focus is never out of sight (issue 27): a field that gets it is scrolled into
// view, always, and a widget reached from the keyboard is ringed in the theme's highlight.
//
// One application-wide event filter. Whatever moved the focus — a shortcut (Alt+1…9, a panel's
// key), Tab, a program (Show the problem, Run) — every scroll area that holds the focused
// widget scrolls so that it is wholly in sight, innermost first. Focus from the keyboard (Tab,
// Backtab, a shortcut) also gets a ring: 21 of 24 Tab stops after the editor once showed no
// focus at all in the Fusion style (tool buttons, plots, tables, tabs). A mouse click is left
// alone: what was clicked is in sight already, and a panel that jumped under the pointer would
// be worse.
#pragma once

#include <QObject>
#include <QPointer>

class QWidget;

namespace hatpic {

class FocusRing;

class FocusReveal : public QObject
{
public:
    static constexpr int kRingWidth = 2; //!< [px], drawn just outside the widget

    //! Installs the filter on the application, once however often it is called.
    static void install();
    //! Scrolls every QScrollArea that holds `widget` until it is in sight.
    static void reveal(QWidget *widget);
    //! The ring shown now around the keyboard focus, or null (object name "focusRing").
    static QWidget *ring();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    explicit FocusReveal(QObject *parent);
    void ringAround(QWidget *widget);
    void placeRing();

    QPointer<QWidget> m_target; //!< the widget ringed
    QPointer<FocusRing> m_ring;
};

} // namespace hatpic
