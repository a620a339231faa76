#include "window/mainwindow.h"

#include "connection/bridgepanel.h"
#include "connection/connectionbar.h"
#include "connection/linkbanner.h"
#include "connection/linkstatswidget.h"
#include "connection/linkstatuswidget.h"
#include "editor/chatterdetector.h"
#include "editor/deviceparameterlink.h"
#include "editor/parametereditor.h"
#include "plots/plotactions.h"
#include "plots/plotfeed.h"
#include "plots/plotpanel.h"
#include "plots/replaycontroller.h"
#include "profiles/profilecontroller.h"
#include "recording/recordingcontrols.h"
#include "recording/recordingplandialog.h"
#include "recording/replaybar.h"
#include "session/sessionwording.h"
#include "simulator/simulatorpanel.h"
#include "stiffness/stiffnessview.h"
#include "window/abdock.h"
#include "window/bottomdocks.h"
#include "window/bridgedock.h"
#include "window/experimentsdock.h"
#include "window/measuredocks.h"
#include "window/shortcutsdialog.h"
#include "window/statusline.h"
#include "window/theme.h"
#include "window/wheelguard.h"
#include "window/windowactions.h"
#include "window/windowgeometry.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

// The window icon lives in this static library: its resources must be registered by hand.
static void initPlotsResources()
{
    Q_INIT_RESOURCE(window);
}

namespace hatpic {

namespace {

const QString kSimPort = QString::fromUtf16(kSimPortName);

} // namespace

MainWindow::MainWindow(QWidget *parent) : QMainWindow(parent)
{
    setObjectName(QStringLiteral("mainWindow"));
    WheelGuard::install(); // the wheel edits only the field that has the focus
    initPlotsResources();
    setWindowIcon(QIcon(QStringLiteral(":/icons/hatpic-tuner.png")));
    createParts();
    createActions();
    createMenus();
    createToolBars();
    createDocks();
    connectParts();
    setWindowTitle(m_profiles->windowTitle());
    readSettings();
    onStateChanged(SessionState::Disconnected, {});
}

MainWindow::~MainWindow()
{
    delete m_bridgeDock; // first: its bridge stops through the client, an earlier child
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

    m_editor = named(new ParameterEditor(this), "parameterEditor");
    m_paramLink = named(new DeviceParameterLink(m_client, m_editor, this), "parameterLink");
    m_stiffness = named(new StiffnessView(this), "stiffnessView");
    m_profiles = named(new ProfileController(m_editor, this, this), "profileController");
    m_simPanel = named(new SimulatorPanel(this), "simulatorPanel");
    for (QWidget *readout :
         {static_cast<QWidget *>(m_simPanel->statusLabel()), static_cast<QWidget *>(m_stats)})
        m_statusLine->readouts()->layout()->addWidget(readout);
    m_stiffness->setEditedParams(m_editor->params());
    m_stiffness->setEditedEffects(m_editor->effects());
    m_feed->setLiveHostParams(m_editor->hostParams());
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
    connect(m_actions->shortcuts, &QAction::triggered, this, &MainWindow::showShortcuts);
    connect(m_actions->about, &QAction::triggered, this, &MainWindow::showAbout);

    QAction *undo = m_editor->undoAction();
    undo->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Z));
    QAction *redo = m_editor->redoAction();
    redo->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
}

