#include "window/mainwindow.h"

#include "connection/bridgepanel.h"
#include "connection/connectionbar.h"
#include "connection/linkbanner.h"
#include "connection/linkstatswidget.h"
#include "connection/linkstatuswidget.h"
#include "editor/chatterdetector.h"
#include "editor/deviceparameterlink.h"
#include "editor/parametereditor.h"
#include "plots/knobsview.h"
#include "plots/plotactions.h"
#include "plots/plotfeed.h"
#include "plots/plotpanel.h"
#include "plots/replaycontroller.h"
#include "profiles/profilecontroller.h"
#include "recording/recordingcontrols.h"
#include "recording/recordingplandialog.h"
#include "recording/replaybar.h"
#include "session/sessionwording.h"
#include "sim/simulatedjoystick.h"
#include "simulator/simulatorpanel.h"
#include "stiffness/stiffnessview.h"
#include "tuning/tuningmodel.h"
#include "window/focusreveal.h"
#include "window/statusline.h"
#include "window/theme.h"
#include "window/wheelguard.h"
#include "window/windowactions.h"
#include "window/windowgeometry.h"
#include "window/windowmenus.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>

// The window icon lives in this static library: its resources must be registered by hand.
static void initPlotsResources()
{
    Q_INIT_RESOURCE(window);
}

namespace hatpic {

MainWindow::MainWindow(QWidget *parent) : QMainWindow(parent)
{
    setObjectName(QStringLiteral("mainWindow"));
    WheelGuard::install();  // the wheel edits only the field that has the focus
    FocusReveal::install(); // a field given the focus is scrolled into view
    initPlotsResources();
    setWindowIcon(QIcon(QStringLiteral(":/icons/hatpic-tuner.png")));
    createParts();
    createActions();
    m_menus = new WindowMenus(this, {.actions = m_actions,
                                     .editor = m_editor,
                                     .profiles = m_profiles,
                                     .plotActions = m_plotActions,
                                     .recording = m_recording,
                                     .theme = m_theme,
                                     .connection = m_connection,
                                     .linkStatus = m_linkStatus});
    m_docks = addWindowDocks(this, {.client = m_client,
                                    .plots = m_plots,
                                    .plotActions = m_plotActions,
                                    .profiles = m_profiles,
                                    .tuning = m_tuning,
                                    .editor = m_editor,
                                    .stiffness = m_stiffness,
                                    .simPanel = m_simPanel,
                                    .simulator = m_simulator.get(),
                                    .view = m_menus->viewMenu()});
    addKnobsDock();
    connectParts();
    setWindowTitle(m_profiles->windowTitle());
    m_firstState = saveState(); // before the saved layout: what Reset layout returns to
    readSettings();
    onStateChanged(SessionState::Disconnected, {});
}

MainWindow::~MainWindow()
{
    delete m_docks.bridge; // first: its bridge stops through the client, an earlier child
}

void MainWindow::createParts()
{
    // Every part has an object name: the tests (and the screenshot program) find them by it.
    auto named = [](auto *part, const char *name) {
        part->setObjectName(QString::fromLatin1(name));
        return part;
    };
    m_client = named(new DeviceClient(this), "deviceClient");
    m_plots = named(new PlotPanel(this), "plotPanel");
    m_feed = named(new PlotFeed(m_plots, this), "plotFeed");
    m_banner = new LinkBanner(this);
    m_replayBar = new ReplayBar(m_feed->replay(), this);
    auto *central = new QWidget(this);
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(4, 4, 4, 0);
    layout->setSpacing(4);
    layout->addWidget(m_banner);
    layout->addWidget(m_replayBar);
    layout->addWidget(m_plots, 1);
    setCentralWidget(central);

    m_connection = named(new ConnectionBar(this), "connectionBar");
    m_linkStatus = named(new LinkStatusWidget(this), "linkStatus");
    m_recording = named(new RecordingControls(this), "recordingControls");
    m_theme = named(new ThemeController(this), "themeController");
    m_statusLine = new StatusLine(statusBar());
    m_stats = new LinkStatsWidget(this);

    // The window's one tuning and its one undo history, handed to all who read or change them.
    m_tuning = named(new TuningModel(this), "tuningModel");
    m_undo = named(new QUndoStack(this), "undoStack");
    m_editor = named(new ParameterEditor(m_tuning, m_undo, this), "parameterEditor");
    m_paramLink =
        named(new DeviceParameterLink(m_client, m_tuning, m_editor, this), "parameterLink");
    m_stiffness = named(new StiffnessView(*m_tuning, this), "stiffnessView");
    m_profiles = named(new ProfileController(m_tuning, m_undo, this, this), "profileController");
    m_simPanel = named(new SimulatorPanel(this), "simulatorPanel");
    m_simulator = std::make_shared<SimulatedJoystick>();
    m_connection->addSource(tr("Simulated HATPIC"), QString::fromUtf16(kSimPortName), m_simulator);
    for (QWidget *readout :
         {static_cast<QWidget *>(m_simPanel->statusLabel()), static_cast<QWidget *>(m_stats)})
        m_statusLine->readouts()->layout()->addWidget(readout);
    m_feed->setLiveHostParams(m_tuning->edited().host);
    m_plotActions = new PlotActions(m_plots, this);
}

void MainWindow::createActions()
{
    m_actions = new WindowActions(this);
    connect(m_actions->connectDevice, &QAction::triggered, m_connection,
            &ConnectionBar::toggleConnection);
    connect(m_actions->pause, &QAction::triggered, m_feed, &PlotFeed::togglePause);
    connect(m_actions->degrees, &QAction::toggled, this, &MainWindow::setAngleInDegrees);
    connect(m_actions->resetReference, &QAction::triggered, this, [this] {
        m_client->resetReference();
        m_feed->addLiveEvent(tr("p_ref reset to 0"));
    });
    connect(m_actions->zero, &QAction::triggered, m_paramLink, &DeviceParameterLink::zero);
    connect(m_actions->saveInDevice, &QAction::triggered, m_paramLink,
            &DeviceParameterLink::saveInDevice);
    connect(m_actions->openRecording, &QAction::triggered, this,
            &MainWindow::openRecordingInteractive);
    connect(m_actions->backToLive, &QAction::triggered, m_feed, &PlotFeed::backToLive);
    connect(m_actions->quit, &QAction::triggered, this, &QWidget::close);
    connect(m_actions->resetLayout, &QAction::triggered, this, &MainWindow::resetLayout);

    QAction *undo = m_editor->undoAction();
    undo->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Z));
    QAction *redo = m_editor->redoAction();
    redo->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
}

