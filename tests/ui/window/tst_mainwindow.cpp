// The real MainWindow against the in-process simulator ("sim") and, where built, the hatpic-sim
// program on a pseudo-terminal: connect, plots fill, edit → push → in sync, invalid values,
// device rejection, undo/redo, profiles, A/B, recording, replay, link loss, settings, keys.
#include "connection/connectionbar.h"
#include "connection/linkbanner.h"
#include "connection/linkstatswidget.h"
#include "connection/linkstatuswidget.h"
#include "editor/deviceparameterlink.h"
#include "editor/parametereditor.h"
#include "plots/plotfeed.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"
#include "plots/replaycontroller.h"
#include "profiles/profilecontroller.h"
#include "recording/recordingcontrols.h"
#include "recording/replaybar.h"
#include "simulator/simulatorpanel.h"
#include "simulatoroptions.h"
#include "stiffness/stiffnessview.h"
#include "telemetry/recordingreader.h"
#include "telemetry/recordingwriter.h"
#include "wheelevent.h"
#include "window/mainwindow.h"
#include "window/shortcutsdialog.h"
#include "window/wheelguard.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QToolBar>
#include <QUndoStack>

#include <cmath>
#include <memory>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

constexpr int kConnectMs = 15000; //!< generous: the machine is shared
constexpr int kDataMs = 15000;

ConnectOptions simOptions(ProtocolChoice protocol = ProtocolChoice::V2)
{
    ConnectOptions options;
    options.port = QStringLiteral("sim");
    options.protocol = protocol;
    return options;
}

//! Samples in the live buffer with a time after t.
qsizetype samplesAfter(const SampleBuffer &buffer, double t)
{
    return buffer.size() - buffer.upperBound(t);
}

//! max θ − min θ over the buffer [rad].
double thetaSpan(const SampleBuffer &buffer)
{
    double lo = 1e9;
    double hi = -1e9;
    for (qsizetype i = 0; i < buffer.size(); ++i) {
        lo = std::min(lo, buffer.value(Channel::Theta, i));
        hi = std::max(hi, buffer.value(Channel::Theta, i));
    }
    return hi - lo;
}

//! A part of the window by its object name: the window has no getters for its parts.
template<typename T> T *part(const QObject *window, const char *name)
{
    auto *found = window->findChild<T *>(QString::fromLatin1(name));
    if (!found)
        qFatal("the window has no %s named %s", T::staticMetaObject.className(), name);
    return found;
}

//! Where the live view ends: the newest sample, or first + window while the data are shorter.
//! Repaints first, so that nothing arrives between the repaint and the comparison.
double liveViewEnd(const MainWindow &window)
{
    auto *plots = part<PlotPanel>(&window, "plotPanel");
    plots->repaintNow();
    const SampleBuffer &b = part<PlotFeed>(&window, "plotFeed")->liveBuffer();
    return std::max(b.lastTime(), b.firstTime() + plots->windowLength());
}

} // namespace

class TestMainWindow : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();

    void connectsToSimulatorAndPlotsSamples_data();
    void connectsToSimulatorAndPlotsSamples();
    void editPushInSyncChangesBehaviour();
    void invalidValueDisablesPush();
    void wheelScrollsParametersAndEditsNothing();
    void deviceRejectionIsShown();
    void undoRedo();
    void profileSaveLoadRoundTrip();
    void abSwitchKeepsBothTunings();
    void legacyDeviceCannotPush();
    void simulatedHandReachesDevice();
    void pauseKeepsLinkRecording();
    void recordCreatesValidFile();
    void replayShowsRecordingAndReturnsToLive();
    void disconnectKeepsPlotData();
    void lostLinkKeepsDataAndReconnects();
    void degreesToggleReachesEveryView();
    void settingsPersist();
    void keyboardShortcuts();
    void narrowWindowKeepsStateTagVisible();
    void narrowReplayBarKeepsItsSlider();
    void hugeReplaySpanKeepsTheWindow_data();
    void hugeReplaySpanKeepsTheWindow();
    void oversizedSettingsAreFitted_data();
    void oversizedSettingsAreFitted();
    void handAndStiffnessInSightTogether();
    void keyboardReachesFieldsAndActions();
    void goToScrollsTheFieldIntoView();
    void keyboardFocusAndPanelKeys();
    void resetLayoutRestoresTheDocks();
    void derivedFiguresInSightAtEverySize_data();
    void derivedFiguresInSightAtEverySize();

private:
    void connectSim(ProtocolChoice protocol = ProtocolChoice::V2);
    //! A part of the window by its object name.
    template<typename T> T *find(const char *name) const { return part<T>(m_window.get(), name); }
    DeviceClient *client() const { return find<DeviceClient>("deviceClient"); }
    //! The device's parameters as read (DeviceParams{} until the device has told them).
    DeviceParams deviceParams() const
    {
        return client()->deviceTuning().params.value_or(DeviceParams{});
    }
    LinkStatusWidget *linkStatus() const { return find<LinkStatusWidget>("linkStatus"); }
    const SampleBuffer &liveBuffer() const { return find<PlotFeed>("plotFeed")->liveBuffer(); }
    bool waitForSamples(qsizetype count);

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
};

void TestMainWindow::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("hatpic-test"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_mainwindow"));
    QVERIFY(m_dir.isValid());
}

void TestMainWindow::init()
{
    QSettings().clear();
    m_window = std::make_unique<MainWindow>();
    // The size a first launch gets on a large screen (the offscreen screen is 800×600).
    m_window->resize(1400, 900);
    find<ProfileController>("profileController")->setQuestion([](const QString &) {
        return QMessageBox::Discard;
    });
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void TestMainWindow::cleanup()
{
    m_window.reset();
}

void TestMainWindow::connectSim(ProtocolChoice protocol)
{
    m_window->connectTo(simOptions(protocol));
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Connected, kConnectMs);
    QTRY_VERIFY_WITH_TIMEOUT(client()->deviceTuning().params.has_value() ||
                                 !client()->deviceInfo().canSetParams(),
                             kConnectMs);
}

bool TestMainWindow::waitForSamples(qsizetype count)
{
    const double since = liveBuffer().lastTime();
    return QTest::qWaitFor([&] { return samplesAfter(liveBuffer(), since) >= count; }, kDataMs);
}

void TestMainWindow::connectsToSimulatorAndPlotsSamples_data()
{
    QTest::addColumn<ProtocolChoice>("protocol");
    QTest::newRow("auto detection") << ProtocolChoice::Auto;
    QTest::newRow("forced v2") << ProtocolChoice::V2;
}

void TestMainWindow::connectsToSimulatorAndPlotsSamples()
{
    QFETCH(ProtocolChoice, protocol);
    QCOMPARE(linkStatus()->stateText(), QStringLiteral("disconnected"));
    connectSim(protocol);
    QCOMPARE(linkStatus()->stateText(), QStringLiteral("connected"));
    QVERIFY2(linkStatus()->identityText().contains(QStringLiteral("Simulated HATPIC")),
             qPrintable(linkStatus()->identityText()));
    QVERIFY(linkStatus()->identityText().contains(QStringLiteral("protocol v2")));
    QCOMPARE(find<ConnectionBar>("connectionBar")->connectButton()->text(),
             QStringLiteral("Disconnect"));
    QVERIFY(find<QDockWidget>("simulatorDock")->isVisible());
    QCOMPARE(find<SimulatorPanel>("simulatorPanel")->hand(), SimulatorPanel::gentleHand());

    QVERIFY(waitForSamples(1500));
    PlotPanel *plots = find<PlotPanel>("plotPanel");
    QTRY_VERIFY(plots->pointCount(Channel::Theta) > 100);
    QVERIFY(plots->pointCount(Channel::TauRec) > 100);
    QVERIFY(plots->pointCount(Channel::PRef) > 100);
    QCOMPARE(plots->viewEnd(), liveViewEnd(*m_window));
    QTRY_VERIFY(find<LinkStatsWidget>("linkStats")->text().contains(QStringLiteral("frames/s")));
    QVERIFY(!find<LinkStatsWidget>("linkStats")->text().startsWith(QStringLiteral("0 frames/s")));

    // The gentle hand moves the knob from the first second.
    QTRY_VERIFY_WITH_TIMEOUT(thetaSpan(liveBuffer()) > 0.05, kDataMs);
}

