#include "window/mainwindow.h"

#include "connection/connectionbar.h"
#include "connection/linkbanner.h"
#include "connection/linkstatswidget.h"
#include "connection/linkstatuswidget.h"
#include "editor/parametereditor.h"
#include "editor/profilecontroller.h"
#include "editor/simulatorpanel.h"
#include "editor/stiffnessview.h"
#include "plots/plotactions.h"
#include "plots/plotpanel.h"
#include "recording/recordingcontrols.h"
#include "recording/replaybar.h"
#include "recording/replaycontroller.h"
#include "window/shortcutsdialog.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QScreen>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

// The window icon lives in this static library: its resources must be registered by hand.
static void initPlotsResources()
{
    Q_INIT_RESOURCE(window);
}

namespace hatpic {

namespace {

constexpr int kStatusMs = 6000;

const QString kSimPort = QString::fromUtf16(kSimPortName);

QString documentsDir()
{
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    return dir.isEmpty() ? QDir::homePath() : dir;
}

} // namespace

MainWindow::MainWindow(QWidget *parent) : QMainWindow(parent)
{
    setObjectName(QStringLiteral("mainWindow"));
    initPlotsResources();
    setWindowIcon(QIcon(QStringLiteral(":/icons/hatpic-tuner.png")));
    m_client = new DeviceClient(this);

    m_plots = new PlotPanel(this);
    m_plots->setSource(&m_live);
    m_banner = new LinkBanner(this);
    m_replay = new ReplayController(this);
    m_replayBar = new ReplayBar(m_replay, this);
    auto *central = new QWidget(this);
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(4, 4, 4, 0);
    layout->setSpacing(4);
    layout->addWidget(m_banner);
    layout->addWidget(m_replayBar);
    layout->addWidget(m_plots, 1);
    setCentralWidget(central);

    m_connection = new ConnectionBar(this);
    m_linkStatus = new LinkStatusWidget(this);
    m_recording = new RecordingControls(this);
    m_stats = new LinkStatsWidget(this);
    statusBar()->addPermanentWidget(m_stats);

    m_editor = new ParameterEditor(this);
    m_stiffness = new StiffnessView(this);
    m_profiles = new ProfileController(m_editor, this, this);
    m_simPanel = new SimulatorPanel(this);
    m_stiffness->setEditedParams(m_editor->params());
    m_plots->setHostParams(m_editor->hostParams());

    m_plotActions = new PlotActions(m_plots, this);
    createActions();
    createMenus();
    createToolBars();
    createDocks();
    connectClient();
    connectEditor();

    connect(m_connection, &ConnectionBar::connectRequested, this, &MainWindow::connectTo);
    connect(m_connection, &ConnectionBar::disconnectRequested, this, &MainWindow::disconnectDevice);
    connect(m_recording, &RecordingControls::startRequested, this,
            [this](const QString &path) { m_client->startRecording(path); });
    connect(m_recording, &RecordingControls::stopRequested, m_client, &DeviceClient::stopRecording);
    connect(m_replay, &ReplayController::activeChanged, this, &MainWindow::onReplayActive);
    connect(m_replay, &ReplayController::positionChanged, this, &MainWindow::onReplayPosition);
    // The replay bar's ▶ and the end of the recording change the state too.
    connect(m_replay, &ReplayController::playingChanged, this, &MainWindow::updateActions);
    connect(m_replayBar, &ReplayBar::backToLiveRequested, this, &MainWindow::backToLive);
    connect(m_plots, &PlotPanel::pausedChanged, this, [this](bool paused) {
        m_pauseAction->setChecked(paused);
        updateActions();
    });
    connect(m_plotActions, &PlotActions::windowChosen, this, &MainWindow::setWindowSeconds);
    connect(m_plotActions, &PlotActions::statusMessage, this,
            [this](const QString &message) { statusBar()->showMessage(message, kStatusMs); });

    setWindowTitle(m_profiles->windowTitle());
    readSettings();
    onStateChanged(SessionState::Disconnected, {});
}

MainWindow::~MainWindow()
{
    // The plots point at m_live, a member destroyed after the child widgets would be.
    m_plots->setSource(nullptr);
}

void MainWindow::createActions()
{
    m_connectAction = new QAction(tr("&Connect"), this);
    m_connectAction->setObjectName(QStringLiteral("connectAction"));
    m_connectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    m_connectAction->setToolTip(tr("Connect to the chosen port, or disconnect (Ctrl+K)"));
    connect(m_connectAction, &QAction::triggered, m_connection, &ConnectionBar::toggleConnection);

    m_pauseAction = new QAction(style()->standardIcon(QStyle::SP_MediaPause), tr("&Pause"), this);
    m_pauseAction->setObjectName(QStringLiteral("pauseAction"));
    m_pauseAction->setCheckable(true);
    m_pauseAction->setShortcuts({QKeySequence(Qt::Key_Space), QKeySequence(Qt::CTRL | Qt::Key_P)});
    m_pauseAction->setToolTip(tr("Freeze the plots (the link keeps recording); in replay, "
                                 "play or pause (Space, Ctrl+P)"));
    connect(m_pauseAction, &QAction::triggered, this, &MainWindow::togglePause);

    m_degreesAction = new QAction(tr("Angles in &degrees"), this);
    m_degreesAction->setCheckable(true);
    m_degreesAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    m_degreesAction->setToolTip(tr("Show angles in degrees; data and files stay in radians "
                                   "(Ctrl+D)"));
    connect(m_degreesAction, &QAction::toggled, this, &MainWindow::setAngleInDegrees);

    m_resetRefAction = new QAction(tr("Reset &p_ref"), this);
    m_resetRefAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    m_resetRefAction->setToolTip(tr("Set the reference position p_ref to 0 (Ctrl+0)"));
    connect(m_resetRefAction, &QAction::triggered, this, [this] {
        m_client->resetReference();
        addLiveEvent(tr("p_ref reset to 0"));
    });

    m_zeroAction = new QAction(tr("Set θ0 to the current &angle (ZERO)"), this);
    connect(m_zeroAction, &QAction::triggered, this,
            [this] { m_commands.insert(m_client->zero(), tr("ZERO")); });
    m_saveDeviceAction = new QAction(tr("Save parameters in the &device"), this);
    m_saveDeviceAction->setToolTip(tr("SAVE_PARAMS: the device restores them at power-up"));
    connect(m_saveDeviceAction, &QAction::triggered, this,
            [this] { m_commands.insert(m_client->saveParams(), tr("Save in device")); });

    m_openRecordingAction = new QAction(style()->standardIcon(QStyle::SP_DialogOpenButton),
                                        tr("Ope&n Recording…"), this);
    m_openRecordingAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    m_openRecordingAction->setToolTip(tr("Replay a recording (Ctrl+Shift+O)"));
    connect(m_openRecordingAction, &QAction::triggered, this,
            &MainWindow::openRecordingInteractive);
    m_backToLiveAction = new QAction(tr("Back to &Live"), this);
    m_backToLiveAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    connect(m_backToLiveAction, &QAction::triggered, this, &MainWindow::backToLive);

    m_quitAction = new QAction(tr("&Quit"), this);
    m_quitAction->setShortcut(QKeySequence::Quit);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);
    m_shortcutsAction = new QAction(tr("&Keyboard Shortcuts"), this);
    m_shortcutsAction->setShortcut(QKeySequence(Qt::Key_F1));
    connect(m_shortcutsAction, &QAction::triggered, this, &MainWindow::showShortcuts);
    m_aboutAction = new QAction(tr("&About HATPIC Tuner"), this);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::showAbout);

    QAction *undo = m_editor->undoAction();
    undo->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Z));
    QAction *redo = m_editor->redoAction();
    redo->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
}

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_profiles->openAction());
    file->addMenu(m_profiles->recentMenu());
    file->addMenu(m_profiles->presetsMenu());
    file->addAction(m_profiles->saveAction());
    file->addAction(m_profiles->saveAsAction());
    file->addSeparator();
    file->addAction(m_openRecordingAction);
    file->addAction(m_plotActions->exportImageAction());
    file->addAction(m_plotActions->exportCsvAction());
    file->addSeparator();
    file->addAction(m_quitAction);

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(m_editor->undoAction());
    edit->addAction(m_editor->redoAction());
    edit->addSeparator();
    edit->addAction(m_profiles->abToggleAction());

    QMenu *device = menuBar()->addMenu(tr("&Device"));
    device->addAction(m_connectAction);
    device->addSeparator();
    device->addAction(m_editor->pushAction());
    device->addAction(m_editor->readAction());
    device->addAction(m_editor->revertAction());
    device->addSeparator();
    device->addAction(m_resetRefAction);
    device->addAction(m_zeroAction);
    device->addAction(m_saveDeviceAction);
    device->addSeparator();
    device->addAction(m_recording->recordAction());

    QMenu *view = menuBar()->addMenu(tr("&View"));
    m_viewMenu = view;
    view->addAction(m_pauseAction);
    view->addAction(m_backToLiveAction);
    QMenu *window = view->addMenu(tr("&Window Length"));
    window->addActions(m_plotActions->windowActions());
    view->addAction(m_plotActions->autoscaleAction());
    view->addAction(m_degreesAction);
    m_plotActions->addSeriesActions(view->addMenu(tr("&Series")));
    view->addSeparator(); // the docks' toggles follow (createDocks)

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(m_shortcutsAction);
    help->addAction(m_aboutAction);
}

