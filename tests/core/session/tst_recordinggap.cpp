// A recording across a link loss (recording.md, "Link losses"): the device behind a real
// pseudo-terminal (SimulatorHost with a --link style symlink, as hatpic-sim runs it) goes
// away while recording and comes back. The same device: the recording waits, resumes in the
// same file, and the first row after the gap says what happened. A different device: the
// recording ends at the loss and says why. The session runs on the test thread.
#include "session/devicesession.h"
#include "sim/simlink.h"
#include "sim/simulatorhost.h"
#include "simulatoroptions.h"
#include "telemetry/numbertext.h"
#include "telemetry/recordingreader.h"

#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

constexpr int kConnectTimeoutMs = 5000;

//! A session with what it tells collected.
struct Harness
{
    DeviceSession session;
    QList<Sample> samples;
    QList<RecordingStatus> recording;
    QList<SessionNotice> notices;

    Harness()
    {
        QObject::connect(&session.samples(), &SamplePipeline::samplesReady,
                         [this](const SampleBatch &b) { samples.append(b); });
        QObject::connect(&session.samples(), &SamplePipeline::recordingChanged,
                         [this](const RecordingStatus &r) { recording.append(r); });
        QObject::connect(&session, &DeviceSession::notice,
                         [this](const SessionNotice &n) { notices.append(n); });
    }
    ~Harness() { QObject::disconnect(&session, nullptr, nullptr, nullptr); }
    double lastT() const { return samples.isEmpty() ? -1.0 : samples.last().t_s; }
    qsizetype samplesAfter(double t) const
    {
        return std::count_if(samples.cbegin(), samples.cend(),
                             [t](const Sample &s) { return s.t_s > t; });
    }
    bool noticed(SessionNotice::Kind kind) const
    {
        return std::any_of(notices.cbegin(), notices.cend(),
                           [kind](const SessionNotice &n) { return n.kind == kind; });
    }
};

//! A simulated joystick behind a pty, reached through the symlink `link`; the hand holds the
//! knob in the notch band, so −τ_rec/θ is K_max on every row.
std::unique_ptr<SimulatorHost> startDevice(const QString &link, double kMax, quint32 deviceId,
                                           double tauLimit = 0.44)
{
    SimulatedDevice::Config config;
    config.params.K_max = kMax;
    config.deviceId = deviceId;
    config.tauLimit = tauLimit;
    config.hand = *HandInput::parse(u"const:0.03"_s);
    auto host = std::make_unique<SimulatorHost>(config);
    if (!host->start().isEmpty() || !host->createLink(link).isEmpty())
        return nullptr;
    return host;
}

double stiffness(const Sample &s)
{
    return -s.tau_rec / s.theta;
}

//! The event texts of a recording, in order.
QStringList eventTexts(const Recording &r)
{
    QStringList texts;
    for (const RecordingEvent &e : r.events)
        texts << e.text;
    return texts;
}

} // namespace

class TestRecordingGap : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void sameDeviceResumesInTheSameFile();
    void otherDeviceEndsTheRecording_data();
    void otherDeviceEndsTheRecording();
    void stopWhileWaitingKeepsTheGap();
    void unreadParametersResumeAfterAWait();
    void noReconnectClosesTheRecording();
};