void TestMainWindow::editPushInSyncChangesBehaviour()
{
    connectSim();
    ParameterEditor *editor = find<ParameterEditor>("parameterEditor");
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::InSync, kConnectMs);
    const DeviceParams before = deviceParams();

    DeviceParams edited = editor->params();
    edited.K_max = 0.6;
    editor->setParams(edited, editor->hostParams(), QStringLiteral("K_max"));
    QCOMPARE(editor->syncState(), SyncState::Edited);
    QVERIFY(editor->pushAction()->isEnabled());
    editor->pushAction()->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::InSync, kConnectMs);
    QCOMPARE(float(deviceParams().K_max), 0.6f);
    QVERIFY2(find<DeviceParameterLink>("parameterLink")
                 ->lastMessage()
                 .contains(QStringLiteral("K_max 0.4 → 0.6")),
             qPrintable(find<DeviceParameterLink>("parameterLink")->lastMessage()));
    QCOMPARE(find<PlotPanel>("plotPanel")->events().size(), 1);
    QVERIFY(
        find<PlotPanel>("plotPanel")->events().constFirst().text.contains(QStringLiteral("K_max")));
    QVERIFY(before.K_max != deviceParams().K_max);

    // The stiffness view draws the device curve with the new K_max.
    QCPGraph *device = find<StiffnessView>("stiffnessView")->deviceStiffnessGraph();
    QTRY_VERIFY(!device->data()->isEmpty());
    double peak = 0;
    for (auto it = device->data()->constBegin(); it != device->data()->constEnd(); ++it)
        peak = std::max(peak, it->value);
    QCOMPARE(float(peak), 0.6f);

    // The device renders it: in the notch band τ_rec = −K_max·(θ−θ0).
    const double pushedAt = liveBuffer().lastTime();
    QVERIFY(QTest::qWaitFor(
        [&] {
            const SampleBuffer &b = liveBuffer();
            for (qsizetype i = b.upperBound(pushedAt + 0.1); i < b.size(); ++i) {
                if (b.flags(i) & 0x02) // in the notch band
                    return true;
            }
            return false;
        },
        30000));
    const SampleBuffer &b = liveBuffer();
    int checked = 0;
    for (qsizetype i = b.upperBound(pushedAt + 0.1); i < b.size(); ++i) {
        if (!(b.flags(i) & 0x02))
            continue;
        const double e = b.value(Channel::Theta, i) - edited.theta0;
        QVERIFY2(std::abs(b.value(Channel::TauRec, i) + 0.6 * e) < 1e-4,
                 qPrintable(QStringLiteral("θ %1, τ_rec %2")
                                .arg(b.value(Channel::Theta, i))
                                .arg(b.value(Channel::TauRec, i))));
        ++checked;
    }
    QVERIFY(checked > 0);
}

void TestMainWindow::invalidValueDisablesPush()
{
    connectSim();
    ParameterEditor *editor = find<ParameterEditor>("parameterEditor");
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::InSync, kConnectMs);
    QSignalSpy validity(editor, &ParameterEditor::validityChanged);
    DeviceParams bad = editor->params();
    bad.K_min = 0.9; // above K_max
    editor->setParams(bad, editor->hostParams(), QStringLiteral("K_min"));
    QVERIFY(!editor->isValid());
    QCOMPARE(validity.size(), 1);
    QVERIFY(!editor->pushAction()->isEnabled());
    QVERIFY(!editor->problems().isEmpty());
    // Ctrl+Return does nothing while invalid: the device keeps its values.
    editor->pushAction()->trigger();
    QTest::qWait(200); // nothing must arrive; there is no event to wait for
    QCOMPARE(float(deviceParams().K_min), float(DeviceParams().K_min));
    editor->undoStack()->undo();
    QVERIFY(editor->isValid());
    QVERIFY(editor->pushAction()->isEnabled() || editor->syncState() == SyncState::InSync);
}

void TestMainWindow::wheelScrollsParametersAndEditsNothing()
{
    // Issue 21, item 15: at 1280×720, with live push on, the pointer resting on K_min and the
    // Parameters panel scrolled past its fields: nothing is edited, nothing reaches the device.
    m_window->resize(1280, 720);
    connectSim();
    ParameterEditor *editor = find<ParameterEditor>("parameterEditor");
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::InSync, kConnectMs);
    editor->setLivePush(true);
    QSignalSpy pushes(editor, &ParameterEditor::pushRequested);
    const Tuning before = editor->tuning();
    const int undoSteps = editor->undoStack()->count();

    QAbstractSpinBox *kMin = editor->findChild<QAbstractSpinBox *>(QStringLiteral("spin_K_min"));
    QVERIFY(kMin && kMin->isVisible());
    for (int i = 0; i < 3; ++i)
        test::turnWheel(kMin, kMin->rect().center(), -120);
    QCOMPARE(editor->params().K_min, before.device.K_min);
    QVERIFY(!kMin->hasFocus());

    auto *scroll = editor->findChild<QScrollArea *>();
    QVERIFY(scroll);
    QScrollBar *bar = scroll->verticalScrollBar();
    QVERIFY2(bar->maximum() > 0, "the panel does not scroll at 1280×720");
    const QPoint pointer(scroll->viewport()->width() / 2, scroll->viewport()->height() / 2);
    int fieldsPassed = 0;
    for (int i = 0; i < 40 && bar->value() < bar->maximum(); ++i) {
        QWidget *under = scroll->viewport()->childAt(pointer);
        fieldsPassed += WheelGuard::isValueField(under) ||
                        (under && WheelGuard::isValueField(under->parentWidget()));
        test::turnWheel(scroll->viewport(), pointer, -120);
    }
    QCOMPARE(bar->value(), bar->maximum());
    QVERIFY2(fieldsPassed > 3, qPrintable(QString::number(fieldsPassed)));
    QTest::qWait(2 * ParameterEditor::kDefaultLivePushIntervalMs); // a live push would be out
    QVERIFY(editor->tuning() == before);
    QCOMPARE(editor->undoStack()->count(), undoSteps);
    QCOMPARE(pushes.size(), 0);
    QCOMPARE(editor->syncState(), SyncState::InSync);

    // A field the user chose (clicked into) takes the wheel, and live push sends it.
    scroll->ensureWidgetVisible(kMin);
    QTest::mouseClick(kMin->findChild<QLineEdit *>(), Qt::LeftButton);
    QTRY_VERIFY(kMin->hasFocus());
    test::turnWheel(kMin, kMin->rect().center(), 120);
    QVERIFY(editor->params().K_min > before.device.K_min);
    QTRY_COMPARE_WITH_TIMEOUT(pushes.size(), 1, kConnectMs);
}