void MainWindow::createToolBars()
{
    QToolBar *link = addToolBar(tr("Connection"));
    link->setObjectName(QStringLiteral("connectionToolBar"));
    link->addWidget(m_connection);
    link->addSeparator();
    link->addWidget(m_linkStatus);

    addToolBarBreak();
    QToolBar *plots = addToolBar(tr("Plots"));
    plots->setObjectName(QStringLiteral("plotsToolBar"));
    plots->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    plots->addAction(m_pauseAction);
    plots->addSeparator();
    plots->addActions(m_plotActions->windowActions());
    plots->addSeparator();
    plots->addAction(m_plotActions->autoscaleAction());
    plots->addAction(m_degreesAction);
    plots->addAction(m_resetRefAction);
    plots->addSeparator();
    plots->addWidget(m_recording);
    plots->addAction(m_openRecordingAction);
}

void MainWindow::createDocks()
{
    auto makeDock = [this](const QString &title, const QString &name, QWidget *widget,
                           Qt::DockWidgetArea area) {
        auto *dock = new QDockWidget(title, this);
        dock->setObjectName(name);
        dock->setWidget(widget);
        addDockWidget(area, dock);
        return dock;
    };
    m_editorDock = makeDock(tr("Parameters"), QStringLiteral("parametersDock"), m_editor,
                            Qt::RightDockWidgetArea);
    m_stiffnessDock = makeDock(tr("Stiffness"), QStringLiteral("stiffnessDock"), m_stiffness,
                               Qt::RightDockWidgetArea);
    m_simDock = makeDock(tr("Simulated hand"), QStringLiteral("simulatorDock"), m_simPanel,
                         Qt::RightDockWidgetArea);
    m_log = new QPlainTextEdit(this);
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(2000);
    m_logDock =
        makeDock(tr("Device log"), QStringLiteral("logDock"), m_log, Qt::BottomDockWidgetArea);
    m_logDock->hide();
    tabifyDockWidget(m_stiffnessDock, m_simDock);
    m_stiffnessDock->raise();
    // As wide as the editor wants (within reason): its rows are long.
    resizeDocks({m_editorDock}, {std::clamp(m_editor->sizeHint().width() + 24, 420, 600)},
                Qt::Horizontal);
    resizeDocks({m_editorDock, m_stiffnessDock}, {560, 300}, Qt::Vertical);

    for (QDockWidget *dock : {m_editorDock, m_stiffnessDock, m_simDock, m_logDock})
        m_viewMenu->addAction(dock->toggleViewAction());
}

