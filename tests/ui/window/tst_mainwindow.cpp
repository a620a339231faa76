// The real MainWindow against the in-process simulator ("sim") and, where built, the hatpic-sim
// program on a pseudo-terminal: connect, plots fill, edit → push → in sync, invalid values,
// device rejection, undo/redo, profiles, A/B, a legacy device, the simulated hand, disconnect,
// link loss, degrees. Recording and replay: tst_mainwindowreplay; keys, the wheel, sizes and
// settings: tst_mainwindowusability.
#include "connection/connectionbar.h"
#include "connection/linkbanner.h"
#include "connection/linkstatswidget.h"
#include "connection/linkstatuswidget.h"
#include "editor/deviceparameterlink.h"
#include "editor/parametereditor.h"
#include "mainwindowtest.h"
#include "plots/knobsview.h"
#include "plots/plotfeed.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"
#include "profiles/profilecontroller.h"
#include "recording/recordingcontrols.h"
#include "simulator/simulatorpanel.h"
#include "simulatoroptions.h"
#include "stiffness/stiffnessview.h"
#include "telemetry/recordingreader.h"
#include "window/mainwindow.h"

#include <QAction>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QProcess>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <QUndoStack>

#include <cmath>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

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

} // namespace

class TestMainWindow : public test::MainWindowTest
{
    Q_OBJECT
public:
    TestMainWindow() : MainWindowTest(QStringLiteral("tst_mainwindow")) {}

private Q_SLOTS:
    void connectsToSimulatorAndPlotsSamples_data();
    void connectsToSimulatorAndPlotsSamples();
    void editPushInSyncChangesBehaviour();
    void invalidValueDisablesPush();
    void deviceRejectionIsShown();
    void undoRedo();
    void profileSaveLoadRoundTrip();
    void abSwitchKeepsBothTunings();
    void legacyDeviceCannotPush();
    void simulatedHandReachesDevice();
    void disconnectKeepsPlotData();
    void lostLinkKeepsDataAndReconnects();
    void degreesToggleReachesEveryView();
    void imuBranchBoardShowsItsKnobs();
};

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
    // One knob: its plots show it all, and the Knobs dock stays away.
    QVERIFY(!find<QDockWidget>("knobsDock")->isVisible());
    QVERIFY(!find<QDockWidget>("knobsDock")->toggleViewAction()->isEnabled());

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

void TestMainWindow::imuBranchBoardShowsItsKnobs()
{
#ifndef HATPIC_SIM_EXECUTABLE
    QSKIP("hatpic-sim is not built");
#else
    // The published IMU branch's board (simulated, on a pseudo-terminal): four knobs and a tilt.
    QProcess sim;
    sim.start(QStringLiteral(HATPIC_SIM_EXECUTABLE),
              {QStringLiteral("--device"), QStringLiteral("imu-branch"), QStringLiteral("--hand-2"),
               QStringLiteral("const:0.05"), QStringLiteral("--tilt"), QStringLiteral("0.3,-0.2")});
    QVERIFY(sim.waitForStarted(5000));
    QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
    ConnectOptions options;
    options.port = QString::fromLocal8Bit(sim.readLine()).trimmed();
    m_window->connectTo(options);
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Connected, kConnectMs);
    auto *dock = find<QDockWidget>("knobsDock");
    auto *knobs = find<KnobsView>("knobs_view");
    QTRY_VERIFY_WITH_TIMEOUT(dock->isVisible(), kConnectMs);
    QVERIFY(dock->toggleViewAction()->isEnabled());
    QTRY_COMPARE_WITH_TIMEOUT(knobs->knobs(), 4, kDataMs);
    QVERIFY(knobs->showsTilt());
    QTRY_VERIFY_WITH_TIMEOUT(knobs->knobAngle(2) > 0.02, kDataMs); // knob 2 is pushed
    QVERIFY(std::abs(knobs->knobAngle(1)) < 0.01);
    QVERIFY2(knobs->text().contains(QStringLiteral("Knob 4: ")) &&
                 knobs->text().contains(QStringLiteral("; roll ")),
             qPrintable(knobs->text()));
    QVERIFY2(linkStatus()->identityText().contains(QStringLiteral("IMU branch")),
             qPrintable(linkStatus()->identityText()));
    find<PlotPanel>("plotPanel")->repaintNow();
    QVERIFY(find<PlotPanel>("plotPanel")->pointCount(Channel::Theta) > 0); // knob 1 is plotted
    const QImage shot = knobs->grab().toImage();
    QVERIFY(shot.width() >= 5 * 84 && shot.height() >= 84);

    m_window->disconnectDevice();
    QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Disconnected, kConnectMs);
    QVERIFY(!dock->isVisible());
    QCOMPARE(knobs->knobs(), 0);
    sim.terminate();
    QVERIFY(sim.waitForFinished(5000));
#endif
}

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