void TestMainWindow::deviceRejectionIsShown()
{
    // The host validates in double precision, the device in float32 (its wire type). Q_dz just
    // below N passes Q_dz < N on the host, but both round to the same float, so the device
    // answers OUT_OF_RANGE naming Q_dz: a real device rejection, reached through the editor.
    connectSim();
    ParameterEditor *editor = find<ParameterEditor>("parameterEditor");
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::InSync, kConnectMs);
    DeviceParams edge = editor->params();
    edge.N = 0.1;
    edge.Q_dz = std::nextafter(0.1, 0.0);
    QVERIFY(validate(edge).empty());
    QCOMPARE(float(edge.Q_dz), float(edge.N));
    editor->setParams(edge, editor->hostParams(), QStringLiteral("Q_dz"));
    QVERIFY(editor->pushAction()->isEnabled());
    editor->pushAction()->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::Rejected, kConnectMs);
    QVERIFY2(find<DeviceParameterLink>("parameterLink")
                 ->lastMessage()
                 .startsWith(QStringLiteral("Push failed")),
             qPrintable(find<DeviceParameterLink>("parameterLink")->lastMessage()));
    QVERIFY2(editor->syncText().contains(QStringLiteral("Q_dz")), qPrintable(editor->syncText()));
    // The device kept its previous, valid set.
    QCOMPARE(float(deviceParams().Q_dz), float(DeviceParams().Q_dz));
    QVERIFY(find<PlotPanel>("plotPanel")->events().isEmpty());
}

void TestMainWindow::undoRedo()
{
    ParameterEditor *editor = find<ParameterEditor>("parameterEditor");
    const DeviceParams original = editor->params();
    DeviceParams edited = original;
    edited.N = 0.15;
    editor->setParams(edited, editor->hostParams(), QStringLiteral("N"));
    QCOMPARE(editor->params().N, 0.15);
    QVERIFY(editor->undoAction()->isEnabled());
    QCOMPARE(editor->undoAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_Z));
    editor->undoAction()->trigger();
    QCOMPARE(editor->params(), original);
    QCOMPARE(editor->redoAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z));
    editor->redoAction()->trigger();
    QCOMPARE(editor->params().N, 0.15);
    // The stiffness view follows the edited set.
    QCPGraph *stiffness = find<StiffnessView>("stiffnessView")->stiffnessGraph();
    QVERIFY(!stiffness->data()->isEmpty());
}

void TestMainWindow::profileSaveLoadRoundTrip()
{
    ProfileController *profiles = find<ProfileController>("profileController");
    ParameterEditor *editor = find<ParameterEditor>("parameterEditor");
    DeviceParams tuned = editor->params();
    tuned.K_max = 0.55;
    tuned.theta0 = 0.125;
    HostParams host = editor->hostParams();
    host.v_max = 2.5;
    host.mode = ReferenceMode::Rotation;
    editor->setParams(tuned, host, QStringLiteral("tune"));
    const QString path = m_dir.filePath(QStringLiteral("Roundtrip.json"));
    QString error;
    QVERIFY2(profiles->saveTo(path, &error), qPrintable(error));
    QVERIFY(!profiles->isModified());

    editor->setParams(DeviceParams(), HostParams(), QStringLiteral("reset"));
    QVERIFY(editor->params() != tuned);
    QVERIFY2(profiles->openFile(path, &error), qPrintable(error));
    QCOMPARE(editor->params(), tuned);
    QCOMPARE(editor->hostParams(), host);
    QCOMPARE(profiles->filePath(), path);
    QVERIFY2(m_window->windowTitle().contains(profiles->profileName()),
             qPrintable(m_window->windowTitle()));

    // A refused file changes nothing.
    const QString broken = m_dir.filePath(QStringLiteral("broken.json"));
    QFile file(broken);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{ not json");
    file.close();
    QVERIFY(!profiles->openFile(broken, &error));
    QVERIFY(!error.isEmpty());
    QCOMPARE(editor->params(), tuned);
}

void TestMainWindow::abSwitchKeepsBothTunings()
{
    ProfileController *profiles = find<ProfileController>("profileController");
    ParameterEditor *editor = find<ParameterEditor>("parameterEditor");
    QAction *ab = profiles->abToggleAction();
    QVERIFY(!ab->shortcut().isEmpty());
    QCOMPARE(profiles->activeSlot(), 0);
    const DeviceParams a = editor->params();
    ab->trigger();
    QCOMPARE(profiles->activeSlot(), 1);
    DeviceParams b = editor->params();
    b.K_min = 0.05;
    editor->setParams(b, editor->hostParams(), QStringLiteral("B"));
    ab->trigger();
    QCOMPARE(profiles->activeSlot(), 0);
    QCOMPARE(editor->params(), a);
    QVERIFY(m_window->windowTitle().contains(QStringLiteral("A")));
    ab->trigger();
    QCOMPARE(editor->params(), b);
}

void TestMainWindow::legacyDeviceCannotPush()
{
    // The published firmware reports no torque limit: the profile's tau_limit stays (it is
    // neither replaced by a built-in guess nor marked as an unsaved change) and is the one the
    // legacy feedback uses.
    ParameterEditor *editor = find<ParameterEditor>("parameterEditor");
    HostParams host = editor->hostParams();
    host.tau_limit = 0.3;
    editor->setParams(editor->params(), host, QStringLiteral("tau_limit"));
    QCOMPARE(editor->hostParams().tau_limit, 0.3);
    // The command line's simulator (hatpic-tuner --port sim) is the published firmware's.
    SimulatedDevice::Config legacy;
    legacy.protocol = WireProtocol::Legacy;
    m_window->connectTo(test::simulatorOptions(legacy, ProtocolChoice::Auto));
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Connected, kConnectMs);
    QCOMPARE(client()->deviceInfo().protocol, WireProtocol::Legacy);
    QVERIFY(linkStatus()->identityText().contains(QStringLiteral("legacy")));
    QVERIFY2(linkStatus()->identityText().contains(QStringLiteral("τ limit 0.3 N·m (assumed)")),
             qPrintable(linkStatus()->identityText()));
    QCOMPARE(client()->deviceInfo().tauLimit, 0.3);
    QCOMPARE(editor->hostParams().tau_limit, 0.3);
    QVERIFY(!editor->canPush());
    QVERIFY(!editor->pushAction()->isEnabled());
    QVERIFY(waitForSamples(5)); // legacy streams at ~5 Hz
    QTRY_VERIFY(find<PlotPanel>("plotPanel")->pointCount(Channel::Theta) > 0);
}

void TestMainWindow::simulatedHandReachesDevice()
{
    connectSim();
    HandInput push;
    push.kind = HandInput::Kind::Constant;
    push.amplitude = 0.1; // beyond the notch: settles near 0.1 / K_min ≈ 0.67 rad
    m_window->setSimulatedHand(push);
    QCOMPARE(find<SimulatorPanel>("simulatorPanel")->hand(), push);
    QTRY_VERIFY_WITH_TIMEOUT(liveBuffer().value(Channel::Theta, liveBuffer().size() - 1) > 0.5,
                             kDataMs);
}

void TestMainWindow::pauseKeepsLinkRecording()
{
    connectSim();
    PlotPanel *plots = find<PlotPanel>("plotPanel");
    plots->setWindowLength(1);
    QVERIFY(waitForSamples(1200)); // more than the window: the view scrolls
    plots->repaintNow();
    find<QAction>("pauseAction")->trigger();
    QVERIFY(find<PlotPanel>("plotPanel")->isPaused());
    QVERIFY(find<QAction>("pauseAction")->isChecked());
    const double end = plots->viewEnd();
    const quint64 appended = liveBuffer().appendedCount();
    QVERIFY(waitForSamples(500));
    QVERIFY(liveBuffer().appendedCount() >= appended + 500);
    plots->repaintNow();
    QCOMPARE(plots->viewEnd(), end);
    find<QAction>("pauseAction")->trigger();
    QVERIFY(!find<PlotPanel>("plotPanel")->isPaused());
    QTRY_VERIFY(plots->viewEnd() > end);
}

