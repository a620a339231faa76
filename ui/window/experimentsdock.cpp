#include "window/experimentsdock.h"

#include "editor/parametereditor.h"
#include "experiments/experimentspanel.h"
#include "experiments/stabilitymapview.h"
#include "simulator/simulatorpanel.h"
#include "window/windowdocks.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QTabWidget>

namespace hatpic {

QDockWidget *addExperimentsDock(QMainWindow *window, const WindowDockParts &parts,
                                QDockWidget *tabWith)
{
    auto *panel = new ExperimentsPanel(parts.client, parts.simulator, parts.plots, window);
    panel->setObjectName(QStringLiteral("experimentsPanel"));
    // The stability map of the teleoperation loop for the tuning being edited, beside the
    // measurements (docs/experiments.md § Stability map).
    auto *map = new StabilityMapView(*parts.editor->model(), window);
    map->setObjectName(QStringLiteral("stabilityMap"));
    auto *tabs = new QTabWidget(window);
    tabs->setObjectName(QStringLiteral("experimentsTabs"));
    // Tabs on the side: the panel's height is what fits at 720 px (tst_windowlayout).
    tabs->setTabPosition(QTabWidget::West);
    tabs->setDocumentMode(true);
    tabs->addTab(panel, QObject::tr("Measure"));
    tabs->addTab(map, QObject::tr("Stability map"));
    auto *dock = new QDockWidget(QObject::tr("Experiments"), window);
    dock->setObjectName(QStringLiteral("experimentsDock"));
    dock->setWidget(tabs);
    window->addDockWidget(Qt::BottomDockWidgetArea, dock);
    if (tabWith)
        window->tabifyDockWidget(tabWith, dock);
    dock->hide();
    // The simulated hand is idle for the run (ExperimentRunner): its panel says so and takes
    // no input until the run ends and the hand is back.
    QObject::connect(panel, &ExperimentsPanel::runningChanged, parts.simPanel,
                     &SimulatorPanel::setHeldByExperiment);
    return dock;
}

} // namespace hatpic
