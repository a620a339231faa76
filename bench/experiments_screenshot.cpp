// experiments_screenshot OUT.png [WIDTH HEIGHT] — makes docs/screenshot-experiments.png: the
// real main window on the built-in simulator with its gentle hand, the Experiments panel opened
// as a user opens it (View → Experiments), a step response run with the form's defaults (the
// runner lets go of the simulated hand for the run and gives it back), and the grab once its
// figures and the ideal overlay are in. Run it under Xvfb:
//   xvfb-run -a -s "-screen 0 1920x1080x24" build/bench/experiments_screenshot
//   docs/screenshot-experiments.png 1920 1080
#include "experiments/experimentspanel.h"
#include "screenshotwindow.h"

#include <QAction>
#include <QDockWidget>

using namespace hatpic;

int main(int argc, char *argv[])
{
    return runScreenshot(argc, argv, "experiments_screenshot", 7000, [](MainWindow &window, QSize) {
        QTimer::singleShot(1500, &window, [&window] {
            // After the connection, which shows the hand's dock for the simulator.
            window.findChild<QDockWidget *>(QStringLiteral("experimentsDock"))
                ->toggleViewAction()
                ->trigger();
        });
        QTimer::singleShot(3000, &window, [&window] {
            auto *panel = window.findChild<ExperimentsPanel *>(QStringLiteral("experimentsPanel"));
            panel->fillDefaults();
            if (!panel->run())
                std::fprintf(stderr, "not started: %s\n", qPrintable(panel->status()));
        });
    });
}