void TestRecordingGap::sameDeviceResumesInTheSameFile()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(u"hatpic"_s);
    const QString csv = dir.filePath(u"run.csv"_s);
    const quint32 id = SimulatedDevice::Config{}.deviceId;
    auto device = startDevice(link, 0.6, id);
    QVERIFY(device);

    Harness h;
    ConnectOptions o;
    o.port = link;
    h.session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > 50, kConnectTimeoutMs);
    h.session.startRecording(csv, u"tst_recordinggap"_s);
    QTRY_VERIFY_WITH_TIMEOUT(h.recording.last().samples > 200, kConnectTimeoutMs);

    // The device goes away (hatpic-sim killed): the recording stays open and waits.
    device.reset();
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Lost, kConnectTimeoutMs);
    const double tLost = h.lastT();
    QVERIFY(h.session.deviceInfo().deviceId == id);
    QVERIFY(h.recording.last().active);
    QVERIFY(h.recording.last().waiting);
    QCOMPARE(h.recording.last().gaps, 1u);
    QVERIFY(h.noticed(SessionNotice::Kind::RecordingWaitsForDevice));
    QVERIFY(!h.noticed(SessionNotice::Kind::RecordingClosedByLoss));

    // It comes back on the same path, with its power-up K_max (what was pushed is gone).
    device = startDevice(link, 0.4, id);
    QVERIFY(device);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    QTRY_VERIFY(h.noticed(SessionNotice::Kind::RecordingResumed));
    QVERIFY(!h.recording.last().waiting);
    QTRY_VERIFY_WITH_TIMEOUT(h.samplesAfter(tLost) > 200, kConnectTimeoutMs);
    h.session.stopRecording();
    QVERIFY(!h.recording.last().active);
    QCOMPARE(h.recording.last().gaps, 1u);

    // One file: the rows before the loss, then the rows after it, the gap an event on the first.
    const RecordingReadResult rr = readRecording(csv);
    QVERIFY2(rr.recording, qPrintable(rr.error));
    const Recording &rec = *rr.recording;
    QVERIFY2(rr.warnings.isEmpty(), qPrintable(rr.warnings.join(u'\n')));
    QCOMPARE(quint64(rec.samples.size()), h.recording.last().samples);
    const auto firstAfter = std::find_if(rec.samples.cbegin(), rec.samples.cend(),
                                         [&](const Sample &s) { return s.t_s > tLost; });
    QVERIFY(firstAfter != rec.samples.cbegin() && firstAfter != rec.samples.cend());
    QCOMPARE((firstAfter - 1)->t_s, tLost);
    QVERIFY(rec.samples.cend() - firstAfter > 100);
    QCOMPARE(rec.events.size(), 1);
    const RecordingEvent &gap = rec.events.first();
    QCOMPARE(gap.t_s, firstAfter->t_s);
    QVERIFY2(gap.text.startsWith(u"gap: link lost after t_s "_s + compactNumberText(tLost) +
                                 u" (port error: "_s),
             qPrintable(gap.text));
    QVERIFY2(gap.text.contains(u"; recording resumed; K_max 0.6 → 0.4 (after the gap)"_s),
             qPrintable(gap.text));
    // The event row is the first the device rendered with the new value: every row after the
    // gap follows K_max 0.4, every row before it 0.6.
    QVERIFY(qAbs(stiffness(*(firstAfter - 1)) - 0.6) < 0.01);
    for (auto it = firstAfter; it != rec.samples.cend(); ++it)
        QVERIFY2(qAbs(stiffness(*it) - 0.4) < 0.01, qPrintable(QString::number(stiffness(*it))));
    QVERIFY(rec.metadata.device.deviceId == id);
}

void TestRecordingGap::otherDeviceEndsTheRecording_data()
{
    QTest::addColumn<quint32>("deviceId");
    QTest::addColumn<double>("tauLimit");
    QTest::addColumn<QString>("difference");
    const quint32 id = SimulatedDevice::Config{}.deviceId;
    QTest::newRow("another device id") << quint32(42) << 0.44 << u"device_id %1 → 42"_s.arg(id);
    QTest::newRow("another torque limit") << id << 0.3 << u"tau_limit 0.44 → 0.3"_s;
}

void TestRecordingGap::otherDeviceEndsTheRecording()
{
    QFETCH(quint32, deviceId);
    QFETCH(double, tauLimit);
    QFETCH(QString, difference);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(u"hatpic"_s);
    const QString csv = dir.filePath(u"run.csv"_s);
    auto device = startDevice(link, 0.4, SimulatedDevice::Config{}.deviceId);
    QVERIFY(device);
    Harness h;
    ConnectOptions o;
    o.port = link;
    h.session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    h.session.startRecording(csv, u"tst_recordinggap"_s);
    QTRY_VERIFY_WITH_TIMEOUT(h.recording.last().samples > 100, kConnectTimeoutMs);
    device.reset();
    QTRY_VERIFY_WITH_TIMEOUT(h.recording.last().waiting, kConnectTimeoutMs);
    const double tLost = h.lastT();

    device = startDevice(link, 0.4, deviceId, tauLimit);
    QVERIFY(device);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    QTRY_VERIFY(!h.recording.last().active);
    QVERIFY(!h.recording.last().waiting);
    QVERIFY(h.recording.last().error.isEmpty());
    QVERIFY(!h.noticed(SessionNotice::Kind::RecordingResumed));
    const auto closed =
        std::find_if(h.notices.cbegin(), h.notices.cend(), [](const SessionNotice &n) {
            return n.kind == SessionNotice::Kind::RecordingClosedOtherDevice;
        });
    QVERIFY(closed != h.notices.cend());
    QCOMPARE(closed->problems, QStringList{difference});

    // The file holds the rows of the first device only; its .json says why it ends there.
    const RecordingReadResult rr = readRecording(csv);
    QVERIFY2(rr.recording, qPrintable(rr.error));
    QCOMPARE(rr.recording->samples.last().t_s, tLost);
    const QStringList events = eventTexts(*rr.recording);
    QCOMPARE(events.size(), 1);
    QVERIFY2(events.first().contains(u"; a different device answered ("_s + difference +
                                     u"), so the recording ended at the loss"_s),
             qPrintable(events.first()));
    QCOMPARE(rr.recording->events.first().t_s, tLost);
}