void TestMainWindow::recordCreatesValidFile()
{
    connectSim();
    ParameterEditor *editor = find<ParameterEditor>("parameterEditor");
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::InSync, kConnectMs);
    const QString path = m_dir.filePath(QStringLiteral("session.csv"));
    RecordingControls *controls = find<RecordingControls>("recordingControls");
    QString suggested;
    controls->setPathChooser([&](const QString &s) {
        suggested = s;
        return path;
    });
    QAction *record = controls->recordAction();
    QCOMPARE(record->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_R));
    QVERIFY(record->isEnabled());
    record->trigger();
    QVERIFY(QFileInfo(suggested).fileName().startsWith(QStringLiteral("hatpic-")));
    QVERIFY(suggested.endsWith(QStringLiteral(".csv")));
    QTRY_VERIFY_WITH_TIMEOUT(controls->status().active, kConnectMs);
    QVERIFY(record->isChecked());
    QTRY_VERIFY_WITH_TIMEOUT(controls->status().samples > 300, kDataMs);
    QVERIFY(controls->statusText().contains(QStringLiteral("samples")));

    DeviceParams edited = editor->params();
    edited.K_max = 0.5;
    editor->setParams(edited, editor->hostParams(), QStringLiteral("K_max"));
    editor->pushAction()->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::InSync, kConnectMs);
    QVERIFY(waitForSamples(200));
    record->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!controls->status().active, kConnectMs);
    QVERIFY(!record->isChecked());

    const RecordingReadResult result = readRecording(path);
    QVERIFY2(result.recording.has_value(), qPrintable(result.error));
    QVERIFY(result.recording->samples.size() > 300);
    QVERIFY(result.recording->hasMetadata);
    QCOMPARE(result.recording->metadata.source, QStringLiteral("hatpic-tuner"));
    QVERIFY(result.recording->metadata.device.simulated);
    QVERIFY(!result.recording->events.isEmpty());
    QVERIFY2(result.recording->events.constFirst().text.contains(QStringLiteral("K_max")),
             qPrintable(result.recording->events.constFirst().text));
}

void TestMainWindow::replayShowsRecordingAndReturnsToLive()
{
    // A recording as the core writes it (the same file hatpicctl stream produces).
    const QString path = m_dir.filePath(QStringLiteral("replay.csv"));
    {
        RecordingWriter recorder;
        RecordingMetadata meta;
        meta.start = QDateTime::currentDateTimeUtc();
        meta.source = QStringLiteral("hatpicctl stream");
        meta.params.K_max = 0.45;
        QVERIFY2(recorder.open(path, meta), qPrintable(recorder.error()));
        SampleBatch batch;
        for (int i = 0; i < 5000; ++i) {
            Sample s;
            s.t_s = 100 + i * 0.001;
            s.theta = 0.2 * std::sin(i * 0.002);
            s.tau_rec = -0.4 * s.theta;
            batch.append(s);
            if (i == 2500) {
                QVERIFY(recorder.append(batch));
                batch.clear();
                recorder.addEvent(QStringLiteral("K_max 0.4 → 0.45"));
            }
        }
        QVERIFY(recorder.append(batch));
        recorder.close();
    }

    connectSim();
    QVERIFY(waitForSamples(100));
    QString error;
    QVERIFY2(m_window->openRecording(path, &error), qPrintable(error));
    QVERIFY(find<PlotFeed>("plotFeed")->isReplaying());
    ReplayBar *bar = find<ReplayBar>("replayBar");
    QVERIFY(bar->isVisible());
    PlotPanel *plots = find<PlotPanel>("plotPanel");
    ReplayController *replay = find<ReplayController>("replayController");
    QCOMPARE(plots->source(), &replay->buffer());
    QVERIFY(!plots->followsLatest());
    QCOMPARE(plots->events().size(), 1);
    QVERIFY(find<QAction>("pauseAction")->text().contains(QStringLiteral("Replay")));
    QCOMPARE(replay->startTime(), 100.0);

    // It opens on a full first window (here the whole 5 s recording).
    QCOMPARE(replay->position(), replay->endTime());
    QCOMPARE(plots->viewStart(), 100.0);
    // Scrub with the slider: data up to the playhead; the view ends there once it is full.
    bar->slider()->setValue(3000);
    QCOMPARE(replay->position(), 103.0);
    QCOMPARE(plots->dataEnd(), 103.0);
    QCOMPARE(plots->viewEnd(), 110.0); // 10 s window, not yet full
    m_window->setWindowSeconds(2);
    QCOMPARE(plots->viewEnd(), 103.0);
    QCOMPARE(plots->viewStart(), 101.0);
    plots->repaintNow();
    QVERIFY(plots->pointCount(Channel::Theta) > 0);
    const QCPGraphData last = *(plots->graph(Channel::Theta)->data()->constEnd() - 1);
    QVERIFY(last.key <= 103.001);
    QVERIFY(bar->positionText().startsWith(QStringLiteral("3.00")));
    // The slider counts from the recording's start, the plots' axis in session time: both
    // are shown, each labelled, and the session time is the axis's.
    QCOMPARE(find<QLabel>("replaySessionTime")->text(), QStringLiteral("t = 103.00 s"));
    QCOMPARE(find<QLabel>("replaySessionTime")->text(),
             ReplayBar::sessionTimeText(plots->dataEnd().value_or(0)));
    QVERIFY(find<QLabel>("replayTime")->toolTip().contains(QStringLiteral("recording")));
    QVERIFY(find<QLabel>("replaySessionTime")->toolTip().contains(QStringLiteral("axis")));

    // Play at 5×: the playhead moves; live samples keep arriving but are not shown.
    bar->speedBox()->setCurrentIndex(bar->speedBox()->findData(5.0));
    QCOMPARE(replay->speed(), 5.0);
    find<QAction>("pauseAction")->trigger(); // Space plays and pauses the replay
    QVERIFY(replay->isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(replay->position() > 103.5, 10000);
    find<QAction>("pauseAction")->trigger();
    QVERIFY(!replay->isPlaying());
    QVERIFY(find<QAction>("pauseAction")->isChecked());
    // The bar's ▶ plays too, and the Play / Pause action follows it.
    QTest::mouseClick(bar->playButton(), Qt::LeftButton);
    QVERIFY(replay->isPlaying());
    QVERIFY(!find<QAction>("pauseAction")->isChecked());
    QTest::mouseClick(bar->playButton(), Qt::LeftButton);
    QVERIFY(!replay->isPlaying());
    QVERIFY(find<QAction>("pauseAction")->isChecked());

    // One click back to live.
    QTest::mouseClick(bar->liveButton(), Qt::LeftButton);
    QVERIFY(!find<PlotFeed>("plotFeed")->isReplaying());
    QVERIFY(!bar->isVisible());
    QCOMPARE(plots->source(), &liveBuffer());
    QVERIFY(plots->followsLatest());
    QCOMPARE(plots->viewEnd(), liveViewEnd(*m_window));

    // A broken file is refused with a reason, and live stays live.
    const QString broken = m_dir.filePath(QStringLiteral("broken.csv"));
    QFile file(broken);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("a,b\n1,2\n");
    file.close();
    QVERIFY(!m_window->openRecording(broken, &error));
    QVERIFY(!error.isEmpty());
    QVERIFY(!find<PlotFeed>("plotFeed")->isReplaying());
}

void TestMainWindow::disconnectKeepsPlotData()
{
    connectSim();
    QVERIFY(waitForSamples(500));
    m_window->disconnectDevice();
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Disconnected, kConnectMs);
    const qsizetype kept = liveBuffer().size();
    QVERIFY(kept >= 500);
    find<PlotPanel>("plotPanel")->repaintNow();
    QVERIFY(find<PlotPanel>("plotPanel")->pointCount(Channel::Theta) > 0);
    QCOMPARE(liveBuffer().size(), kept);
    QCOMPARE(linkStatus()->stateText(), QStringLiteral("disconnected"));
    QVERIFY(!find<ParameterEditor>("parameterEditor")->canPush());
    QVERIFY(!find<QDockWidget>("simulatorDock")->isVisible());
    QVERIFY(!find<RecordingControls>("recordingControls")->recordAction()->isEnabled());
}

