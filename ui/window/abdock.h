// The A/B comparison and the profile's notes in the window: their docks, the other slot's
// curves in the stiffness view, and the blind test (its window, and the main window hidden
// while it runs, so nothing tells the participant which slot is on the device).
#pragma once

#include <QList>

class QDockWidget;
class QMainWindow;

namespace hatpic {

class ParameterEditor;
class ProfileController;
class StiffnessView;
class TuningModel;

//! Adds the docks "abDock" (panel "abComparePanel") and "notesDock" (editor "profileNotes"),
//! tabbed behind `tabWith` and hidden, and the blind test ("blindRunner", "blindDialog").
QList<QDockWidget *> addAbDocks(QMainWindow *window, ProfileController *profiles,
                                TuningModel *tuning, ParameterEditor *editor,
                                StiffnessView *stiffness, QDockWidget *tabWith);

} // namespace hatpic