void TestRecordingGap::stopWhileWaitingKeepsTheGap()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(u"hatpic"_s);
    const QString csv = dir.filePath(u"run.csv"_s);
    auto device = startDevice(link, 0.4, SimulatedDevice::Config{}.deviceId);
    QVERIFY(device);
    Harness h;
    ConnectOptions o;
    o.port = link;
    h.session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    h.session.startRecording(csv, u"tst_recordinggap"_s);
    QTRY_VERIFY_WITH_TIMEOUT(h.recording.last().samples > 100, kConnectTimeoutMs);
    device.reset();
    QTRY_VERIFY_WITH_TIMEOUT(h.recording.last().waiting, kConnectTimeoutMs);
    const double tLost = h.lastT();

    h.session.stopRecording();
    QVERIFY(!h.recording.last().active);
    QVERIFY(!h.recording.last().waiting);
    QCOMPARE(h.recording.last().gaps, 1u);
    const RecordingReadResult rr = readRecording(csv);
    QVERIFY2(rr.recording, qPrintable(rr.error));
    QCOMPARE(rr.recording->samples.last().t_s, tLost);
    const QStringList events = eventTexts(*rr.recording);
    QCOMPARE(events.size(), 1);
    QVERIFY2(events.first().startsWith(u"gap: link lost after t_s "_s + compactNumberText(tLost) +
                                       u" (port error: "_s),
             qPrintable(events.first()));
    QVERIFY(rr.recording->events.first().text.endsWith(
        u"; the recording ended before the device came back"_s));
    QCOMPARE(rr.recording->events.first().t_s, tLost);
}

void TestRecordingGap::unreadParametersResumeAfterAWait()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString csv = dir.filePath(u"run.csv"_s);
    Harness h;
    const ConnectOptions o = test::simulatorOptions({}, ProtocolChoice::V2);
    h.session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    h.session.startRecording(csv, u"tst_recordinggap"_s);
    QTRY_VERIFY_WITH_TIMEOUT(h.recording.last().samples > 100, kConnectTimeoutMs);

    // The device that comes back never answers GET_PARAMS (every resend is lost).
    QObject::connect(
        &h.session, &DeviceSession::stateChanged, &h.session, [&h](SessionState state) {
            if (state == SessionState::Connected && test::simLinkOf(h.session))
                test::simLinkOf(h.session)->dropHostFrames(1 + CommandQueue::kCommandRetries,
                                                           quint8(v2::MessageType::GetParams));
        });
    test::simLinkOf(h.session)->sever(u"unplugged by the test"_s);
    QVERIFY(h.recording.last().waiting);
    const double tLost = h.lastT();
    QTRY_VERIFY_WITH_TIMEOUT(h.noticed(SessionNotice::Kind::RecordingResumed),
                             kConnectTimeoutMs + 1000 * int(RecordingController::kResumeWait_s));
    QTRY_VERIFY_WITH_TIMEOUT(h.recording.last().samples > 0 && !h.recording.last().waiting,
                             kConnectTimeoutMs);
    const double tResumed = h.lastT();
    QTRY_VERIFY_WITH_TIMEOUT(h.samplesAfter(tResumed) > 20, kConnectTimeoutMs);
    h.session.stopRecording();

    const RecordingReadResult rr = readRecording(csv);
    QVERIFY2(rr.recording, qPrintable(rr.error));
    const QStringList events = eventTexts(*rr.recording);
    QCOMPARE(events.size(), 1);
    QVERIFY2(events.first().startsWith(u"gap: link lost after t_s "_s + compactNumberText(tLost) +
                                       u" (port error: unplugged by the test); recording "
                                       u"resumed; the device's parameters were not read back"_s),
             qPrintable(events.first()));
    // Rows resumed about kResumeWait_s after the first sample of the device that came back.
    const double firstRowAfter = rr.recording->events.first().t_s;
    const auto firstSampleAfter = std::find_if(h.samples.cbegin(), h.samples.cend(),
                                               [&](const Sample &s) { return s.t_s > tLost; });
    QVERIFY(firstSampleAfter != h.samples.cend());
    QVERIFY(firstRowAfter - firstSampleAfter->t_s >= RecordingController::kResumeWait_s);
}

void TestRecordingGap::noReconnectClosesTheRecording()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString csv = dir.filePath(u"run.csv"_s);
    Harness h;
    ConnectOptions o = test::simulatorOptions();
    o.autoReconnect = false; // hatpicctl: a loss ends the program, and the recording with it
    h.session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    h.session.startRecording(csv, u"tst_recordinggap"_s);
    QTRY_VERIFY_WITH_TIMEOUT(h.recording.last().samples > 50, kConnectTimeoutMs);
    test::simLinkOf(h.session)->sever(u"unplugged by the test"_s);
    QVERIFY(!h.recording.last().active);
    QVERIFY(!h.recording.last().waiting);
    QVERIFY(h.noticed(SessionNotice::Kind::RecordingClosedByLoss));
    QVERIFY(!h.noticed(SessionNotice::Kind::RecordingWaitsForDevice));
}

QTEST_GUILESS_MAIN(TestRecordingGap)
#include "tst_recordinggap.moc"