void TestMainWindow::lostLinkKeepsDataAndReconnects()
{
#ifndef HATPIC_SIM_EXECUTABLE
    QSKIP("hatpic-sim is not built");
#else
    // hatpic-sim on a pseudo-terminal, behind a symlink that outlives the process.
    const QString link = m_dir.filePath(QStringLiteral("hatpic-pty"));
    auto start = [&](QProcess &sim) {
        sim.start(QStringLiteral(HATPIC_SIM_EXECUTABLE), {QStringLiteral("--link"), link});
        QVERIFY(sim.waitForStarted(5000));
        QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine() || QFileInfo::exists(link), 10000);
    };
    QProcess sim;
    start(sim);
    ConnectOptions options;
    options.port = link;
    options.protocol = ProtocolChoice::V2;
    m_window->connectTo(options);
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Connected, kConnectMs);
    QVERIFY(!find<QDockWidget>("simulatorDock")->isVisible()); // not the in-process simulator
    QVERIFY(waitForSamples(500));
    // A recording runs through the loss (issue 21, item 5).
    const QString csv = m_dir.filePath(QStringLiteral("through-the-loss.csv"));
    RecordingControls *controls = find<RecordingControls>("recordingControls");
    controls->setPathChooser([&](const QString &) { return csv; });
    controls->recordAction()->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(controls->status().samples > 100, kDataMs);
    auto *recordingLabel = controls->findChild<QLabel *>(QStringLiteral("recordingStatus"));

    sim.terminate(); // the device vanishes
    QVERIFY(sim.waitForFinished(5000));
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Lost, kConnectMs);
    // The recording waits, and says so where the user looks for it.
    QTRY_VERIFY(controls->status().waiting);
    QVERIFY(controls->recordAction()->isChecked());
    QVERIFY2(recordingLabel->text().contains(QStringLiteral("· waiting for the device")),
             qPrintable(recordingLabel->text()));
    QCOMPARE(linkStatus()->stateText(), QStringLiteral("LINK LOST"));
    QVERIFY(find<LinkBanner>("linkBanner")->isVisible());
    QVERIFY2(find<LinkBanner>("linkBanner")->text().contains(QStringLiteral("Reconnecting")),
             qPrintable(find<LinkBanner>("linkBanner")->text()));
    // Said once, in the banner, not clipped again in the status bar.
    const QString message = m_window->statusBar()->currentMessage();
    QVERIFY2(message.isEmpty() || !find<LinkBanner>("linkBanner")->text().contains(message),
             qPrintable(message));
    const qsizetype kept = liveBuffer().size();
    QVERIFY(kept >= 500);
    find<PlotPanel>("plotPanel")->repaintNow();
    QVERIFY(find<PlotPanel>("plotPanel")->pointCount(Channel::Theta) > 0);

    // The port returns: the session reconnects by itself and the banner goes away.
    QProcess again;
    start(again);
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Connected, 30000);
    QVERIFY(!find<LinkBanner>("linkBanner")->isVisible());
    QVERIFY(waitForSamples(200));
    QVERIFY(liveBuffer().size() > kept); // old and new data, one time axis
    // The same recording goes on; the gap stays in sight after it is saved.
    QTRY_VERIFY(!controls->status().waiting);
    QVERIFY(controls->status().active);
    const quint64 beforeStop = controls->status().samples;
    QTRY_VERIFY_WITH_TIMEOUT(controls->status().samples > beforeStop + 100, kDataMs);
    controls->recordAction()->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!controls->status().active, kConnectMs);
    QCOMPARE(recordingLabel->text(),
             QStringLiteral("Saved through-the-loss.csv (%1) · 1 gap")
                 .arg(RecordingControls::formatBytes(controls->status().bytes)));
    const RecordingReadResult recorded = readRecording(csv);
    QVERIFY2(recorded.recording, qPrintable(recorded.error));
    QCOMPARE(recorded.recording->events.size(), 1);
    QVERIFY(recorded.recording->events.first().text.startsWith(QStringLiteral("gap: ")));
    m_window->disconnectDevice();
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Disconnected, kConnectMs);
    again.terminate();
    again.waitForFinished(5000);
#endif
}

void TestMainWindow::degreesToggleReachesEveryView()
{
    QAction *degrees = find<QAction>("degreesAction");
    QVERIFY(!degrees->isChecked());
    degrees->trigger();
    QVERIFY(find<PlotPanel>("plotPanel")->angleInDegrees());
    QVERIFY(find<StiffnessView>("stiffnessView")->angleInDegrees());
    QVERIFY(find<ParameterEditor>("parameterEditor")->angleInDegrees());
    // The editor's own check box drives the same switch.
    find<ParameterEditor>("parameterEditor")->setAngleInDegrees(false);
    QTRY_VERIFY(!degrees->isChecked());
}

void TestMainWindow::settingsPersist()
{
    find<ConnectionBar>("connectionBar")
        ->setOptions(QStringLiteral("/dev/ttyTEST0"), 115200, ProtocolChoice::Legacy);
    find<QAction>("degreesAction")->setChecked(true);
    find<PlotPanel>("plotPanel")->setWindowLength(30);
    const QString profile = m_dir.filePath(QStringLiteral("Persisted.json"));
    QVERIFY(find<ProfileController>("profileController")->saveTo(profile));
    QVERIFY(m_window->close());

    m_window = std::make_unique<MainWindow>();
    ConnectionBar *bar = find<ConnectionBar>("connectionBar");
    QCOMPARE(bar->port(), QStringLiteral("/dev/ttyTEST0"));
    QCOMPARE(bar->baud(), 115200);
    QCOMPARE(bar->protocol(), ProtocolChoice::Legacy);
    QVERIFY(find<PlotPanel>("plotPanel")->angleInDegrees());
    QCOMPARE(find<PlotPanel>("plotPanel")->windowLength(), 30.0);
    QCOMPARE(find<ProfileController>("profileController")->filePath(), profile);
}

