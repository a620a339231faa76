// DeviceSession against a device that sends nonsense (issue 10, "Hostile input"): the test
// plays the device on the master side of a real pseudo-terminal and scripts its answers.
#include "protocol/v2codec.h"
#include "scripteddevice.h"
#include "session/devicesession.h"
#include "telemetry/recordingreader.h"
#include "telemetry/recordingwriter.h"

#include <QSocketNotifier>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <fcntl.h>
#include <limits>
#include <pty.h>
#include <unistd.h>

using namespace hatpic;
using hatpic::test::ScriptedDevice;
using namespace Qt::StringLiterals;

namespace {

constexpr int kTimeoutMs = 5000;
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

struct Session
{
    DeviceSession session;
    QList<Sample> samples;
    QList<DeviceInfo> infos;
    StateDetail lastDetail;
    LinkStats stats;
    Session()
    {
        QObject::connect(&session.samples(), &SamplePipeline::samplesReady,
                         [this](const SampleBatch &b) { samples.append(b); });
        QObject::connect(&session, &DeviceSession::deviceInfoChanged,
                         [this](const DeviceInfo &i) { infos.append(i); });
        QObject::connect(&session, &DeviceSession::stateChanged,
                         [this](SessionState, const StateDetail &d) { lastDetail = d; });
        QObject::connect(&session, &DeviceSession::statsUpdated,
                         [this](const LinkStats &s) { stats = s; });
    }
    ~Session() { QObject::disconnect(&session, nullptr, nullptr, nullptr); }
    void connectTo(const QString &port, ProtocolChoice choice = ProtocolChoice::Auto)
    {
        ConnectOptions o;
        o.port = port;
        o.baud = 921600;
        o.protocol = choice;
        o.feedbackRateHz = 0;
        o.autoReconnect = false;
        session.connectDevice(o);
    }
};

} // namespace

class TestSessionHostile : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void nonsenseHelloReplyIsRefused_data();
    void nonsenseHelloReplyIsRefused();
    void firmwareNameIsMadePrintable();
    void strayByteBeforeHelloIsSurvived_data();
    void strayByteBeforeHelloIsSurvived();
    void nonFiniteTelemetryIsSkippedAndCounted();
    void paramsFloodKeepsTheRecordingReadable();
};

void TestSessionHostile::nonsenseHelloReplyIsRefused_data()
{
    QTest::addColumn<float>("tauLimit");
    QTest::addColumn<int>("maxStreamHz");
    QTest::addColumn<QString>("field");
    QTest::newRow("tau_limit -1") << -1.0f << 1000 << u"tau_limit"_s;
    QTest::newRow("tau_limit 0") << 0.0f << 1000 << u"tau_limit"_s;
    QTest::newRow("tau_limit NaN") << kNaN << 1000 << u"tau_limit"_s;
    QTest::newRow("tau_limit Inf") << kInf << 1000 << u"tau_limit"_s;
    QTest::newRow("tau_limit 11") << 11.0f << 1000 << u"tau_limit"_s;
    QTest::newRow("max_stream_hz 0") << 0.44f << 0 << u"max_stream_hz"_s;
}

void TestSessionHostile::nonsenseHelloReplyIsRefused()
{
    QFETCH(float, tauLimit);
    QFETCH(int, maxStreamHz);
    QFETCH(QString, field);
    ScriptedDevice device;
    QVERIFY(device.isValid());
    device.hello.tauLimit = tauLimit;
    device.hello.maxStreamHz = quint16(maxStreamHz);
    Session s;
    s.connectTo(device.path());
    QTRY_VERIFY_WITH_TIMEOUT(device.hellosAnswered() > 0, kTimeoutMs);
    QTRY_COMPARE_WITH_TIMEOUT(s.session.state(), SessionState::Disconnected, kTimeoutMs);
    QVERIFY2(s.infos.isEmpty(), "a nonsense device was taken as connected");
    QCOMPARE(s.lastDetail.port, device.path());
    const auto *refused = s.lastDetail.as<state::Refused>();
    QVERIFY(refused);
    QVERIFY2(refused->error.contains(field), qPrintable(refused->error));
}