void MainWindow::connectParts()
{
    connect(m_connection, &ConnectionBar::connectRequested, this, &MainWindow::connectTo);
    connect(m_connection, &ConnectionBar::disconnectRequested, this, &MainWindow::disconnectDevice);
    connect(m_client, &DeviceClient::stateChanged, this, &MainWindow::onStateChanged);
    connect(m_client, &DeviceClient::deviceInfoChanged, this, &MainWindow::onDeviceInfo);
    connect(m_client, &DeviceClient::statsUpdated, m_stats, &LinkStatsWidget::setStats);
    connect(m_client, &DeviceClient::deviceLog, this, [this](const QString &line) {
        m_docks.logView->appendPlainText(line);
        showStatus(tr("Device: %1").arg(line));
    });
    connect(m_client, &DeviceClient::notice, this, [this](const SessionNotice &notice) {
        const QString text = SessionWording::notice(notice);
        m_docks.logView->appendPlainText(text);
        showStatus(text);
        // How a recording ended stays beside the record button, not only for a few seconds.
        if (notice.kind == SessionNotice::Kind::RecordingClosedOtherDevice ||
            notice.kind == SessionNotice::Kind::RecordingClosedByLoss)
            m_recording->setNote(text);
    });

    // What the plots and the stiffness view show: the feed, live or replay.
    connect(m_client, &DeviceClient::samplesReady, m_feed, &PlotFeed::appendLive);
    connect(m_client, &DeviceClient::samplesReady, m_knobs, &KnobsView::showSamples);
    connect(m_client, &DeviceClient::samplesReady, new ChatterWatch(m_editor),
            &ChatterWatch::addSamples); // warns in the derived figures
    connect(m_client, &DeviceClient::deviceTuningChanged, m_feed, &PlotFeed::setLiveDeviceTuning);
    connect(m_tuning, &TuningModel::editedChanged, m_feed, [this](TuningChange change) {
        if (change.host)
            m_feed->setLiveHostParams(m_editor->hostParams());
    });
    connect(m_paramLink, &DeviceParameterLink::deviceChanged, m_feed, &PlotFeed::addLiveEvent);
    connect(m_feed, &PlotFeed::replayingChanged, m_stiffness, &StiffnessView::setReplaying);
    connect(m_feed, &PlotFeed::deviceTuningShown, m_stiffness, &StiffnessView::setDeviceTuning);
    connect(m_feed, &PlotFeed::operatingPoint, m_stiffness, &StiffnessView::setOperatingPoint);
    connect(m_feed, &PlotFeed::operatingPointCleared, m_stiffness,
            &StiffnessView::clearOperatingPoint);
    connect(m_feed, &PlotFeed::replayingChanged, this, &MainWindow::updateActions);
    connect(m_feed, &PlotFeed::pausedChanged, this, &MainWindow::updateActions);
    connect(m_replayBar, &ReplayBar::backToLiveRequested, this, &MainWindow::backToLive);
    connect(m_plotActions, &PlotActions::windowChosen, this, &MainWindow::setWindowSeconds);
    connect(m_plotActions, &PlotActions::statusMessage, this, &MainWindow::showStatus);

    connect(m_recording, &RecordingControls::startRequested, m_client,
            [this](const QString &path) { m_client->startRecording(path, m_recording->plan()); });
    connect(m_replayBar, &ReplayBar::overlayRequested, this, &MainWindow::overlayInteractive);
    connect(m_recording, &RecordingControls::stopRequested, m_client, &DeviceClient::stopRecording);
    connect(m_client, &DeviceClient::recordingChanged, this, [this](const RecordingStatus &s) {
        m_recording->setStatus(s);
        if (!s.active && !s.error.isEmpty())
            showStatus(tr("Recording stopped: %1").arg(s.error));
    });

    connect(m_paramLink, &DeviceParameterLink::commandFinished, this, &MainWindow::showStatus);
    connect(m_editor, &ParameterEditor::angleInDegreesChanged, m_actions->degrees,
            &QAction::setChecked);
    connect(m_profiles, &ProfileController::titleChanged, this, &QWidget::setWindowTitle);
    connect(m_profiles, &ProfileController::statusMessage, this, &MainWindow::showStatus);
    connect(m_simPanel, &SimulatorPanel::handChanged, m_simulator.get(),
            &SimulatedJoystick::setHand);

    // The robot loop's state at a glance, whichever panel is in front (issue 27).
    if (auto *bridge = qobject_cast<BridgePanel *>(m_docks.bridge->widget())) {
        auto *loop = new QLabel(this);
        loop->setObjectName(QStringLiteral("statusLoop"));
        loop->hide();
        m_statusLine->readouts()->layout()->addWidget(loop);
        connect(bridge, &BridgePanel::loopStateChanged, loop,
                [loop](const QString &text, BridgePanel::LoopState state) {
                    loop->setVisible(state != BridgePanel::LoopState::Off);
                    loop->setText(state == BridgePanel::LoopState::Generating
                                      ? tr("Loop generating energy: see the Bridge panel")
                                      : text);
                    loop->setStyleSheet(state == BridgePanel::LoopState::Generating
                                            ? QStringLiteral("color: white; background: #b00020; "
                                                             "padding: 0 4px;")
                                            : QString());
                });
    }
}

