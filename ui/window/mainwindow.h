// The tuner's main window: connection bar and link state, the three live plots, recording and
// replay, and docks for the parameter editor, the stiffness view, the simulated hand and the
// device log. Owns the one DeviceClient; every device call returns at once and its results
// arrive as signals on this (the GUI) thread.
#pragma once

#include "plots/samplebuffer.h"
#include "session/deviceclient.h"
#include "telemetry/recording.h"

#include <QHash>
#include <QMainWindow>

#include <optional>

class QAction;
class QDockWidget;
class QMenu;
class QPlainTextEdit;

namespace hatpic {

class ConnectionBar;
class LinkBanner;
class LinkStatsWidget;
class LinkStatusWidget;
class ParameterEditor;
class PlotActions;
class PlotPanel;
class ProfileController;
class RecordingControls;
class ReplayBar;
class ReplayController;
class SimulatorPanel;
class StiffnessView;

class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    static constexpr double kDefaultWindowSeconds = 10;

    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    //! Connects at once. For the simulator with no hand chosen yet, a gentle sine of the
    //! operator torque keeps the plots moving (gentleHand()).
    void connectTo(const ConnectOptions &options);
    void disconnectDevice();
    //! The operator input the simulator starts with: a slow sine that crosses the notch.
    static HandInput gentleHand();
    //! Chooses the simulated hand (as if picked in the simulator panel).
    void setSimulatedHand(const HandInput &hand);

    //! Enters replay of a recording; false (with `error`) when it cannot be read.
    bool openRecording(const QString &csvPath, QString *error = nullptr);
    void backToLive();
    bool isReplaying() const;

    //! Length of the plots' time window [s] (View → Window Length).
    void setWindowSeconds(double seconds);

    void setLivePaused(bool paused);
    bool isLivePaused() const;

    //! Actions with a shortcut, in menu order (the Help → Keyboard shortcuts table).
    QList<QAction *> shortcutActions() const;

    DeviceClient *client() const { return m_client; }
    PlotPanel *plotPanel() const { return m_plots; }
    const SampleBuffer &liveBuffer() const { return m_live; }
    ParameterEditor *parameterEditor() const { return m_editor; }
    ProfileController *profileController() const { return m_profiles; }
    StiffnessView *stiffnessView() const { return m_stiffness; }
    SimulatorPanel *simulatorPanel() const { return m_simPanel; }
    QDockWidget *simulatorDock() const { return m_simDock; }
    ConnectionBar *connectionBar() const { return m_connection; }
    LinkStatusWidget *linkStatus() const { return m_linkStatus; }
    LinkBanner *linkBanner() const { return m_banner; }
    LinkStatsWidget *linkStats() const { return m_stats; }
    RecordingControls *recordingControls() const { return m_recording; }
    ReplayController *replayController() const { return m_replay; }
    ReplayBar *replayBar() const { return m_replayBar; }
    QAction *connectAction() const { return m_connectAction; }
    QAction *pauseAction() const { return m_pauseAction; }
    QAction *degreesAction() const { return m_degreesAction; }
    QAction *resetReferenceAction() const { return m_resetRefAction; }
    QString lastCommandMessage() const { return m_lastCommandMessage; }

    //! `rect` made no larger than `available` and moved inside it: what the window's geometry
    //! is saved as and restored to, so that no screen ever gets a window larger than itself.
    static QRect fittedInto(const QRect &rect, const QRect &available);

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void createActions();
    void createMenus();
    void createToolBars();
    void createDocks();
    void connectClient();
    void connectEditor();
    void readSettings();
    void writeSettings() const;
    //! The available geometry of the screen showing `rect` (else this window's, else primary).
    QRect availableGeometryFor(const QRect &rect) const;

    void onStateChanged(SessionState state, const QString &detail);
    void onDeviceInfo(const DeviceInfo &info);
    void onDeviceParams(const DeviceParams &params);
    void onSamples(const SampleBatch &batch);
    void onCommandFinished(quint64 id, const CommandResult &result);
    void onReplayActive(bool active);
    void onReplayPosition(double t);
    void setAngleInDegrees(bool degrees);
    void addLiveEvent(const QString &text);
    void togglePause();
    void openRecordingInteractive();
    void showShortcuts();
    void showAbout();
    void updateActions();

    DeviceClient *m_client = nullptr;
    SampleBuffer m_live;
    QList<RecordingEvent> m_liveEvents;

    PlotPanel *m_plots = nullptr;
    PlotActions *m_plotActions = nullptr;
    ConnectionBar *m_connection = nullptr;
    LinkStatusWidget *m_linkStatus = nullptr;
    LinkBanner *m_banner = nullptr;
    LinkStatsWidget *m_stats = nullptr;
    RecordingControls *m_recording = nullptr;
    ReplayController *m_replay = nullptr;
    ReplayBar *m_replayBar = nullptr;
    ParameterEditor *m_editor = nullptr;
    StiffnessView *m_stiffness = nullptr;
    ProfileController *m_profiles = nullptr;
    SimulatorPanel *m_simPanel = nullptr;
    QPlainTextEdit *m_log = nullptr;
    QDockWidget *m_editorDock = nullptr;
    QDockWidget *m_stiffnessDock = nullptr;
    QDockWidget *m_simDock = nullptr;
    QDockWidget *m_logDock = nullptr;

    QAction *m_connectAction = nullptr;
    QAction *m_pauseAction = nullptr;
    QAction *m_degreesAction = nullptr;
    QAction *m_resetRefAction = nullptr;
    QAction *m_zeroAction = nullptr;
    QAction *m_saveDeviceAction = nullptr;
    QAction *m_openRecordingAction = nullptr;
    QAction *m_backToLiveAction = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_shortcutsAction = nullptr;
    QAction *m_aboutAction = nullptr;
    QMenu *m_viewMenu = nullptr;

    QString m_port;            //!< port of the current or last connection
    bool m_handChosen = false; //!< the user picked a simulated hand
    struct PendingPush
    {
        DeviceParams before; //!< the device's values when the push was sent
        DeviceParams pushed;
    };
    QHash<quint64, PendingPush> m_pushes; //!< pushes in flight, by request id
    QHash<quint64, QString> m_commands;   //!< other commands in flight: what they were
    QString m_lastCommandMessage;
};

} // namespace hatpic
