// measure_screenshot OUT.png [WIDTH HEIGHT] — the measuring tools in the real main window,
// connected to the built-in simulator with its gentle hand: after a few seconds the plots are
// paused, the cursors A and B are on, the XY view and the torque breakdown docks are open (side
// by side from 1600 px wide, tabs below), and the window is grabbed at 1400×900 (or
// WIDTH×HEIGHT). Run it under Xvfb:
//   xvfb-run -a -s "-screen 0 1280x720x24" build/bench/measure_screenshot
//   docs/screenshot-measure-1280x720.png 1280 720
#include "plots/measurecursors.h"
#include "plots/plotfeed.h"
#include "plots/plotpanel.h"
#include "screenshotwindow.h"

#include <QAction>
#include <QDockWidget>

using namespace hatpic;

int main(int argc, char *argv[])
{
    return runScreenshot(
        argc, argv, "measure_screenshot", 9800, [](MainWindow &window, QSize size) {
            auto *xy = window.findChild<QDockWidget *>(QStringLiteral("xyDock"));
            auto *breakdown = window.findChild<QDockWidget *>(QStringLiteral("breakdownDock"));
            if (size.width() >= 1600) {
                // (A dock in a tab group would take the other as a tab: out of it first.)
                window.removeDockWidget(xy);
                window.removeDockWidget(breakdown);
                window.addDockWidget(Qt::BottomDockWidgetArea, xy);
                window.splitDockWidget(xy, breakdown, Qt::Horizontal);
            }
            breakdown->toggleViewAction()->trigger(); // as the View menu opens them
            xy->toggleViewAction()->trigger();
            QTimer::singleShot(9000, &window, [&window] {
                window.findChild<PlotFeed *>(QStringLiteral("plotFeed"))->togglePause();
                auto *plots = window.findChild<PlotPanel *>(QStringLiteral("plotPanel"));
                window.findChild<QAction *>(QStringLiteral("measureAction"))->trigger();
                plots->measure()->setTime(0, plots->viewEnd() - 4.2);
                plots->measure()->setTime(1, plots->viewEnd() - 1.7);
                plots->repaintNow();
            });
        });
}