void MainWindow::showStatus(const QString &message)
{
    m_statusLine->show(message);
}

void MainWindow::setSimulatedHand(const HandInput &hand)
{
    m_simPanel->chooseHand(hand);
    m_simulator->setHand(hand);
}

bool MainWindow::startBridge(int rosVersion)
{
    m_docks.bridge->show();
    m_docks.bridge->raise();
    auto *panel = qobject_cast<BridgePanel *>(m_docks.bridge->widget());
    return panel && panel->startOn(rosVersion);
}

void MainWindow::connectTo(const ConnectOptions &options)
{
    ConnectOptions opts = options;
    opts.detectForMs = std::max(opts.detectForMs, ConnectOptions::kDetectBootMs);
    if (!opts.link)
        opts.link = m_connection->sourceNamed(opts.port); // a listed source, given by its name
    if (const auto given = std::dynamic_pointer_cast<SimulatedJoystick>(opts.link)) {
        // The window's simulator, configured as a command line's (its faults and seed) asked.
        if (given != m_simulator)
            m_simulator->setConfig(given->config());
        m_simulator->answerIn(opts.protocol);
        m_simulator->setHand(m_simPanel->handToStartWith(m_simulator->hand()));
        opts.link = m_simulator;
    }
    m_paramLink->prepare(opts);
    m_port = opts.port;
    m_portSimulated = opts.link && opts.link->simulated();
    m_connection->setOptions(opts.port, opts.baud, opts.protocol);
    m_client->connectDevice(opts);
}

