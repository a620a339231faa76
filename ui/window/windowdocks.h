// The window's docks and where they open: Parameters and Stiffness on the right, the simulated
// hand under the plots, and the panels opened from the View menu (device log, Bridge,
// Experiments, A/B, notes, XY view, torque breakdown) tabbed together under the plots
// (BottomDocks). Each dock's toggle goes into the View menu.
#pragma once

#include <QList>

class QAction;
class QDockWidget;
class QMainWindow;
class QMenu;
class QPlainTextEdit;

namespace hatpic {

class DeviceClient;
class ParameterEditor;
class PlotActions;
class PlotPanel;
class ProfileController;
class SimulatedJoystick;
class SimulatorPanel;
class StiffnessView;
class TuningModel;

//! What the docks hold or are wired to, and the menu that gets their toggles.
struct WindowDockParts
{
    DeviceClient *client = nullptr;
    PlotPanel *plots = nullptr;
    PlotActions *plotActions = nullptr;
    ProfileController *profiles = nullptr;
    TuningModel *tuning = nullptr; //!< the window's
    ParameterEditor *editor = nullptr;
    StiffnessView *stiffness = nullptr;
    SimulatorPanel *simPanel = nullptr;
    SimulatedJoystick *simulator = nullptr; //!< the one the window connects through
    QMenu *view = nullptr;
};

//! The docks the window itself reaches; the others are only shown and hidden by their toggles.
struct WindowDocks
{
    QDockWidget *parameters = nullptr; //!< "parametersDock"
    QDockWidget *stiffness = nullptr;  //!< "stiffnessDock"
    QDockWidget *simulator = nullptr;  //!< "simulatorDock": shown for a simulated device only
    QDockWidget *bridge = nullptr;     //!< "bridgeDock": its bridge stops through the client
    QDockWidget *log = nullptr;        //!< "logDock"
    QPlainTextEdit *logView = nullptr; //!< the device's log lines and the session's notices
    //! Ctrl+Shift+B Bridge, X Experiments, C A/B, N Notes, L Device log: each brings its panel
    //! to the front (shown, its tab raised), or hides it when it is in front already.
    QList<QAction *> panelShortcuts;
    ParameterEditor *editor = nullptr; //!< the Parameters dock's (its width follows it)
};

//! Adds every dock to `window`, sized and placed, their toggles to `parts.view`.
WindowDocks addWindowDocks(QMainWindow *window, const WindowDockParts &parts);
//! The docks' sizes of a first launch (View → Reset layout applies them again).
void resizeDocksToDefault(QMainWindow *window, const WindowDocks &docks);

} // namespace hatpic
