// map_screenshot OUT.png [WIDTH HEIGHT] — makes docs/screenshot-stability-map.png: the real main
// window on the built-in simulator, the Experiments panel opened (View → Experiments) on its
// Stability map tab, the map of the defaults computed (the delay in use 0.15 s marked), and the
// grab once it is in. Run it under Xvfb:
//   xvfb-run -a -s "-screen 0 1280x720x24" build/bench/map_screenshot
//   docs/screenshot-stability-map.png 1280 720
#include "experiments/stabilitymapview.h"
#include "screenshotwindow.h"

#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QTabWidget>

using namespace hatpic;

int main(int argc, char *argv[])
{
    return runScreenshot(argc, argv, "map_screenshot", 9000, [](MainWindow &window, QSize) {
        QTimer::singleShot(1500, &window, [&window] {
            auto *dock = window.findChild<QDockWidget *>(QStringLiteral("experimentsDock"));
            dock->toggleViewAction()->trigger();
            dock->raise();
            auto *map = window.findChild<StabilityMapView *>(QStringLiteral("stabilityMap"));
            window.findChild<QTabWidget *>(QStringLiteral("experimentsTabs"))
                ->setCurrentWidget(map);
            map->findChild<QDoubleSpinBox *>(QStringLiteral("mapDelayInUse"))->setValue(0.15);
            if (!map->compute())
                std::fprintf(stderr, "not started: %s\n", qPrintable(map->status()));
        });
    });
}