// The menus and toolbars: which action sits where. The actions themselves belong to the parts
// (editor, profiles, plots, recording) and to WindowActions.

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_profiles->openAction());
    file->addMenu(m_profiles->recentMenu());
    file->addMenu(m_profiles->presetsMenu());
    file->addAction(m_profiles->saveAction());
    file->addAction(m_profiles->saveAsAction());
    file->addSeparator();
    file->addAction(m_actions->openRecording);
    file->addAction(m_plotActions->exportImageAction());
    file->addAction(m_plotActions->exportCsvAction());
    file->addSeparator();
    file->addAction(m_actions->quit);

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(m_editor->undoAction());
    edit->addAction(m_editor->redoAction());
    edit->addSeparator();
    edit->addAction(m_profiles->abToggleAction());
    edit->addAction(m_profiles->pushOnSwitchAction());

    QMenu *device = menuBar()->addMenu(tr("&Device"));
    device->addAction(m_actions->connectDevice);
    device->addSeparator();
    device->addAction(m_editor->pushAction());
    device->addAction(m_editor->readAction());
    device->addAction(m_editor->revertAction());
    device->addSeparator();
    device->addAction(m_actions->resetReference);
    device->addAction(m_actions->zero);
    device->addAction(m_actions->saveInDevice);
    device->addSeparator();
    device->addAction(m_recording->recordAction());
    device->addAction(m_recording->planAction());

    QMenu *view = menuBar()->addMenu(tr("&View"));
    m_viewMenu = view;
    view->addAction(m_actions->pause);
    view->addAction(m_actions->backToLive);
    QMenu *window = view->addMenu(tr("&Window Length"));
    window->addActions(m_plotActions->windowActions());
    view->addAction(m_plotActions->autoscaleAction());
    view->addAction(m_actions->degrees);
    view->addAction(m_plotActions->measureAction());
    m_plotActions->addSeriesActions(view->addMenu(tr("&Series")));
    view->addMenu(m_theme->menu());
    view->addSeparator(); // the docks' toggles follow (createDocks)

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(m_actions->shortcuts);
    help->addAction(m_actions->about);
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
    plots->addAction(m_actions->pause);
    plots->addSeparator();
    plots->addActions(m_plotActions->windowActions());
    plots->addSeparator();
    plots->addAction(m_plotActions->autoscaleAction());
    plots->addAction(m_actions->degrees);
    plots->addAction(m_plotActions->measureAction());
    plots->addAction(m_actions->resetReference);
    plots->addSeparator();
    plots->addWidget(m_recording);
    plots->addAction(m_actions->openRecording);
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
    // Under the plots, so that the hand and the stiffness view are in sight together.
    m_simDock = makeDock(tr("Simulated hand"), QStringLiteral("simulatorDock"), m_simPanel,
                         Qt::BottomDockWidgetArea);
    m_log = new QPlainTextEdit(this);
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(2000);
    m_logDock =
        makeDock(tr("Device log"), QStringLiteral("logDock"), m_log, Qt::BottomDockWidgetArea);
    m_logDock->hide();
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea); // the hand's dock: plots only
    // The robot bridge is opened from View → Bridge, beside the device log: never in front of
    // the hand, which must stay in sight with the stiffness view.
    m_bridgeDock = addBridgeDock(this, m_client, m_profiles, m_editor, m_logDock);
    m_bridgeDock->hide();
    // Tuning experiments (docs/experiments.md): View → Experiments, beside the device log.
    QDockWidget *experiments = addExperimentsDock(this, m_client, m_plots, m_simPanel, m_logDock);
    // As wide as the editor wants (within reason): its rows are long.
    resizeDocks({m_editorDock}, {std::clamp(m_editor->sizeHint().width() + 24, 420, 600)},
                Qt::Horizontal);
    // The stiffness view's two plots stay readable at 720 px (issue 21: once 40 px each).
    resizeDocks({m_editorDock, m_stiffnessDock}, {500, 360}, Qt::Vertical);

    for (QDockWidget *dock : {m_editorDock, m_stiffnessDock, m_simDock, m_bridgeDock, m_logDock})
        m_viewMenu->addAction(dock->toggleViewAction());
    m_viewMenu->addAction(experiments->toggleViewAction());
    // A/B comparison and the profile's notes, opened from the View menu, beside the log.
    for (QDockWidget *dock : addAbDocks(this, m_profiles, m_editor, m_stiffness, m_logDock))
        m_viewMenu->addAction(dock->toggleViewAction());
    addMeasureDocks(this, m_plots, m_plotActions, m_profiles, m_editor, m_stiffness, m_viewMenu,
                    m_logDock);
    // The panels under the plots open usable, beside the hand or tabbed with it.
    auto *bottom = new BottomDocks(this, m_simDock);
    for (QDockWidget *dock : findChildren<QDockWidget *>()) {
        if (dock != m_simDock && dockWidgetArea(dock) == Qt::BottomDockWidgetArea)
            bottom->add(dock);
    }
}