void TestMainWindow::keyboardShortcuts()
{
    {
        // Every shortcut is in view at once: the table needs no scrolling.
        ShortcutsDialog dialog(m_window->shortcutActions(), m_window.get());
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto *table = dialog.findChild<QTableWidget *>();
        QVERIFY(table);
        QVERIFY(table->rowCount() >= 15);
        QVERIFY2(!table->verticalScrollBar()->isVisible(),
                 qPrintable(QStringLiteral("%1 rows in %2 px")
                                .arg(table->rowCount())
                                .arg(table->viewport()->height())));
    }
    const QStringList lines = ShortcutsDialog::describe(m_window->shortcutActions());
    auto has = [&](const QKeySequence &key) {
        const QString text = key.toString(QKeySequence::NativeText);
        return std::any_of(lines.cbegin(), lines.cend(),
                           [&](const QString &l) { return l.contains(text); });
    };
    QVERIFY(has(QKeySequence(Qt::CTRL | Qt::Key_K)));
    QVERIFY(has(QKeySequence(Qt::CTRL | Qt::Key_Return)));
    QVERIFY(has(QKeySequence(Qt::Key_Space)));
    QVERIFY(has(QKeySequence(Qt::CTRL | Qt::Key_R)));
    QVERIFY(has(QKeySequence(Qt::CTRL | Qt::Key_Z)));
    QVERIFY(has(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)));
    QVERIFY(has(find<ProfileController>("profileController")->abToggleAction()->shortcut()));

    // Ctrl+K connects through the real shortcut machinery.
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    find<PlotPanel>("plotPanel")->customPlot()->setFocus();
    QTest::keyClick(m_window.get(), Qt::Key_K, Qt::ControlModifier);
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Connected, kConnectMs);
    QTest::keyClick(find<PlotPanel>("plotPanel")->customPlot(), Qt::Key_Space);
    QVERIFY(find<PlotPanel>("plotPanel")->isPaused());
    QTest::keyClick(m_window.get(), Qt::Key_P, Qt::ControlModifier);
    QVERIFY(!find<PlotPanel>("plotPanel")->isPaused());
    QTest::keyClick(m_window.get(), Qt::Key_K, Qt::ControlModifier);
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Disconnected, kConnectMs);
}

void TestMainWindow::narrowWindowKeepsStateTagVisible()
{
    // On a laptop-sized window the long device identity must give way (elided), not push the
    // state tag — the one place LINK LOST shows — into the toolbar's overflow menu.
    m_window->resize(1000, 700);
    connectSim();
    auto *tag = m_window->findChild<QLabel *>(QStringLiteral("linkState"));
    QVERIFY(tag);
    QCOMPARE(tag->text(), QStringLiteral("connected"));
    QTRY_VERIFY(linkStatus()->identityText().contains(QStringLiteral("τ limit")));
    // Let the toolbars lay out the new identity (nested layouts: a few rounds).
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QVERIFY(tag->isVisible());
    const QRect inWindow(tag->mapTo(m_window.get(), QPoint(0, 0)), tag->size());
    QVERIFY2(m_window->rect().contains(inWindow),
             qPrintable(QStringLiteral("tag at x %1..%2, window %3 wide")
                            .arg(inWindow.left())
                            .arg(inWindow.right())
                            .arg(m_window->width())));
    auto *identity = m_window->findChild<QLabel *>(QStringLiteral("deviceIdentity"));
    QVERIFY(identity);
    QTRY_VERIFY(identity->isVisible());
    // The full identity stays available (tooltip, identityText()).
    QVERIFY(linkStatus()->identityText().contains(QStringLiteral("τ limit")));
    QCOMPARE(identity->toolTip(), linkStatus()->identityText());
}

void TestMainWindow::narrowReplayBarKeepsItsSlider()
{
    // A long file name and source must not squeeze the scrub slider to nothing, nor widen the
    // centre of a laptop-sized window at the editor's expense.
    const QString path = m_dir.filePath(
        QStringLiteral("a-rather-long-recording-name-from-the-morning-session-trial-07.csv"));
    {
        RecordingWriter recorder;
        RecordingMetadata meta;
        meta.start = QDateTime::currentDateTimeUtc();
        meta.source = QStringLiteral("hatpicctl stream --csv on the lab bench computer");
        QVERIFY2(recorder.open(path, meta), qPrintable(recorder.error()));
        SampleBatch batch;
        for (int i = 0; i < 3000; ++i) {
            Sample s;
            s.t_s = i * 0.001;
            batch.append(s);
        }
        QVERIFY(recorder.append(batch));
        recorder.close();
    }
    m_window->resize(1000, 700);
    QString error;
    QVERIFY2(m_window->openRecording(path, &error), qPrintable(error));
    ReplayBar *bar = find<ReplayBar>("replayBar");
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QVERIFY(bar->isVisible());
    QVERIFY2(bar->slider()->width() >= 120, qPrintable(QString::number(bar->slider()->width())));
    QVERIFY2(bar->minimumSizeHint().width() < 600,
             qPrintable(QString::number(bar->minimumSizeHint().width())));
    auto *title = bar->findChild<QLabel *>(QStringLiteral("replayTitle"));
    QVERIFY(title);
    QVERIFY(title->toolTip().contains(QStringLiteral("morning-session-trial-07.csv")));
    QVERIFY(title->toolTip().contains(QStringLiteral("lab bench")));
}

void TestMainWindow::hugeReplaySpanKeepsTheWindow_data()
{
    QTest::addColumn<QByteArray>("csv");
    QTest::addColumn<double>("middle"); // t at the slider's middle
    QTest::newRow("0 to 1e300 s") << QByteArray("t_s,theta\n0,0\n5e299,0.1\n1e300,0\n") << 5e299;
    QTest::newRow("35 days (ms overflow an int)")
        << QByteArray("t_s,theta\n0,0\n1500000,0.1\n3000000,0\n") << 1.5e6;
    QTest::newRow("beyond the largest double")
        << QByteArray("t_s,theta\n-1.7e308,0\n0,0.1\n1.7e308,0\n") << 0.0;
}

void TestMainWindow::hugeReplaySpanKeepsTheWindow()
{
    // Issue 10: a recording whose t_s spans 0…1e300 widened the window to 5474 px (a 300-digit
    // time label) and saved that size for every later launch; spans over ~24.8 days overflowed
    // the slider's int.
    QFETCH(QByteArray, csv);
    QFETCH(double, middle);
    const QString path = m_dir.filePath(QStringLiteral("span.csv"));
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(csv);
    }
    const QRect available = m_window->screen()->availableGeometry();
    m_window->resize(m_window->minimumSizeHint().expandedTo(QSize(1100, 700))); // room for the bar
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    const int width = m_window->width();
    const int minimumWidth = m_window->minimumSizeHint().width();

    QString error;
    QVERIFY2(m_window->openRecording(path, &error), qPrintable(error));
    ReplayBar *bar = find<ReplayBar>("replayBar");
    ReplayController *replay = find<ReplayController>("replayController");
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    find<PlotPanel>("plotPanel")->repaintNow();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);

    // Nothing widens the window: not the replay bar, not the plots' axis labels.
    QCOMPARE(m_window->width(), width);
    QVERIFY2(m_window->minimumSizeHint().width() <= width,
             qPrintable(QString::number(m_window->minimumSizeHint().width())));
    QVERIFY2(bar->minimumSizeHint().width() < 700,
             qPrintable(QString::number(bar->minimumSizeHint().width())));
    QVERIFY2(bar->positionText().size() <= 24, qPrintable(bar->positionText()));
    auto *plot = find<PlotPanel>("plotPanel")->findChild<QCustomPlot *>();
    QVERIFY(plot);
    for (QCPAxisRect *rect : plot->axisRects()) {
        for (QCPAxis *axis : rect->axes()) {
            for (const QString &label : axis->tickVectorLabels())
                QVERIFY2(label.size() <= 16, qPrintable(label));
        }
    }

    // The slider covers the whole span in an int, both ways.
    QSlider *slider = bar->slider();
    QVERIFY(slider->maximum() > 0 && slider->maximum() <= ReplayBar::kMaxSliderSteps);
    slider->setValue(slider->maximum());
    QCOMPARE(replay->position(), replay->endTime());
    slider->setValue(slider->maximum() / 2);
    QVERIFY2(std::abs(replay->position() - middle) <= 1e-6 * replay->endTime(),
             qPrintable(QString::number(replay->position())));
    replay->setPosition(replay->startTime());
    QCOMPARE(slider->value(), 0);
    replay->setPosition(replay->endTime());
    QCOMPARE(slider->value(), slider->maximum());

    // The next launch gets a window that fits the screen.
    QVERIFY(m_window->close());
    m_window = std::make_unique<MainWindow>();
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QVERIFY2(m_window->width() <= std::max(available.width(), minimumWidth),
             qPrintable(QString::number(m_window->width())));
}

