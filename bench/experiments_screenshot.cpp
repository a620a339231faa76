// experiments_screenshot OUT.png [WIDTH HEIGHT] — makes docs/screenshot-experiments.png: the
// real main window on the built-in simulator with the Experiments dock open, a step response
// run with the form's defaults, and the grab once its figures and the ideal overlay are in.
// Run it under Xvfb:
//   xvfb-run -a -s "-screen 0 1400x900x24" build/bench/experiments_screenshot
//   docs/screenshot-experiments.png
#include "experiments/experimentspanel.h"
#include "screenshotwindow.h"

#include <QDockWidget>

using namespace hatpic;

int main(int argc, char *argv[])
{
    return runScreenshot(
        argc, argv, "experiments_screenshot", 20000, [](MainWindow &window, QSize size) {
            auto *dock = window.findChild<QDockWidget *>(QStringLiteral("experimentsDock"));
            dock->show();
            dock->raise();
            window.resizeDocks({dock}, {size.height() * 45 / 100}, Qt::Vertical);
            QTimer::singleShot(3000, &window, [&window] {
                auto *panel =
                    window.findChild<ExperimentsPanel *>(QStringLiteral("experimentsPanel"));
                panel->fillDefaults();
                if (!panel->run())
                    std::fprintf(stderr, "not started: %s\n", qPrintable(panel->status()));
            });
        });
}