void MainWindow::disconnectDevice()
{
    m_client->disconnectDevice();
}

void MainWindow::onStateChanged(SessionState state, const StateDetail &event)
{
    const QString detail = SessionWording::stateDetail(event);
    m_connection->setState(state);
    m_linkStatus->setState(state);
    // Before the first connection, the port chosen in the bar (the banner says how to start).
    const ConnectOptions chosen = m_connection->options();
    if (m_port.isEmpty())
        m_banner->setState(state, event, chosen.port, chosen.link && chosen.link->simulated());
    else
        m_banner->setState(state, event, m_port, m_portSimulated);
    m_recording->setCanRecord(state == SessionState::Connected);
    if (state == SessionState::Disconnected) {
        m_stats->clear();
        m_linkStatus->setDeviceInfo(std::nullopt);
        m_docks.simulator->hide();
        m_docks.simulator->toggleViewAction()->setEnabled(false);
        m_knobs->clear();
        m_knobsDock->hide();
        m_knobsDock->toggleViewAction()->setEnabled(false);
        m_simPanel->statusLabel()->hide();
        m_feed->setLiveDeviceTuning({});
    }
    // The banner already says why the link was lost or refused; the status bar, which clips a
    // long text against the link statistics, only repeats the other details.
    if (!detail.isEmpty() && m_banner->text().isEmpty())
        showStatus(detail);
    updateActions();
}

void MainWindow::addKnobsDock()
{
    m_knobs = new KnobsView(this);
    m_knobsDock = new QDockWidget(tr("Knobs"), this);
    m_knobsDock->setObjectName(QStringLiteral("knobsDock"));
    m_knobsDock->setWidget(m_knobs);
    addDockWidget(Qt::BottomDockWidgetArea, m_knobsDock);
    m_knobsDock->hide();
    m_knobsDock->toggleViewAction()->setEnabled(false);
    m_menus->viewMenu()->addAction(m_knobsDock->toggleViewAction());
}

void MainWindow::onDeviceInfo(const DeviceInfo &info)
{
    m_linkStatus->setDeviceInfo(info);
    const bool board = info.axes > 1 || info.tilt;
    m_knobsDock->toggleViewAction()->setEnabled(board);
    if (board != m_knobsDock->isVisible())
        m_knobsDock->setVisible(board);
    m_docks.simulator->toggleViewAction()->setEnabled(info.simulated);
    m_docks.simulator->setVisible(info.simulated);
    m_simPanel->statusLabel()->setVisible(info.simulated);
    updateActions();
}

bool MainWindow::openRecording(const QString &csvPath, QString *error)
{
    if (!m_feed->openRecording(csvPath, error))
        return false;
    if (!m_feed->replay()->warnings().isEmpty())
        showStatus(m_feed->replay()->warnings().join(u' '));
    return true;
}

void MainWindow::backToLive()
{
    m_feed->backToLive();
}

bool MainWindow::openProfile(const QString &path, QString *error)
{
    return m_profiles->openFile(path, error);
}

void MainWindow::setWindowSeconds(double seconds)
{
    m_feed->setWindowLength(seconds);
    m_plotActions->checkWindow(seconds);
}

void MainWindow::setRepaintRate(double hz)
{
    m_plots->setRepaintRate(hz);
}

void MainWindow::setAngleInDegrees(bool degrees)
{
    m_actions->degrees->setChecked(degrees);
    m_plots->setAngleInDegrees(degrees);
    m_knobs->setUnits(m_plots->units()); // angles only: the reference mode does not reach it
    m_stiffness->setAngleInDegrees(degrees);
    m_editor->setAngleInDegrees(degrees);
}

void MainWindow::updateActions()
{
    m_actions->update(m_client->state(), m_client->deviceInfo().canSetParams(),
                      m_feed->isReplaying(), m_feed->isPaused());
}

QList<QAction *> MainWindow::shortcutActions() const
{
    return m_menus->shortcutActions() + m_docks.panelShortcuts;
}

void MainWindow::openRecordingInteractive()
{
    const QString path = m_recording->chooseRecordingToOpen();
    if (path.isEmpty())
        return;
    QSettings().setValue(QStringLiteral("recording/dir"), m_recording->directory());
    QString error;
    if (!openRecording(path, &error))
        QMessageBox::warning(this, tr("Open recording"),
                             tr("Cannot replay %1:\n%2").arg(path, error));
}

