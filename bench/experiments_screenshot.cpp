// experiments_screenshot OUT.png [WIDTH HEIGHT] — makes docs/screenshot-experiments.png: the
// real main window on the built-in simulator with the Experiments dock open in place of the
// simulated hand (the hand let go, so only τ_ext moves the knob), a step response run with the
// form's defaults, and the grab once its figures and the ideal overlay are in.
// Run it under Xvfb:
//   xvfb-run -a -s "-screen 0 1400x900x24" build/bench/experiments_screenshot
//   docs/screenshot-experiments.png
#include "editor/simulatorpanel.h"
#include "experiments/experimentspanel.h"
#include "screenshotwindow.h"

#include <QPushButton>

#include <QDockWidget>

using namespace hatpic;

int main(int argc, char *argv[])
{
    return runScreenshot(
        argc, argv, "experiments_screenshot", 5000, [](MainWindow &window, QSize size) {
            auto *dock = window.findChild<QDockWidget *>(QStringLiteral("experimentsDock"));
            dock->show();
            dock->raise();
            window.resizeDocks({dock}, {size.height() * 45 / 100}, Qt::Vertical);
            QTimer::singleShot(1500, &window, [&window] {
                // After the connection, which shows the hand's dock for the simulator.
                window.findChild<QDockWidget *>(QStringLiteral("simulatorDock"))->hide();
                auto *hand = window.findChild<SimulatorPanel *>();
                for (QPushButton *b : hand->findChildren<QPushButton *>()) {
                    if (b->text() == QStringLiteral("Let go"))
                        b->click();
                }
            });
            QTimer::singleShot(3000, &window, [&window] { // the knob has come to rest
                auto *panel =
                    window.findChild<ExperimentsPanel *>(QStringLiteral("experimentsPanel"));
                panel->fillDefaults();
                if (!panel->run())
                    std::fprintf(stderr, "not started: %s\n", qPrintable(panel->status()));
            });
        });
}