void TestMainWindow::oversizedSettingsAreFitted_data()
{
    QTest::addColumn<bool>("legacyKey"); // window/geometry as saved by earlier versions
    QTest::newRow("window/rect") << false;
    QTest::newRow("window/geometry") << true;
}

void TestMainWindow::oversizedSettingsAreFitted()
{
    QFETCH(bool, legacyKey);
    m_window.reset();
    const QRect available = QGuiApplication::primaryScreen()->availableGeometry();
    const QRect huge(available.topLeft() + QPoint(-3000, 50), QSize(6000, 4000));
    {
        QSettings settings;
        settings.clear();
        if (legacyKey) {
            QWidget big;
            big.setGeometry(huge);
            settings.setValue(QStringLiteral("window/geometry"), big.saveGeometry());
        } else {
            settings.setValue(QStringLiteral("window/rect"), huge);
        }
    }
    m_window = std::make_unique<MainWindow>();
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    const QSize least = m_window->minimumSize();
    QVERIFY2(m_window->width() <= std::max(available.width(), least.width()),
             qPrintable(QString::number(m_window->width())));
    QVERIFY2(m_window->height() <= std::max(available.height(), least.height()),
             qPrintable(QString::number(m_window->height())));
    // And what it saves fits too, whatever size it had.
    m_window->resize(6000, 4000);
    QVERIFY(m_window->close());
    const QRect saved = QSettings().value(QStringLiteral("window/rect")).toRect();
    QVERIFY2(available.contains(saved), qPrintable(QStringLiteral("%1 %2 %3×%4")
                                                       .arg(saved.x())
                                                       .arg(saved.y())
                                                       .arg(saved.width())
                                                       .arg(saved.height())));
}

// Issue 27: Alt+1…9 put the cursor in a field without scrolling it into view; the user typed
// blind. Every Alt+N brings its field in sight, even when it had the focus already.
void TestMainWindow::goToScrollsTheFieldIntoView()
{
    m_window->resize(1280, 560); // the Parameters panel scrolls
    connectSim();
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    auto *scroll = find<QScrollArea>("parameterScroll");
    QScrollBar *bar = scroll->verticalScrollBar();
    QVERIFY2(bar->maximum() > 0, "the Parameters panel does not scroll");
    const auto inView = [scroll](const char *name) {
        auto *w = scroll->findChild<QWidget *>(QString::fromLatin1(name));
        return scroll->viewport()->rect().contains(
            QRect(w->mapTo(scroll->viewport(), QPoint()), w->size()));
    };
    bar->setValue(0);
    QVERIFY(!inView("spin_tau_limit"));
    QTest::keyClick(m_window.get(), Qt::Key_9, Qt::AltModifier);
    QCOMPARE(QApplication::focusWidget(), find<QWidget>("spin_tau_limit"));
    QVERIFY(inView("spin_tau_limit"));
    // Scrolled away with the focus kept: Alt+9 brings it back.
    bar->setValue(0);
    QVERIFY(!inView("spin_tau_limit"));
    QTest::keyClick(m_window.get(), Qt::Key_9, Qt::AltModifier);
    QVERIFY(inView("spin_tau_limit"));
    QTest::keyClick(m_window.get(), Qt::Key_1, Qt::AltModifier);
    QVERIFY(inView("spin_D_adm"));
}

// Issue 27: toolbar buttons were Tab stops; Push handed the focus on to the simulated hand's
// selector; the panels under the plots had no keys; F1 named "Disconnect" for Ctrl+K.
void TestMainWindow::keyboardFocusAndPanelKeys()
{
    m_window->resize(1280, 720);
    // Opened disconnected, the window says how to start (issue 27).
    QCOMPARE(find<LinkBanner>("linkBanner")->text(),
             u"Not connected. Press Connect (Ctrl+K) to try the simulated knob."_s);
    connectSim();
    QVERIFY(find<LinkBanner>("linkBanner")->text().isEmpty());
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    for (QToolBar *bar : m_window->findChildren<QToolBar *>()) {
        for (QAbstractButton *button : bar->findChildren<QAbstractButton *>())
            QVERIFY2(button->focusPolicy() == Qt::NoFocus, qPrintable(button->text()));
    }

    // F1 names what the keys do, whatever the actions' states.
    const QStringList lines = ShortcutsDialog::describe(m_window->shortcutActions());
    const auto line = [&](const QKeySequence &key) {
        const QString text = key.toString(QKeySequence::NativeText) + u'\t';
        for (const QString &l : lines) {
            if (l.startsWith(text) || l.contains(u" or "_s + text))
                return l.section(u'\t', 1);
        }
        return QString();
    };
    QCOMPARE(line(QKeySequence(Qt::CTRL | Qt::Key_K)), u"Connect or disconnect"_s);
    QCOMPARE(line(QKeySequence(Qt::CTRL | Qt::Key_R)), u"Record, or stop recording"_s);

    // A key for each panel under the plots: it comes to the front, again hides it.
    const std::pair<const char *, QKeyCombination> panels[] = {
        {"bridgeDock", Qt::CTRL | Qt::SHIFT | Qt::Key_B},
        {"experimentsDock", Qt::CTRL | Qt::SHIFT | Qt::Key_X},
        {"abDock", Qt::CTRL | Qt::SHIFT | Qt::Key_C},
        {"notesDock", Qt::CTRL | Qt::SHIFT | Qt::Key_N},
        {"logDock", Qt::CTRL | Qt::SHIFT | Qt::Key_L},
    };
    for (const auto &[name, key] : panels) {
        auto *dock = find<QDockWidget>(name);
        QVERIFY2(!line(QKeySequence(key)).isEmpty(), name);
        QTest::keySequence(m_window.get(), QKeySequence(key));
        QTRY_VERIFY2(dock->isVisible() && !dock->visibleRegion().isEmpty(), name);
        QTest::keySequence(m_window.get(), QKeySequence(key));
        QTRY_VERIFY2(!dock->isVisible(), name);
    }

    // A click on Push leaves the cursor in the field being tuned.
    auto *box = find<QAbstractSpinBox>("spin_K_max");
    QTest::keyClick(m_window.get(), Qt::Key_4, Qt::AltModifier);
    QCOMPARE(QApplication::focusWidget(), box);
    QTest::keyClicks(box, u"0.5"_s);
    QTest::keyClick(box, Qt::Key_Return);
    QSignalSpy done(find<DeviceParameterLink>("parameterLink"),
                    &DeviceParameterLink::commandFinished);
    QTest::mouseClick(find<QWidget>("button_push"), Qt::LeftButton);
    QVERIFY(done.wait(kConnectMs));
    QCOMPARE(QApplication::focusWidget(), box);
}