void MainWindow::overlayInteractive()
{
    const QString path = m_recording->chooseRecordingToOpen();
    QString error;
    if (!path.isEmpty() && !m_feed->replay()->openOverlay(path, &error))
        QMessageBox::warning(this, tr("Overlay recording"),
                             tr("Cannot overlay %1:\n%2").arg(path, error));
}

void MainWindow::readSettings()
{
    QSettings settings;
    m_connection->setOptions(
        settings.value(QStringLiteral("connection/port")).toString(), // none: the first source
        settings.value(QStringLiteral("connection/baud"), 0).toInt(),
        static_cast<ProtocolChoice>(
            settings.value(QStringLiteral("connection/protocol"), int(ProtocolChoice::Auto))
                .toInt()));
    if (!restoreWindowGeometry(this, settings)) {
        resizeToDefault(this); // the first launch; what is saved on close is fitted
        m_firstSize = size();  // shown at it, its frame is fitted too
    }
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    setAngleInDegrees(settings.value(QStringLiteral("view/degrees"), false).toBool());
    setWindowSeconds(
        settings.value(QStringLiteral("view/window"), kDefaultWindowSeconds).toDouble());
    m_plotActions->autoscaleAction()->setChecked(
        settings.value(QStringLiteral("view/autoscale"), true).toBool());
    m_recording->setDirectory(settings.value(QStringLiteral("recording/dir")).toString());
    m_recording->setPlan(RecordingPlanDialog::loadPlan(settings));
    m_theme->setChoice(
        ThemeController::fromKey(settings.value(QStringLiteral("view/theme")).toString()));
    const QString profile = settings.value(QStringLiteral("profiles/last")).toString();
    if (!profile.isEmpty() && QFileInfo::exists(profile)) {
        QString error;
        if (!m_profiles->openFile(profile, &error))
            showStatus(error);
    }
}

void MainWindow::writeSettings() const
{
    QSettings settings;
    settings.setValue(QStringLiteral("connection/port"), m_connection->port());
    settings.setValue(QStringLiteral("connection/baud"), m_connection->baud());
    settings.setValue(QStringLiteral("connection/protocol"), int(m_connection->protocol()));
    saveWindowGeometry(this, settings);
    settings.setValue(QStringLiteral("window/state"), saveState());
    settings.setValue(QStringLiteral("view/degrees"), m_plots->angleInDegrees());
    settings.setValue(QStringLiteral("view/window"), m_plots->windowLength());
    settings.setValue(QStringLiteral("view/autoscale"), m_plots->autoscale());
    if (!m_recording->directory().isEmpty())
        settings.setValue(QStringLiteral("recording/dir"), m_recording->directory());
    settings.setValue(QStringLiteral("profiles/last"), m_profiles->filePath());
    RecordingPlanDialog::savePlan(settings, m_recording->plan());
    settings.setValue(QStringLiteral("view/theme"), ThemeController::key(m_theme->choice()));
}

void MainWindow::recordOnConnect(const QString &csvPath)
{
    auto start = [this, csvPath] { m_client->startRecording(csvPath, RecordingPlan{}); };
    if (m_client->state() == SessionState::Connected) {
        start();
        return;
    }
    auto *once = new QObject(this);
    connect(m_client, &DeviceClient::stateChanged, once, [once, start](SessionState state) {
        if (state != SessionState::Connected)
            return;
        start();
        once->deleteLater();
    });
}

void MainWindow::resetLayout()
{
    restoreState(m_firstState);
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        dock->setFloating(false);
    // The simulated hand's panel follows the device, not the first launch.
    const bool simulated =
        m_client->state() != SessionState::Disconnected && m_client->deviceInfo().simulated;
    m_docks.simulator->setVisible(simulated);
    if (isMaximized() || isFullScreen())
        showNormal();
    resizeToDefault(this);
    resizeDocksToDefault(this, m_docks);
    showStatus(tr("Layout reset: the panels where and as large as at a first launch."));
}

void MainWindow::showEvent(QShowEvent *event)
{
    QMainWindow::showEvent(event);
    if (m_shown)
        return;
    m_shown = true;
    // Under a window manager the frame (title bar, borders) comes on top of the size asked
    // for: a window as large as the screen had its status bar below it (issue 27). Once the
    // frame is known, the whole frame is fitted into the screen.
    if (m_firstSize.isEmpty() || size() != m_firstSize)
        return; // a size restored or asked for: the program's or the user's
    QTimer::singleShot(0, this, [this] { fitFrameIntoScreen(this); });
    QTimer::singleShot(500, this, [this] { fitFrameIntoScreen(this); });
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