void TestSessionHostile::firmwareNameIsMadePrintable()
{
    ScriptedDevice device;
    QVERIFY(device.isValid());
    device.hello.firmware.assign("ev\x1b[2J\r\nil\x7f");
    Session s;
    s.connectTo(device.path());
    QTRY_COMPARE_WITH_TIMEOUT(s.session.state(), SessionState::Connected, kTimeoutMs);
    const QString firmware = s.session.deviceInfo().firmware;
    for (const QChar c : firmware)
        QVERIFY2(c.unicode() >= 0x20 && c.unicode() != 0x7F, qPrintable(firmware));
    QCOMPARE(firmware, u"ev\\x1b[2J\\x0d\\x0ail\\x7f"_s);
}

void TestSessionHostile::strayByteBeforeHelloIsSurvived_data()
{
    QTest::addColumn<int>("choice");
    QTest::newRow("auto") << int(ProtocolChoice::Auto);
    QTest::newRow("forced v2") << int(ProtocolChoice::V2);
}

void TestSessionHostile::strayByteBeforeHelloIsSurvived()
{
    // One byte of noise already sits in the device's receiver: the HELLO must not be glued
    // onto it.
    QFETCH(int, choice);
    ScriptedDevice device;
    QVERIFY(device.isValid());
    device.preload(QByteArray(1, '\x05'));
    Session s;
    s.connectTo(device.path(), ProtocolChoice(choice));
    QTRY_COMPARE_WITH_TIMEOUT(s.session.state(), SessionState::Connected, kTimeoutMs);
}

void TestSessionHostile::nonFiniteTelemetryIsSkippedAndCounted()
{
    ScriptedDevice device;
    QVERIFY(device.isValid());
    Session s;
    s.connectTo(device.path());
    QTRY_COMPARE_WITH_TIMEOUT(s.session.state(), SessionState::Connected, kTimeoutMs);
    quint32 t = 1000;
    const auto burst = [&](int n, float theta) {
        for (int i = 0; i < n; ++i)
            device.sendTelemetry(theta, t += 1000);
    };
    burst(20, 0.5f);
    device.sendTelemetry(kNaN, t += 1000);
    device.sendTelemetry(kInf, t += 1000);
    burst(20, 0.5f);
    QTRY_COMPARE_WITH_TIMEOUT(s.samples.size(), 40, kTimeoutMs);
    for (const Sample &sample : std::as_const(s.samples)) {
        QVERIFY(std::isfinite(sample.theta));
        QVERIFY(std::isfinite(sample.p_ref));
        QVERIFY(std::isfinite(sample.v_ref));
    }
    // p_ref goes on integrating after the bad frames.
    QVERIFY(s.samples.last().p_ref > s.samples[19].p_ref);
    QTRY_COMPARE_WITH_TIMEOUT(s.stats.nonFinite, quint64(2), kTimeoutMs);
}

void TestSessionHostile::paramsFloodKeepsTheRecordingReadable()
{
    // A device sending PARAMS that differ each time, 2000 per second, while telemetry flows:
    // the recording stays readable and its events bounded.
    ScriptedDevice device;
    QVERIFY(device.isValid());
    Session s;
    s.connectTo(device.path());
    QTRY_COMPARE_WITH_TIMEOUT(s.session.state(), SessionState::Connected, kTimeoutMs);
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"flood.csv"_s);
    s.session.startRecording(csv, u"tst_sessionhostile"_s);
    quint32 t = 1000;
    DeviceParams a;
    DeviceParams b = a;
    b.K_max = 0.6;
    for (int ms = 0; ms < 1500; ++ms) {
        device.send(v2::Params{ms % 2 ? a : b});
        device.send(v2::Params{ms % 2 ? b : a});
        device.sendTelemetry(0.01f, t += 1000);
        if (ms % 20 == 0)
            QTest::qWait(1);
    }
    QTRY_VERIFY_WITH_TIMEOUT(s.samples.size() >= 1500, kTimeoutMs);
    s.session.stopRecording();
    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording, qPrintable(read.error));
    QCOMPARE(read.recording->samples.size(), 1500);
    QVERIFY2(read.recording->events.size() <= 2 * (RecordingWriter::kMaxEventsPerSecond + 1),
             qPrintable(QString::number(read.recording->events.size())));
    QFile json(recordingMetadataPath(csv));
    QVERIFY(json.size() < 256 * 1024);
}

QTEST_GUILESS_MAIN(TestSessionHostile)
#include "tst_sessionhostile.moc"