// Issue 27: a dock shrunk once stayed shrunk across launches; View → Reset layout.
void TestMainWindow::resetLayoutRestoresTheDocks()
{
    m_window->resize(1280, 720);
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    auto *parameters = find<QDockWidget>("parametersDock");
    const int width = parameters->width();
    QVERIFY(width >= 400);
    m_window->resizeDocks({parameters}, {width - 120}, Qt::Horizontal);
    auto *bridge = find<QDockWidget>("bridgeDock");
    bridge->show();
    auto *stiffness = find<QDockWidget>("stiffnessDock");
    stiffness->hide();
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QVERIFY2(parameters->width() < width - 60, qPrintable(QString::number(parameters->width())));

    // Across a launch, the shrunk dock stays: saved, read back.
    m_window->close();
    m_window = std::make_unique<MainWindow>();
    m_window->resize(1280, 720);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    parameters = find<QDockWidget>("parametersDock");
    QVERIFY2(parameters->width() < width - 60, qPrintable(QString::number(parameters->width())));

    auto *reset = find<QAction>("resetLayoutAction");
    QVERIFY(reset);
    reset->trigger();
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QTRY_VERIFY2(parameters->width() >= 420, // resizeDocksToDefault: at least 420 px
                 qPrintable(QString::number(parameters->width())));
    QVERIFY(find<QDockWidget>("stiffnessDock")->isVisible());
    QVERIFY(!find<QDockWidget>("bridgeDock")->isVisible());
}

QTEST_MAIN(TestMainWindow)
void TestMainWindow::handAndStiffnessInSightTogether()
{
    // Once tabs of one dock: the operating point could not be watched while the input changed.
    m_window->resize(1280, 720);
    connectSim();
    QTRY_VERIFY(find<QDockWidget>("simulatorDock")->isVisible());
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    auto *stiffness = find<QWidget>("stiffness_plot");
    auto *hand = find<QWidget>("simulatorPanel");
    QVERIFY(stiffness->isVisible() && !stiffness->visibleRegion().isEmpty());
    QVERIFY(hand->isVisible() && !hand->visibleRegion().isEmpty());
    // Never tabs of one dock with the stiffness view (at 1280×720 the hand is a tab of the
    // panels under the plots, none of them open here: bottomdocks.h).
    QVERIFY(!m_window->tabifiedDockWidgets(find<QDockWidget>("simulatorDock"))
                 .contains(find<QDockWidget>("stiffnessDock")));
    // The active input in the status bar, following the panel.
    auto *status = find<QLabel>("handStatus");
    QVERIFY(status->isVisible());
    QCOMPARE(status->text(), QStringLiteral("Hand: sine 0.06 N·m at 0.2 Hz"));
    HandInput still;
    still.kind = HandInput::Kind::Constant;
    still.amplitude = 0.01;
    find<SimulatorPanel>("simulatorPanel")->setHand(still);
    QCOMPARE(status->text(), QStringLiteral("Hand: constant 0.01 N·m"));
    m_window->disconnectDevice();
    QTRY_VERIFY(!status->isVisible());
}

void TestMainWindow::keyboardReachesFieldsAndActions()
{
    connectSim();
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    auto *editor = find<ParameterEditor>("parameterEditor");

    // Alt+4 goes to K_max; Tab goes from field to field (no sliders, no buttons between).
    QTest::keyClick(m_window.get(), Qt::Key_4, Qt::AltModifier);
    QCOMPARE(QApplication::focusWidget(), find<QWidget>("spin_K_max"));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
    QCOMPARE(QApplication::focusWidget(), find<QWidget>("spin_N"));
    QTest::keyClick(m_window.get(), Qt::Key_1, Qt::AltModifier);
    QCOMPARE(QApplication::focusWidget(), find<QWidget>("spin_D_adm"));
    for (const char *next : {"spin_M_adm", "spin_K_min", "spin_K_max"}) {
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), find<QWidget>(next));
    }

    // Space in a number field pauses; again resumes.
    auto *plots = find<PlotPanel>("plotPanel");
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QVERIFY(plots->isPaused());
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QVERIFY(!plots->isPaused());

    // Ctrl+Z in a field: its own typing first, then the parameter edit.
    const double before = editor->params().K_max;
    auto *box = find<QAbstractSpinBox>("spin_K_max");
    box->selectAll();
    QTest::keyClicks(box, QStringLiteral("0.7"));
    QTest::keyClick(box, Qt::Key_Return);
    QCOMPARE(editor->params().K_max, 0.7);
    QTest::keyClicks(box, QStringLiteral("5"));
    QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier); // the field's own undo: the "5"
    QCOMPARE(editor->params().K_max, 0.7);
    QTest::keyClick(box, Qt::Key_Return);
    for (int i = 0; i < 3 && editor->params().K_max != before; ++i)
        QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(editor->params().K_max, before);
    // Ctrl+Shift+Z in the field redoes the edit: the field has no typing of its own to redo.
    QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(editor->params().K_max, 0.7);

    // Read and window length by key.
    QSignalSpy reads(editor, &ParameterEditor::readRequested);
    QTest::keyClick(m_window.get(), Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(reads.count(), 1);
    QTest::keyClick(m_window.get(), Qt::Key_3, Qt::ControlModifier);
    QCOMPARE(plots->windowLength(), 30.0);
    const bool autoscale = plots->autoscale();
    QTest::keyClick(m_window.get(), Qt::Key_A, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(plots->autoscale(), !autoscale);

    // F1's dialog carries the user guide too.
    ShortcutsDialog dialog(m_window->shortcutActions(), m_window.get());
    auto *guide = dialog.findChild<QTextBrowser *>(QStringLiteral("userGuide"));
    QVERIFY(guide);
    QVERIFY(guide->toPlainText().contains(QStringLiteral("HATPIC Tuner — user guide")));
}

void TestMainWindow::derivedFiguresInSightAtEverySize_data()
{
    QTest::addColumn<QSize>("size");
    QTest::newRow("1280x720") << QSize(1280, 720);
    QTest::newRow("1400x900") << QSize(1400, 900);
    QTest::newRow("1920x1080") << QSize(1920, 1080);
}

void TestMainWindow::derivedFiguresInSightAtEverySize()
{
    // Once, at 1280×720 the editor showed D_adm to K_max only; the figures and warnings were
    // below, to be scrolled to. Now they sit under Push, wholly visible at every size.
    QFETCH(QSize, size);
    QVERIFY2(m_window->minimumSizeHint().width() <= 1280 &&
                 m_window->minimumSizeHint().height() <= 720,
             qPrintable(QStringLiteral("%1×%2")
                            .arg(m_window->minimumSizeHint().width())
                            .arg(m_window->minimumSizeHint().height())));
    m_window->resize(size);
    connectSim();
    auto *editor = find<ParameterEditor>("parameterEditor");
    // A set that both saturates and rings: both warnings show.
    DeviceParams p = editor->params();
    p.K_min = 1.0;
    p.K_max = 4.0;
    p.M_adm = 0.001;
    editor->setParams(p, editor->hostParams(), QStringLiteral("test"));
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QCOMPARE(m_window->size(), size);

    auto wholeInSight = [this](QWidget *w) {
        if (!w->isVisible())
            return false;
        const QRect inWindow(w->mapTo(m_window.get(), QPoint(0, 0)), w->size());
        return m_window->rect().contains(inWindow) && w->visibleRegion() == QRegion(w->rect());
    };
    auto *push = find<QWidget>("button_push");
    QVERIFY(wholeInSight(push));
    for (const char *name : {"derivedFiguresBox", "figure_zeta", "figure_peak_tau",
                             "warning_saturation", "warning_ringing"})
        QVERIFY2(wholeInSight(find<QWidget>(name)), name);
    // Next to Push: right below its row.
    const int pushBottom = push->mapTo(m_window.get(), QPoint(0, push->height())).y();
    const int boxTop = find<QWidget>("derivedFiguresBox")->mapTo(m_window.get(), QPoint(0, 0)).y();
    QVERIFY2(boxTop - pushBottom < 80, qPrintable(QString::number(boxTop - pushBottom)));
}

#include "tst_mainwindow.moc"