void MainWindow::connectClient()
{
    connect(m_client, &DeviceClient::stateChanged, this, &MainWindow::onStateChanged);
    connect(m_client, &DeviceClient::deviceInfoChanged, this, &MainWindow::onDeviceInfo);
    connect(m_client, &DeviceClient::deviceParamsChanged, this, &MainWindow::onDeviceParams);
    connect(m_client, &DeviceClient::samplesReady, this, &MainWindow::onSamples);
    connect(m_client, &DeviceClient::commandFinished, this, &MainWindow::onCommandFinished);
    connect(m_client, &DeviceClient::statsUpdated, m_stats, &LinkStatsWidget::setStats);
    connect(m_client, &DeviceClient::recordingChanged, this, [this](const RecordingStatus &s) {
        m_recording->setStatus(s);
        if (!s.active && !s.error.isEmpty())
            statusBar()->showMessage(tr("Recording stopped: %1").arg(s.error), kStatusMs);
    });
    connect(m_client, &DeviceClient::deviceLog, this, [this](const QString &line) {
        m_log->appendPlainText(line);
        statusBar()->showMessage(tr("Device: %1").arg(line), kStatusMs);
    });
}

void MainWindow::connectEditor()
{
    connect(m_editor, &ParameterEditor::pushRequested, this, [this](const DeviceParams &params) {
        m_pushes.insert(m_client->pushParams(params), {m_client->deviceParams(), params});
    });
    connect(m_editor, &ParameterEditor::readRequested, this,
            [this] { m_commands.insert(m_client->readParams(), tr("Read")); });
    connect(m_editor, &ParameterEditor::hostParamsChanged, this, [this](const HostParams &host) {
        m_client->setHostParams(host);
        if (!isReplaying())
            m_plots->setHostParams(host);
    });
    connect(m_editor, &ParameterEditor::paramsEdited, this,
            [this] { m_stiffness->setEditedParams(m_editor->params()); });
    connect(m_editor, &ParameterEditor::angleInDegreesChanged, m_degreesAction,
            &QAction::setChecked);
    connect(m_profiles, &ProfileController::titleChanged, this, &QWidget::setWindowTitle);
    connect(m_profiles, &ProfileController::statusMessage, this,
            [this](const QString &message) { statusBar()->showMessage(message, kStatusMs); });
    connect(m_simPanel, &SimulatorPanel::handChanged, this, [this](const HandInput &hand) {
        m_handChosen = true;
        m_client->setSimulatedHand(hand);
    });
}