void MainWindow::connectParts()
{
    connect(m_connection, &ConnectionBar::connectRequested, this, &MainWindow::connectTo);
    connect(m_connection, &ConnectionBar::disconnectRequested, this, &MainWindow::disconnectDevice);
    connect(m_client, &DeviceClient::stateChanged, this, &MainWindow::onStateChanged);
    connect(m_client, &DeviceClient::deviceInfoChanged, this, &MainWindow::onDeviceInfo);
    connect(m_client, &DeviceClient::statsUpdated, m_stats, &LinkStatsWidget::setStats);
    connect(m_client, &DeviceClient::deviceLog, this, [this](const QString &line) {
        m_log->appendPlainText(line);
        showStatus(tr("Device: %1").arg(line));
    });
    connect(m_client, &DeviceClient::notice, this, [this](const SessionNotice &notice) {
        const QString text = SessionWording::notice(notice);
        m_log->appendPlainText(text);
        showStatus(text);
        // How a recording ended stays beside the record button, not only for a few seconds.
        if (notice.kind == SessionNotice::Kind::RecordingClosedOtherDevice ||
            notice.kind == SessionNotice::Kind::RecordingClosedByLoss)
            m_recording->setNote(text);
    });

    // What the plots and the stiffness view show: the feed, live or replay.
    connect(m_client, &DeviceClient::samplesReady, m_feed, &PlotFeed::appendLive);
    connect(m_client, &DeviceClient::samplesReady, new ChatterWatch(m_editor),
            &ChatterWatch::addSamples); // warns in the derived figures
    connect(m_client, &DeviceClient::deviceTuningChanged, m_feed, &PlotFeed::setLiveDeviceTuning);
    connect(m_editor, &ParameterEditor::hostParamsChanged, m_feed, &PlotFeed::setLiveHostParams);
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
    connect(m_editor, &ParameterEditor::paramsEdited, this, [this] {
        m_stiffness->setEditedEffects(m_editor->effects());
        m_stiffness->setEditedParams(m_editor->params());
    });
    connect(m_editor, &ParameterEditor::angleInDegreesChanged, m_actions->degrees,
            &QAction::setChecked);
    connect(m_profiles, &ProfileController::titleChanged, this, &QWidget::setWindowTitle);
    connect(m_profiles, &ProfileController::statusMessage, this, &MainWindow::showStatus);
    connect(m_simPanel, &SimulatorPanel::handChanged, m_client, &DeviceClient::setSimulatedHand);
}

void MainWindow::showStatus(const QString &message)
{
    m_statusLine->show(message);
}

void MainWindow::setSimulatedHand(const HandInput &hand)
{
    m_simPanel->chooseHand(hand);
    m_client->setSimulatedHand(hand);
}

bool MainWindow::startBridge(int rosVersion)
{
    m_bridgeDock->show();
    m_bridgeDock->raise();
    auto *panel = qobject_cast<BridgePanel *>(m_bridgeDock->widget());
    return panel && panel->startOn(rosVersion);
}

void MainWindow::connectTo(const ConnectOptions &options)
{
    ConnectOptions opts = options;
    if (opts.port == kSimPort)
        opts.sim.hand = m_simPanel->handToStartWith(opts.sim.hand);
    m_paramLink->prepare(opts);
    m_port = opts.port;
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
    m_banner->setState(state, event, m_port);
    m_recording->setCanRecord(state == SessionState::Connected);
    if (state == SessionState::Disconnected) {
        m_stats->clear();
        m_linkStatus->setDeviceInfo(std::nullopt);
        m_simDock->hide();
        m_simDock->toggleViewAction()->setEnabled(false);
        m_simPanel->statusLabel()->hide();
        m_feed->setLiveDeviceTuning({});
    }
    // The banner already says why the link was lost or refused; the status bar, which clips a
    // long text against the link statistics, only repeats the other details.
    if (!detail.isEmpty() && m_banner->text().isEmpty())
        showStatus(detail);
    updateActions();
}

void MainWindow::onDeviceInfo(const DeviceInfo &info)
{
    m_linkStatus->setDeviceInfo(info);
    m_simDock->toggleViewAction()->setEnabled(info.simulated);
    m_simDock->setVisible(info.simulated);
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
    return QList<QAction *>{m_actions->connectDevice,
                            m_editor->pushAction(),
                            m_actions->pause,
                            m_recording->recordAction(),
                            m_editor->undoAction(),
                            m_editor->redoAction(),
                            m_profiles->abToggleAction(),
                            m_profiles->openAction(),
                            m_profiles->saveAction(),
                            m_profiles->saveAsAction(),
                            m_actions->openRecording,
                            m_actions->backToLive,
                            m_plotActions->autoscaleAction(),
                            m_actions->degrees,
                            m_actions->resetReference,
                            m_plotActions->exportImageAction(),
                            m_plotActions->exportCsvAction(),
                            m_plotActions->measureAction(),
                            m_actions->shortcuts,
                            m_actions->quit} +
           m_editor->keyboardActions() + m_plotActions->windowActions();
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
        settings.value(QStringLiteral("connection/port"), kSimPort).toString(),
        settings.value(QStringLiteral("connection/baud"), 0).toInt(),
        static_cast<ProtocolChoice>(
            settings.value(QStringLiteral("connection/protocol"), int(ProtocolChoice::Auto))
                .toInt()));
    if (!restoreWindowGeometry(this, settings))
        resizeToDefault(this); // the first launch; what is saved on close is fitted
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
