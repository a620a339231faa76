// The sample pipeline carries out a RecordingPlan: armed until θ crosses or a push takes
// effect, the pre-trigger span from the recent samples, a fixed length that closes the file
// itself (whole and readable), calling off an armed recording, and the recent samples' bound;
// the recording controller's one state through all of it (idle, armed, open, waiting).
#include "session/samplepipeline.h"
#include "telemetry/recordingreader.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace hatpic;

namespace {

Sample at(int ms)
{
    Sample s;
    s.t_s = ms / 1000.0;
    s.theta = s.t_s; // θ [rad] ramps with time: crosses level L at t = L
    return s;
}

void pushRange(SamplePipeline &pipeline, int fromMs, int toMs)
{
    for (int i = fromMs; i <= toMs; ++i)
        pipeline.push(at(i));
    pipeline.flush();
}

RecordingStatus lastStatus(const QSignalSpy &spy)
{
    return spy.constLast().at(0).value<RecordingStatus>();
}

} // namespace

class TestRecordingPlan : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void thresholdWithPreTriggerAndLength();
    void nextPushKeepsParamsBefore();
    void nowWithLengthClosesItself();
    void cancelArmed();
    void recentSamplesAreBounded();
    void oneStateAtATime();

private:
    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }
    QTemporaryDir m_dir;
};

void TestRecordingPlan::initTestCase()
{
    QVERIFY(m_dir.isValid());
    registerSessionMetaTypes();
}

void TestRecordingPlan::thresholdWithPreTriggerAndLength()
{
    SamplePipeline pipeline;
    QSignalSpy status(&pipeline, &SamplePipeline::recordingChanged);
    pushRange(pipeline, 0, 500);
    RecordingPlan plan;
    plan.start = RecordingPlan::Start::Threshold;
    plan.level = 1.0;
    plan.preTrigger_s = 0.25;
    plan.duration_s = 0.5;
    const QString csv = path("threshold.csv");
    pipeline.startRecording(csv, QStringLiteral("test"), DeviceInfo{}, plan);
    QVERIFY(pipeline.isArmed());
    QVERIFY(lastStatus(status).armed);
    QVERIFY(!QFile::exists(csv)); // nothing is written while armed
    pushRange(pipeline, 501, 999);
    QVERIFY(pipeline.isArmed());
    pushRange(pipeline, 1000, 2000);
    QVERIFY(!pipeline.isArmed());
    QVERIFY(!pipeline.isRecording()); // closed itself after its length
    const RecordingStatus last = lastStatus(status);
    QVERIFY(!last.active);
    QVERIFY(last.error.isEmpty());

    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording, qPrintable(read.error));
    const Recording &rec = *read.recording;
    QCOMPARE(rec.samples.size(), 750); // (0.75, 1.0) before, [1.0, 1.5] after
    QCOMPARE(rec.samples.constFirst().t_s, 0.751);
    QCOMPARE(rec.samples.constLast().t_s, 1.5);
    QCOMPARE(rec.events.size(), 1);
    QCOMPARE(rec.events[0].t_s, 1.0);
    QCOMPARE(rec.events[0].text, QStringLiteral("trigger: theta rising through 1"));
}

void TestRecordingPlan::nextPushKeepsParamsBefore()
{
    SamplePipeline pipeline;
    DeviceParams before;
    before.K_max = 0.4;
    pipeline.builder().setDeviceParams(before);
    pushRange(pipeline, 0, 300);
    RecordingPlan plan;
    plan.start = RecordingPlan::Start::NextPush;
    plan.preTrigger_s = 0.1;
    const QString csv = path("push.csv");
    pipeline.startRecording(csv, QStringLiteral("test"), DeviceInfo{}, plan);
    pushRange(pipeline, 301, 400);
    pipeline.tuningApplied(CommandKind::Zero, {}); // a ZERO is no push
    QVERIFY(pipeline.isArmed());
    DeviceParams after = before;
    after.K_max = 0.6;
    pipeline.tuningApplied(CommandKind::SetParams, {after, std::nullopt});
    QVERIFY(pipeline.isRecording());
    pushRange(pipeline, 401, 600);
    pipeline.stopRecording();

    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording, qPrintable(read.error));
    const Recording &rec = *read.recording;
    QCOMPARE(rec.samples.constFirst().t_s, 0.301); // 0.1 s before the push at 0.4 s
    QCOMPARE(rec.samples.constLast().t_s, 0.6);
    QCOMPARE(rec.metadata.params.K_max, 0.4); // the parameters before the push
    QCOMPARE(rec.events.size(), 1);
    QCOMPARE(rec.events[0].t_s, 0.401);
    QVERIFY2(rec.events[0].text.startsWith(QLatin1String("trigger: push; K_max 0.4")),
             qPrintable(rec.events[0].text));
}