HandInput MainWindow::gentleHand()
{
    // 0.06 N·m is more than the notch holds with the default parameters (K_max·N = 0.04 N·m),
    // so the knob is pushed out of the notch and back every 5 s: dead zone, notch and slope
    // all show in the plots and on the stiffness curve.
    HandInput hand;
    hand.kind = HandInput::Kind::Sine;
    hand.amplitude = 0.06;
    hand.frequency = 0.2;
    return hand;
}

void MainWindow::setSimulatedHand(const HandInput &hand)
{
    m_handChosen = true;
    m_simPanel->setHand(hand);
    m_client->setSimulatedHand(hand);
}

void MainWindow::connectTo(const ConnectOptions &options)
{
    ConnectOptions opts = options;
    if (opts.port == kSimPort) {
        if (!m_handChosen && opts.sim.hand.kind == HandInput::Kind::Idle)
            opts.sim.hand = gentleHand();
        else if (m_handChosen)
            opts.sim.hand = m_simPanel->hand();
        m_simPanel->setHand(opts.sim.hand);
    }
    // The published firmware does not report its torque limit: the editor's tau_limit (the
    // profile's) scales the legacy feedback and stays what it is.
    if (m_editor->hostParams().tau_limit > 0)
        opts.legacy.tauLimit = m_editor->hostParams().tau_limit;
    m_port = opts.port;
    m_connection->setOptions(opts.port, opts.baud, opts.protocol);
    m_client->setHostParams(m_editor->hostParams());
    m_client->connectDevice(opts);
}

void MainWindow::disconnectDevice()
{
    m_client->disconnectDevice();
}

void MainWindow::onStateChanged(SessionState state, const QString &detail)
{
    m_connection->setState(state);
    m_linkStatus->setState(state);
    m_banner->setState(state, detail, m_port);
    const bool connected = state == SessionState::Connected;
    m_connectAction->setText(state == SessionState::Disconnected ? tr("&Connect")
                                                                 : tr("&Disconnect"));
    m_recording->setCanRecord(connected);
    const DeviceInfo info = m_client->deviceInfo();
    m_editor->setCanPush(connected && info.canSetParams(),
                         connected ? tr("the legacy protocol cannot carry parameters") : QString());
    if (state == SessionState::Disconnected) {
        m_editor->clearDeviceParams();
        m_stats->clear();
        m_linkStatus->setDeviceInfo(std::nullopt);
        m_simDock->hide();
        m_simDock->toggleViewAction()->setEnabled(false);
        if (!isReplaying()) {
            m_plots->setDeviceParams(std::nullopt);
            m_stiffness->setDeviceParams(std::nullopt);
            m_stiffness->clearOperatingPoint();
        }
    }
    // The banner already says why the link was lost or refused; the status bar, which clips a
    // long text against the link statistics, only repeats the other details.
    if (!detail.isEmpty() && m_banner->text().isEmpty())
        statusBar()->showMessage(detail, kStatusMs);
    updateActions();
}

