// The measuring views in the window: the XY view and the torque breakdown as docks (hidden
// until chosen in the View menu), the stiffness view's trail, and the caption of exported
// pictures (profile name and parameters).
#pragma once

class QDockWidget;
class QMainWindow;
class QMenu;

namespace hatpic {

class PlotActions;
class PlotPanel;
class ProfileController;
class StiffnessView;
class TuningModel;

struct MeasureDocks
{
    QDockWidget *xy = nullptr;        //!< "xyDock", its view "xyView"
    QDockWidget *breakdown = nullptr; //!< "breakdownDock", its view "torqueBreakdown"
};

//! Adds the docks to `window` at the bottom, tabbed behind `tabWith`, their toggles to `view`.
MeasureDocks addMeasureDocks(QMainWindow *window, PlotPanel *plots, PlotActions *plotActions,
                             ProfileController *profiles, TuningModel *tuning,
                             StiffnessView *stiffness, QMenu *view, QDockWidget *tabWith);

} // namespace hatpic
