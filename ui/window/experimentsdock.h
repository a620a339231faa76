// The Experiments panel in the window: its dock (tabbed with the device log) holding the
// measurements and the stability map of the edited tuning, and the simulated
// hand's panel held idle while an experiment runs (the runner lets go of the hand itself).
#pragma once

class QDockWidget;
class QMainWindow;

namespace hatpic {

class DeviceClient;
class ParameterEditor;
class PlotPanel;
class SimulatorPanel;

//! Adds the dock "experimentsDock" (its tabs: the panel "experimentsPanel" and the stability
//! map "stabilityMap" of `editor`'s tuning), hidden and tabbed behind `tabWith`.
QDockWidget *addExperimentsDock(QMainWindow *window, DeviceClient *client, PlotPanel *plots,
                                SimulatorPanel *hand, ParameterEditor *editor,
                                QDockWidget *tabWith);

} // namespace hatpic
