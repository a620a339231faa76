// The Experiments panel in the window: its dock (tabbed with the device log) holding the
// measurements and the stability map of the edited tuning, and the simulated
// hand's panel held idle while an experiment runs (the runner lets go of the hand itself).
#pragma once

class QDockWidget;
class QMainWindow;

namespace hatpic {

struct WindowDockParts;

//! Adds the dock "experimentsDock" (its tabs: the panel "experimentsPanel" on the parts' client
//! and simulator, and the stability map "stabilityMap" of their editor's tuning), hidden and
//! tabbed behind `tabWith`.
QDockWidget *addExperimentsDock(QMainWindow *window, const WindowDockParts &parts,
                                QDockWidget *tabWith);

} // namespace hatpic