void MainWindow::onDeviceInfo(const DeviceInfo &info)
{
    m_linkStatus->setDeviceInfo(info);
    if (info.protocol == WireProtocol::V2) // a legacy device reports no limit
        m_editor->setTauLimit(shortestFloatDecimal(info.tauLimit));
    m_simDock->toggleViewAction()->setEnabled(info.simulated);
    m_simDock->setVisible(info.simulated);
    updateActions();
}

void MainWindow::onDeviceParams(const DeviceParams &params)
{
    m_editor->setDeviceParams(params);
    if (!isReplaying()) {
        m_plots->setDeviceParams(params);
        m_stiffness->setDeviceParams(params);
    }
}

void MainWindow::onSamples(const SampleBatch &batch)
{
    if (batch.isEmpty())
        return;
    m_live.append(batch);
    if (!isReplaying()) {
        const Sample &last = batch.constLast();
        m_stiffness->setOperatingPoint(last.theta, last.tau_rec);
    }
}

void MainWindow::onCommandFinished(quint64 id, const CommandResult &result)
{
    if (m_pushes.contains(id)) {
        const PendingPush push = m_pushes.take(id);
        m_editor->pushFinished(result);
        if (result.ok()) {
            const QString change = describeParamChange(push.before, push.pushed);
            m_lastCommandMessage =
                change.isEmpty() ? tr("Pushed (no change).") : tr("Pushed: %1").arg(change);
            if (!change.isEmpty())
                addLiveEvent(change);
        } else {
            m_lastCommandMessage = tr("Push failed: %1").arg(result.message);
        }
        statusBar()->showMessage(m_lastCommandMessage, kStatusMs);
        return;
    }
    const QString what = m_commands.take(id);
    if (what.isEmpty())
        return;
    m_lastCommandMessage =
        result.ok() ? tr("%1: done.").arg(what) : tr("%1 failed: %2").arg(what, result.message);
    if (result.ok() && what == tr("ZERO"))
        addLiveEvent(tr("ZERO: θ0 := current angle"));
    statusBar()->showMessage(m_lastCommandMessage, kStatusMs);
}

void MainWindow::addLiveEvent(const QString &text)
{
    if (m_live.isEmpty())
        return;
    // Forget markers that scrolled out of the live buffer.
    const double oldest = m_live.firstTime();
    m_liveEvents.removeIf([oldest](const RecordingEvent &e) { return e.t_s < oldest; });
    m_liveEvents.append({m_live.lastTime(), text});
    if (!isReplaying())
        m_plots->setEvents(m_liveEvents);
}

bool MainWindow::openRecording(const QString &csvPath, QString *error)
{
    QString why;
    if (!m_replay->open(csvPath, &why)) {
        if (error)
            *error = why;
        return false;
    }
    if (!m_replay->warnings().isEmpty())
        statusBar()->showMessage(m_replay->warnings().join(u' '), kStatusMs);
    onReplayActive(true); // refresh also when already replaying another file
    // Open on a full first window rather than on a single sample.
    m_replay->setPosition(
        std::min(m_replay->startTime() + m_plots->windowLength(), m_replay->endTime()));
    return true;
}

void MainWindow::backToLive()
{
    m_replay->close();
}

bool MainWindow::isReplaying() const
{
    return m_replay->isActive();
}

void MainWindow::onReplayActive(bool active)
{
    m_stiffness->setReplaying(active);
    if (active) {
        const Recording &rec = m_replay->recording();
        m_plots->setPaused(false);
        m_plots->setSource(&m_replay->buffer());
        m_plots->setFollowLatest(false);
        m_plots->setEvents(rec.events);
        const std::optional<DeviceParams> params =
            rec.hasMetadata ? std::optional(rec.metadata.params) : std::nullopt;
        m_plots->setDeviceParams(params);
        m_plots->setHostParams(rec.hasMetadata ? rec.metadata.host : m_editor->hostParams());
        m_stiffness->setDeviceParams(params);
        onReplayPosition(m_replay->position());
    } else {
        m_plots->setDataEnd(std::nullopt);
        m_plots->setSource(&m_live);
        m_plots->setFollowLatest(true);
        m_plots->setEvents(m_liveEvents);
        const std::optional<DeviceParams> params =
            m_client->hasDeviceParams() ? std::optional(m_client->deviceParams()) : std::nullopt;
        m_plots->setDeviceParams(params);
        m_plots->setHostParams(m_editor->hostParams());
        m_stiffness->setDeviceParams(params);
        m_stiffness->clearOperatingPoint();
    }
    updateActions();
}

