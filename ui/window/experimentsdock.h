// The Experiments panel in the window: its dock (tabbed with the device log), and the simulated
// hand's panel held idle while an experiment runs (the runner lets go of the hand itself).
#pragma once

class QDockWidget;
class QMainWindow;

namespace hatpic {

class DeviceClient;
class PlotPanel;
class SimulatorPanel;

//! Adds the dock "experimentsDock" (its panel "experimentsPanel"), hidden and tabbed behind
//! `tabWith`.
QDockWidget *addExperimentsDock(QMainWindow *window, DeviceClient *client, PlotPanel *plots,
                                SimulatorPanel *hand, QDockWidget *tabWith);

} // namespace hatpic
