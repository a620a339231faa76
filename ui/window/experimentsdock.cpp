#include "window/experimentsdock.h"

#include "experiments/experimentspanel.h"
#include "simulator/simulatorpanel.h"

#include <QDockWidget>
#include <QMainWindow>

namespace hatpic {

QDockWidget *addExperimentsDock(QMainWindow *window, DeviceClient *client, PlotPanel *plots,
                                SimulatorPanel *hand, QDockWidget *tabWith)
{
    auto *panel = new ExperimentsPanel(client, plots, window);
    panel->setObjectName(QStringLiteral("experimentsPanel"));
    auto *dock = new QDockWidget(QObject::tr("Experiments"), window);
    dock->setObjectName(QStringLiteral("experimentsDock"));
    dock->setWidget(panel);
    window->addDockWidget(Qt::BottomDockWidgetArea, dock);
    if (tabWith)
        window->tabifyDockWidget(tabWith, dock);
    dock->hide();
    // The simulated hand is idle for the run (ExperimentRunner): its panel says so and takes
    // no input until the run ends and the hand is back.
    QObject::connect(panel, &ExperimentsPanel::runningChanged, hand,
                     &SimulatorPanel::setHeldByExperiment);
    return dock;
}

} // namespace hatpic
