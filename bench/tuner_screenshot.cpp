// tuner_screenshot OUT.png [WIDTH HEIGHT] — makes docs/screenshot.png: the real main window,
// connected to the built-in simulator with its gentle hand, K_max pushed from 0.4 to 0.6 after
// a few seconds (a marker on the time axis, the device curve on the stiffness view), the cursor
// readout on, then a grab of the window at 1400×900 (or WIDTH×HEIGHT). Run it under Xvfb (see
// docs/performance.md):
//   xvfb-run -a -s "-screen 0 1400x900x24" build/bench/tuner_screenshot docs/screenshot.png
//   xvfb-run -a -s "-screen 0 1280x720x24" build/bench/tuner_screenshot
//   docs/screenshot-1280x720.png 1280 720
#include "editor/parametereditor.h"
#include "plots/plotpanel.h"
#include "screenshotwindow.h"

#include <QAction>

using namespace hatpic;

int main(int argc, char *argv[])
{
    return runScreenshot(argc, argv, "tuner_screenshot", 14200, [](MainWindow &window, QSize) {
        QTimer::singleShot(6500, &window, [&window] {
            auto *editor = window.findChild<ParameterEditor *>(QStringLiteral("parameterEditor"));
            DeviceParams params = editor->params();
            params.K_max = 0.6;
            editor->setParams(params, editor->hostParams(), QStringLiteral("K_max"));
            editor->pushAction()->trigger();
        });
        QTimer::singleShot(13800, &window, [&window] {
            auto *plots = window.findChild<PlotPanel *>(QStringLiteral("plotPanel"));
            plots->setCursorTime(plots->viewEnd() - 1.6);
            plots->repaintNow();
        });
    });
}