void MainWindow::onReplayPosition(double t)
{
    if (!isReplaying())
        return;
    // As live: data up to the playhead, sweeping in from the left until they fill the window.
    m_plots->setDataEnd(t);
    m_plots->setViewEnd(std::max(t, m_replay->startTime() + m_plots->windowLength()));
    if (const std::optional<Sample> s = m_replay->currentSample())
        m_stiffness->setOperatingPoint(s->theta, s->tau_rec);
}

void MainWindow::setLivePaused(bool paused)
{
    if (!isReplaying())
        m_plots->setPaused(paused);
}

bool MainWindow::isLivePaused() const
{
    return m_plots->isPaused();
}

void MainWindow::togglePause()
{
    if (isReplaying()) {
        m_replay->togglePlay();
        m_pauseAction->setChecked(!m_replay->isPlaying());
        return;
    }
    m_plots->setPaused(!m_plots->isPaused());
}

void MainWindow::setWindowSeconds(double seconds)
{
    m_plots->setWindowLength(seconds);
    m_plotActions->checkWindow(seconds);
    if (isReplaying())
        onReplayPosition(m_replay->position());
}

void MainWindow::setAngleInDegrees(bool degrees)
{
    m_degreesAction->setChecked(degrees);
    m_plots->setAngleInDegrees(degrees);
    m_stiffness->setAngleInDegrees(degrees);
    m_editor->setAngleInDegrees(degrees);
}

void MainWindow::updateActions()
{
    const SessionState state = m_client->state();
    const bool connected = state == SessionState::Connected;
    const bool v2 = connected && m_client->deviceInfo().canSetParams();
    m_resetRefAction->setEnabled(connected);
    m_zeroAction->setEnabled(v2);
    m_saveDeviceAction->setEnabled(v2);
    m_backToLiveAction->setEnabled(isReplaying());
    m_pauseAction->setText(isReplaying() ? tr("&Play / Pause Replay") : tr("&Pause"));
    if (isReplaying())
        m_pauseAction->setChecked(!m_replay->isPlaying());
    else
        m_pauseAction->setChecked(m_plots->isPaused());
}

QList<QAction *> MainWindow::shortcutActions() const
{
    return {m_connectAction,
            m_editor->pushAction(),
            m_pauseAction,
            m_recording->recordAction(),
            m_editor->undoAction(),
            m_editor->redoAction(),
            m_profiles->abToggleAction(),
            m_profiles->openAction(),
            m_profiles->saveAction(),
            m_profiles->saveAsAction(),
            m_openRecordingAction,
            m_backToLiveAction,
            m_plotActions->autoscaleAction(),
            m_degreesAction,
            m_resetRefAction,
            m_plotActions->exportImageAction(),
            m_plotActions->exportCsvAction(),
            m_shortcutsAction,
            m_quitAction};
}

void MainWindow::showShortcuts()
{
    ShortcutsDialog dialog(shortcutActions(), this);
    dialog.exec();
}

void MainWindow::showAbout()
{
    QMessageBox::about(
        this, tr("About HATPIC Tuner"),
        tr("<b>HATPIC Tuner %1</b><p>Tuning and live plots for the HATPIC single-axis haptic "
           "joystick (Mellet, Ruggiero, Lippiello).</p>")
            .arg(QApplication::applicationVersion()));
}

void MainWindow::openRecordingInteractive()
{
    // The folder of the last recording made or opened (what a researcher opens next).
    QString dir = m_recording->directory();
    if (dir.isEmpty() || !QDir(dir).exists())
        dir = documentsDir();
    if (!QDir(dir).exists())
        dir = QDir::homePath();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open recording"), dir, tr("CSV recordings (*.csv)"));
    if (path.isEmpty())
        return;
    m_recording->setDirectory(QFileInfo(path).absolutePath());
    QSettings().setValue(QStringLiteral("recording/dir"), m_recording->directory());
    QString error;
    if (!openRecording(path, &error))
        QMessageBox::warning(this, tr("Open recording"),
                             tr("Cannot replay %1:\n%2").arg(path, error));
}

