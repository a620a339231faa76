// Where the panels under the plots open. The simulated hand sits there, and so do the panels
// opened from the View menu (device log, Bridge, Experiments, A/B, notes, XY view, torque
// breakdown), which share one place as tabs. The hand stands beside them only where the area
// under the plots holds both at their preferred widths (1920 px screens); where it does not
// (1280×720) the hand is one of those tabs, alone while no panel is open. Placed ahead of
// time, so that opening a panel never squeezes it beside the hand, nor pushes the docks on the
// right out of their width (issue 21: at 1280×720 the Experiments panel beside the hand once
// clipped the Parameters panel and hid Run). A panel the user opens comes to the front, tall
// enough to be used (at most half the window); closing the last one gives the hand back the
// height it had.
#pragma once

#include <QList>
#include <QObject>

class QDockWidget;
class QMainWindow;

namespace hatpic {

class BottomDocks : public QObject
{
    Q_OBJECT
public:
    //! Share of the window's height a panel may take when it opens.
    static constexpr double kMaxHeightShare = 0.5;

    //! `hand`: the simulated hand's dock, under the plots.
    BottomDocks(QMainWindow *window, QDockWidget *hand);

    //! A panel of the group (already tabbed with the others): brought forward whenever the
    //! user opens it (its View-menu toggle).
    void add(QDockWidget *panel);
    //! Shows `panel` in front of its tabs, at a usable height.
    void open(QDockWidget *panel);
    //! Puts the hand beside the panels or among their tabs, for the area's width now.
    void placeHand();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QMainWindow *m_window;
    QDockWidget *m_hand;
    QList<QDockWidget *> m_panels;
    int m_handHeight = 0;       //!< the hand's height before a panel made the area taller [px]
    bool m_placeQueued = false; //!< a placeHand() waits for the event loop
    //! The hand is one of the panels' tabs (by placeHand(); Qt lists only visible tab mates).
    //! False at first: as the window builds it, or as a saved layout had it (which a narrow
    //! window tabs again, harmlessly if it already was).
    bool m_handTabbed = false;
};

} // namespace hatpic
