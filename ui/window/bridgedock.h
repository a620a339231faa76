// The Bridge panel in the window: its dock, tabbed with another, and its wiring to the
// profile (host.bridge: opened, edited, saved) and to the reference mode.
#pragma once

class QDockWidget;
class QMainWindow;

namespace hatpic {

class DeviceClient;
class ProfileController;
class TuningModel;

//! Adds the dock "bridgeDock" (its panel "bridgePanel") to `window`, tabbed behind `tabWith`.
QDockWidget *addBridgeDock(QMainWindow *window, DeviceClient *client, ProfileController *profiles,
                           TuningModel *tuning, QDockWidget *tabWith);

} // namespace hatpic
