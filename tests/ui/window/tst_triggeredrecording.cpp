// Triggered recordings on the real MainWindow against the in-process simulator: the options
// set through the Recording Options action, the record button arms, a push opens the file
// with the span before it and the parameters before it, and the fixed length closes it
// itself; an armed threshold that is called off writes nothing.
#include "editor/parametereditor.h"
#include "profiles/profilecontroller.h"
#include "recording/recordingcontrols.h"
#include "session/deviceclient.h"
#include "telemetry/recordingreader.h"
#include "window/mainwindow.h"

#include <QAction>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace hatpic;

namespace {

constexpr int kConnectMs = 15000; //!< generous: the machine is shared

} // namespace

class TestTriggeredRecording : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void pushTriggerWithSpanAndLength();
    void cancelledThresholdWritesNothing();

private:
    void connectSim(MainWindow &window);
    QTemporaryDir m_dir;
};

void TestTriggeredRecording::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("hatpic-test"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_triggeredrecording"));
    QSettings().clear();
    QVERIFY(m_dir.isValid());
}

void TestTriggeredRecording::connectSim(MainWindow &window)
{
    window.findChild<ProfileController *>(QStringLiteral("profileController"))
        ->setQuestion([](const QString &) { return QMessageBox::Discard; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    ConnectOptions options;
    options.port = QStringLiteral("sim");
    options.protocol = ProtocolChoice::V2;
    window.connectTo(options);
    auto *client = window.findChild<DeviceClient *>(QStringLiteral("deviceClient"));
    QTRY_COMPARE_WITH_TIMEOUT(client->state(), SessionState::Connected, kConnectMs);
    auto *editor = window.findChild<ParameterEditor *>(QStringLiteral("parameterEditor"));
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::InSync, kConnectMs);
}

void TestTriggeredRecording::pushTriggerWithSpanAndLength()
{
    MainWindow window;
    connectSim(window);
    auto *controls = window.findChild<RecordingControls *>(QStringLiteral("recordingControls"));
    auto *editor = window.findChild<ParameterEditor *>(QStringLiteral("parameterEditor"));
    RecordingPlan plan;
    plan.start = RecordingPlan::Start::NextPush;
    plan.preTrigger_s = 0.3;
    plan.duration_s = 0.5;
    controls->setPlanChooser([plan](const RecordingPlan &) { return std::optional(plan); });
    controls->planAction()->trigger();
    const QString path = m_dir.filePath(QStringLiteral("push.csv"));
    controls->setPathChooser([&](const QString &) { return path; });
    QTest::qWait(400); // more than the span before the trigger has been received
    controls->recordAction()->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(controls->status().armed, kConnectMs);
    QVERIFY(controls->recordAction()->isChecked());
    QVERIFY(controls->statusText().contains(QStringLiteral("the next push")));
    QVERIFY(!QFileInfo::exists(path));

    const double kMaxBefore = editor->params().K_max;
    DeviceParams edited = editor->params();
    edited.K_max = kMaxBefore + 0.05;
    editor->setParams(edited, editor->hostParams(), QStringLiteral("K_max"));
    editor->pushAction()->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(controls->status().active, kConnectMs);
    // The length closes it: no stop pressed.
    QTRY_VERIFY_WITH_TIMEOUT(!controls->status().active && !controls->status().armed, kConnectMs);
    QVERIFY(controls->status().error.isEmpty());
    QVERIFY(!controls->recordAction()->isChecked());

    const RecordingReadResult read = readRecording(path);
    QVERIFY2(read.recording, qPrintable(read.error));
    const Recording &rec = *read.recording;
    // The parameters before the push (as the device holds them: float32).
    QVERIFY(std::abs(rec.metadata.params.K_max - kMaxBefore) < 1e-6);
    QVERIFY(!rec.events.isEmpty());
    const RecordingEvent trigger = rec.events.constFirst();
    QVERIFY2(trigger.text.startsWith(QLatin1String("trigger: push; K_max")),
             qPrintable(trigger.text));
    const double before = trigger.t_s - rec.samples.constFirst().t_s;
    const double after = rec.samples.constLast().t_s - trigger.t_s;
    // The span ends at the trigger; the event is written on the first sample after it, which a
    // loaded machine may deliver a frame or two late (1 kHz: a few ms).
    QVERIFY2(before > 0.2 && before <= 0.3 + 0.005, qPrintable(QString::number(before)));
    QVERIFY2(after > 0.4 && after <= 0.5 + 1e-9, qPrintable(QString::number(after)));
}

void TestTriggeredRecording::cancelledThresholdWritesNothing()
{
    MainWindow window;
    connectSim(window);
    auto *controls = window.findChild<RecordingControls *>(QStringLiteral("recordingControls"));
    RecordingPlan plan;
    plan.start = RecordingPlan::Start::Threshold;
    plan.quantity = RecordingPlan::Quantity::Theta;
    plan.level = 3.0; // out of the simulated hand's reach
    controls->setPlan(plan);
    const QString path = m_dir.filePath(QStringLiteral("never.csv"));
    controls->setPathChooser([&](const QString &) { return path; });
    controls->recordAction()->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(controls->status().armed, kConnectMs);
    QVERIFY(controls->statusText().contains(QStringLiteral("θ rising through 3 rad")));
    controls->recordAction()->trigger(); // called off
    QTRY_VERIFY_WITH_TIMEOUT(!controls->status().armed, kConnectMs);
    QVERIFY(!controls->status().active);
    QVERIFY(!QFileInfo::exists(path));
}

QTEST_MAIN(TestTriggeredRecording)
#include "tst_triggeredrecording.moc"
