// The tuner's main window assembles the folders' parts and wires them: the connection bar and
// link state, the plots and their feed (live or replay), recording, and docks for the parameter
// editor, the stiffness view, the simulated hand and the device log. It owns the one
// DeviceClient; the parameter round trip belongs to DeviceParameterLink, what the plots show to
// PlotFeed, which action sits in which menu and toolbar to WindowMenus, where each dock opens
// to addWindowDocks. Tests reach the parts by their object names (findChild), not through the
// window.
#pragma once

#include "session/deviceclient.h"
#include "sim/handinput.h"
#include "window/windowdocks.h"

#include <QMainWindow>

#include <memory>

class QAction;

class QDockWidget;
class QUndoStack;

namespace hatpic {

class ConnectionBar;
class DeviceParameterLink;
class LinkBanner;
class LinkStatsWidget;
class LinkStatusWidget;
class ParameterEditor;
class PlotActions;
class PlotFeed;
class KnobsView;
class PlotPanel;
class ProfileController;
class RecordingControls;
class ReplayBar;
class ThemeController;
class SimulatedJoystick;
class SimulatorPanel;
class StatusLine;
class StiffnessView;
class TuningModel;
class WindowActions;
class WindowMenus;

class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    static constexpr double kDefaultWindowSeconds = 10;

    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    //! Connects at once. For the simulator with no hand chosen yet, a gentle sine of the
    //! operator torque keeps the plots moving (SimulatorPanel::gentleHand()).
    void connectTo(const ConnectOptions &options);
    void disconnectDevice();
    //! Chooses the simulated hand (as if picked in the simulator panel).
    void setSimulatedHand(const HandInput &hand);
    //! Shows the Bridge panel and starts the robot bridge on ROS `rosVersion` (1 or 2) with the
    //! settings it shows (the profile's host.bridge), as View → Bridge and Enable would. False
    //! when it could not start; the panel says why.
    bool startBridge(int rosVersion);

    //! Records every sample to `csvPath` (and its .json) from the next time the device is
    //! connected (at once when it is), as Record would, starting at once whatever the plan
    //! (hatpic-tuner --record).
    void recordOnConnect(const QString &csvPath);

    //! Enters replay of a recording; false (with `error`) when it cannot be read.
    bool openRecording(const QString &csvPath, QString *error = nullptr);
    void backToLive();
    //! Opens a profile into the editor (as File → Open); false (with `error`) when refused.
    bool openProfile(const QString &path, QString *error = nullptr);

    //! Length of the plots' time window [s] (View → Window Length).
    void setWindowSeconds(double seconds);
    //! How often the plots repaint at most [Hz] (hatpic-tuner --repaint-rate).
    void setRepaintRate(double hz);

    //! Actions with a shortcut, in menu order (the Help → Keyboard shortcuts table).
    QList<QAction *> shortcutActions() const;
    //! View → Reset layout: the docks where, as large as, and shown as at a first launch (a
    //! dock shrunk once no longer stays shrunk across launches), the window fitted to its
    //! screen.
    void resetLayout();

protected:
    void closeEvent(QCloseEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    void createParts();
    void createActions();
    void connectParts();
    void readSettings();
    void writeSettings() const;

    void onStateChanged(SessionState state, const StateDetail &event);
    void onDeviceInfo(const DeviceInfo &info);
    //! The Knobs dock: a board's several knobs and its tilt (hidden for a single knob).
    void addKnobsDock();
    void setAngleInDegrees(bool degrees);
    void showStatus(const QString &message);
    void openRecordingInteractive();
    void overlayInteractive();
    void updateActions();

    DeviceClient *m_client = nullptr;
    DeviceParameterLink *m_paramLink = nullptr;
    PlotFeed *m_feed = nullptr;

    PlotPanel *m_plots = nullptr;
    PlotActions *m_plotActions = nullptr;
    ConnectionBar *m_connection = nullptr;
    LinkStatusWidget *m_linkStatus = nullptr;
    LinkBanner *m_banner = nullptr;
    LinkStatsWidget *m_stats = nullptr;
    StatusLine *m_statusLine = nullptr;
    RecordingControls *m_recording = nullptr;
    ReplayBar *m_replayBar = nullptr;
    TuningModel *m_tuning = nullptr; //!< the one tuning: edited, the device's, the sync state
    QUndoStack *m_undo = nullptr;    //!< the one undo history: edits, loads, A/B, notes
    ParameterEditor *m_editor = nullptr;
    StiffnessView *m_stiffness = nullptr;
    ProfileController *m_profiles = nullptr;
    SimulatorPanel *m_simPanel = nullptr;
    //! The simulated joystick the window connects through (the connection bar's first source);
    //! its hand is the simulator panel's.
    std::shared_ptr<SimulatedJoystick> m_simulator;

    WindowActions *m_actions = nullptr;
    WindowMenus *m_menus = nullptr;
    WindowDocks m_docks;
    KnobsView *m_knobs = nullptr;
    QDockWidget *m_knobsDock = nullptr; //!< "knobsDock": shown for a board with several knobs
    ThemeController *m_theme = nullptr;

    QString m_port;               //!< port of the current or last connection
    bool m_portSimulated = false; //!< that connection's link is a simulator
    QByteArray m_firstState;      //!< the docks as at a first launch (View → Reset layout)
    bool m_shown = false;         //!< shown once: the first window's frame fitted
    QSize m_firstSize;            //!< a first launch's size (nothing restored), else empty
};

} // namespace hatpic