void MainWindow::readSettings()
{
    QSettings settings;
    m_connection->setOptions(
        settings.value(QStringLiteral("connection/port"), kSimPort).toString(),
        settings.value(QStringLiteral("connection/baud"), 0).toInt(),
        static_cast<ProtocolChoice>(
            settings.value(QStringLiteral("connection/protocol"), int(ProtocolChoice::Auto))
                .toInt()));
    // The window's own rectangle, fitted into the screen both when saved and when restored;
    // "window/geometry" is what versions before it saved (opaque, and never fitted).
    const QRect saved = settings.value(QStringLiteral("window/rect")).toRect();
    if (saved.isValid()) {
        setGeometry(fittedInto(saved, availableGeometryFor(saved)));
        if (settings.value(QStringLiteral("window/maximized"), false).toBool())
            setWindowState(windowState() | Qt::WindowMaximized);
    } else if (restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray())) {
        if (!isMaximized() && !isFullScreen())
            setGeometry(fittedInto(geometry(), availableGeometryFor(geometry())));
    } else {
        resize(1400, 900); // the first launch; what is saved on close is fitted
    }
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    setAngleInDegrees(settings.value(QStringLiteral("view/degrees"), false).toBool());
    setWindowSeconds(
        settings.value(QStringLiteral("view/window"), kDefaultWindowSeconds).toDouble());
    m_plotActions->autoscaleAction()->setChecked(
        settings.value(QStringLiteral("view/autoscale"), true).toBool());
    m_recording->setDirectory(settings.value(QStringLiteral("recording/dir")).toString());
    const QString profile = settings.value(QStringLiteral("profiles/last")).toString();
    if (!profile.isEmpty() && QFileInfo::exists(profile)) {
        QString error;
        if (!m_profiles->openFile(profile, &error))
            statusBar()->showMessage(error, kStatusMs);
    }
}

void MainWindow::writeSettings() const
{
    QSettings settings;
    settings.setValue(QStringLiteral("connection/port"), m_connection->port());
    settings.setValue(QStringLiteral("connection/baud"), m_connection->baud());
    settings.setValue(QStringLiteral("connection/protocol"), int(m_connection->protocol()));
    const QRect normal = isMaximized() || isFullScreen() ? normalGeometry() : geometry();
    settings.setValue(QStringLiteral("window/rect"),
                      fittedInto(normal, availableGeometryFor(normal)));
    settings.setValue(QStringLiteral("window/maximized"), isMaximized());
    settings.remove(QStringLiteral("window/geometry"));
    settings.setValue(QStringLiteral("window/state"), saveState());
    settings.setValue(QStringLiteral("view/degrees"), m_plots->angleInDegrees());
    settings.setValue(QStringLiteral("view/window"), m_plots->windowLength());
    settings.setValue(QStringLiteral("view/autoscale"), m_plots->autoscale());
    if (!m_recording->directory().isEmpty())
        settings.setValue(QStringLiteral("recording/dir"), m_recording->directory());
    settings.setValue(QStringLiteral("profiles/last"), m_profiles->filePath());
}

QRect MainWindow::fittedInto(const QRect &rect, const QRect &available)
{
    if (!available.isValid())
        return rect;
    QRect fitted(rect.topLeft(), rect.size().boundedTo(available.size()));
    fitted.moveLeft(std::clamp(fitted.left(), available.left(),
                               available.left() + available.width() - fitted.width()));
    fitted.moveTop(std::clamp(fitted.top(), available.top(),
                              available.top() + available.height() - fitted.height()));
    return fitted;
}

QRect MainWindow::availableGeometryFor(const QRect &rect) const
{
    const QScreen *on = rect.isValid() ? QGuiApplication::screenAt(rect.center()) : nullptr;
    if (!on)
        on = screen();
    if (!on)
        on = QGuiApplication::primaryScreen();
    return on ? on->availableGeometry() : QRect();
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (!m_profiles->maybeSave()) {
        event->ignore();
        return;
    }
    writeSettings();
    event->accept();
}

} // namespace hatpic