void TestRecordingPlan::nowWithLengthClosesItself()
{
    SamplePipeline pipeline;
    RecordingPlan plan;
    plan.duration_s = 0.2;
    const QString csv = path("now.csv");
    pipeline.startRecording(csv, QStringLiteral("test"), DeviceInfo{}, plan);
    QVERIFY(pipeline.isRecording());
    pushRange(pipeline, 1000, 1500);
    QVERIFY(!pipeline.isRecording());
    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording, qPrintable(read.error));
    QCOMPARE(read.recording->samples.size(), 201); // 1.0 … 1.2 s
    QCOMPARE(read.recording->samples.constLast().t_s, 1.2);
    QVERIFY(read.recording->events.isEmpty()); // a plain start marks nothing
}

void TestRecordingPlan::cancelArmed()
{
    SamplePipeline pipeline;
    QSignalSpy status(&pipeline, &SamplePipeline::recordingChanged);
    RecordingPlan plan;
    plan.start = RecordingPlan::Start::Threshold;
    plan.level = 0.5;
    const QString csv = path("cancelled.csv");
    pipeline.startRecording(csv, QStringLiteral("test"), DeviceInfo{}, plan);
    pipeline.stopRecording();
    QVERIFY(!pipeline.isArmed());
    QVERIFY(!lastStatus(status).armed);
    QVERIFY(!lastStatus(status).active);
    pushRange(pipeline, 0, 1000); // crosses 0.5: nothing starts any more
    QVERIFY(!pipeline.isRecording());
    QVERIFY(!QFile::exists(csv));
}

void TestRecordingPlan::recentSamplesAreBounded()
{
    SamplePipeline pipeline;
    pushRange(pipeline, 0, 15000);
    RecordingPlan plan;
    plan.preTrigger_s = 60; // more than is kept: sanitized to kMaxPreTrigger_s
    const QString csv = path("bounded.csv");
    pipeline.startRecording(csv, QStringLiteral("test"), DeviceInfo{}, plan);
    pushRange(pipeline, 15001, 15001); // the start is marked on the first sample after it
    pipeline.stopRecording();
    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording, qPrintable(read.error));
    QCOMPARE(read.recording->samples.size(), 10001); // (5.0, 15.0], then 15.001
    QCOMPARE(read.recording->samples.constFirst().t_s, 5.001);
    QCOMPARE(read.recording->events.size(), 1);
    QCOMPARE(read.recording->events[0].t_s, 15.001);
    QCOMPARE(read.recording->events[0].text, QStringLiteral("trigger: start"));
}

// The controller is in one of its four states, each with its own facts, and says which.
void TestRecordingPlan::oneStateAtATime()
{
    using namespace recording;
    SamplePipeline pipeline;
    const RecordingController &rec = pipeline.recording();
    QVERIFY(std::holds_alternative<Idle>(rec.state()));
    pushRange(pipeline, 0, 100);

    RecordingPlan plan;
    plan.start = RecordingPlan::Start::Threshold;
    plan.level = 0.2;
    plan.duration_s = 1.0;
    DeviceInfo device;
    device.deviceId = 7;
    pipeline.startRecording(path("states.csv"), QStringLiteral("test"), device, plan);
    const auto *armed = std::get_if<Armed>(&rec.state());
    QVERIFY(armed);
    QCOMPARE(armed->trigger.plan().level, 0.2);
    QCOMPARE(armed->device.deviceId, 7u);

    pushRange(pipeline, 101, 300); // crosses 0.2 at 0.2 s: open until 1.2 s
    const auto *open = std::get_if<Open>(&rec.state());
    QVERIFY(open);
    QCOMPARE(open->stopAt, std::optional(1.2));
    QCOMPARE(open->device.deviceId, 7u);

    // The link goes while the session reconnects: it waits, with what held at the loss.
    DeviceParams held;
    held.K_max = 0.45;
    pipeline.tuningReceived({held, std::nullopt, std::nullopt});
    pipeline.connectionEnded({}, true);
    const auto *waiting = std::get_if<Waiting>(&rec.state());
    QVERIFY(waiting);
    QVERIFY(!waiting->reconnected);
    QCOMPARE(waiting->held.params->K_max, 0.45);
    QCOMPARE(waiting->open.stopAt, std::optional(1.2)); // what resumes

    // The same device is back and tells its parameters: open again, its length kept.
    pipeline.connectionStarted(device);
    QVERIFY(std::holds_alternative<Waiting>(rec.state())); // its parameters not told yet
    QVERIFY(std::get<Waiting>(rec.state()).reconnected);
    pipeline.tuningReceived({held, std::nullopt, std::nullopt});
    open = std::get_if<Open>(&rec.state());
    QVERIFY(open);
    QCOMPARE(open->stopAt, std::optional(1.2));

    pipeline.stopRecording();
    QVERIFY(std::holds_alternative<Idle>(rec.state()));
}

QTEST_GUILESS_MAIN(TestRecordingPlan)
#include "tst_recordingplan.moc"
