// End to end: DeviceClient against the hatpic-sim program over a real pseudo-terminal.
#include "session/deviceclient.h"
#include "simprocess.h"
#include "telemetry/recordingreader.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace hatpic;
using hatpic::test::SimProcess;

namespace {

constexpr int kConnectTimeoutMs = 5000;

struct Collector
{
    QList<Sample> samples;
    double lastT() const { return samples.isEmpty() ? -1 : samples.last().t_s; }
    qsizetype after(double t) const
    {
        return std::count_if(samples.cbegin(), samples.cend(),
                             [t](const Sample &s) { return s.t_s > t; });
    }
};

} // namespace

class TestSessionPty : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void detects_data();
    void detects();
    void paramsOverPty();
    void throughput_data();
    void throughput();
    void killedSimulatorIsLostAndReconnects();
};

void TestSessionPty::initTestCase()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not part of this build");
#endif
}

void TestSessionPty::detects_data()
{
    QTest::addColumn<QString>("protocol");
    QTest::addColumn<int>("baud");
    QTest::newRow("v2") << QStringLiteral("v2") << 921600;
    QTest::newRow("legacy") << QStringLiteral("legacy") << 115200;
}

void TestSessionPty::detects()
{
    QFETCH(QString, protocol);
    QFETCH(int, baud);
    SimProcess sim({QStringLiteral("--protocol"), protocol});
    const QString path = sim.path();
    QVERIFY2(!path.isEmpty(), qPrintable(sim.errors()));
    DeviceClient client;
    Collector c;
    connect(&client, &DeviceClient::samplesReady, this,
            [&](const SampleBatch &b) { c.samples.append(b); });
    ConnectOptions o;
    o.port = path;
    o.baud = baud;
    client.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(client.state(), SessionState::Connected, kConnectTimeoutMs);
    QCOMPARE(wireProtocolName(client.deviceInfo().protocol), protocol);
    QCOMPARE(client.deviceInfo().port, path);
    QTRY_VERIFY_WITH_TIMEOUT(c.samples.size() >= 3, kConnectTimeoutMs);
    if (protocol == u"legacy")
        QVERIFY(c.samples.last().flags & kFlagModelEstimated);
}

void TestSessionPty::paramsOverPty()
{
    SimProcess sim({QStringLiteral("--hand"), QStringLiteral("sine:0.05:1")});
    const QString path = sim.path();
    QVERIFY2(!path.isEmpty(), qPrintable(sim.errors()));
    DeviceClient client;
    ConnectOptions o;
    o.port = path;
    client.connectDevice(o);
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().params.has_value(), kConnectTimeoutMs);
    DeviceParams p;
    p.K_max = 1.5;
    p.D_adm = 2e-4;
    QObject caller;
    QList<Outcome> outcomes;
    client.request(request::Push{{p, std::nullopt}},
                   {&caller, [&outcomes](const Outcome &o) { outcomes.append(o); }});
    QTRY_COMPARE_WITH_TIMEOUT(outcomes.size(), 1, kConnectTimeoutMs);
    const Outcome r = outcomes.first();
    QCOMPARE(std::get<outcome::Done>(r.result).readBack, outcome::ReadBack::Matches);
    QCOMPARE(client.deviceTuning().params.value().K_max, 1.5);
    QCOMPARE(client.deviceTuning().params.value().D_adm, double(2e-4f));
}

void TestSessionPty::throughput_data()
{
    QTest::addColumn<int>("rate");
    QTest::newRow("1 kHz") << 1000;
    QTest::newRow("2 kHz") << 2000;
}

void TestSessionPty::throughput()
{
    QFETCH(int, rate);
    SimProcess sim({QStringLiteral("--rate"), QString::number(rate)});
    const QString path = sim.path();
    QVERIFY2(!path.isEmpty(), qPrintable(sim.errors()));
    DeviceClient client;
    ConnectOptions o;
    o.port = path;
    o.streamRateHz = quint16(rate);
    client.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(client.state(), SessionState::Connected, kConnectTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(client.stats().frames > quint64(rate), kConnectTimeoutMs);
    const quint64 frames0 = client.stats().frames;
    QElapsedTimer window;
    window.start();
    QTRY_VERIFY_WITH_TIMEOUT(client.stats().frames > frames0 + quint64(2 * rate),
                             2 * kConnectTimeoutMs);
    const LinkStats s = client.stats();
    const double averageRate = double(s.frames - frames0) / (double(window.elapsed()) / 1000.0);
    qInfo("over the pty at %d Hz: %.0f frames/s, %.0f B/s, seq drops %llu, decoder drops %llu, "
          "RTT last %.2f ms / median %.2f ms / max %.2f ms",
          rate, s.framesPerSecond, s.bytesPerSecond, s.seqDrops, s.totalDecoderDrops(), s.rttLastMs,
          s.rttMedianMs, s.rttMaxMs);
    // The exact rate is tested on simulated time (tst_simulateddevicelink); here the point is that
    // the pty carries the stream without a loss. The rate is judged over two seconds of host
    // time, loosely: a loaded CI machine delays the simulator, which then catches up in bursts.
    QVERIFY2(averageRate > 0.8 * rate && averageRate < 1.2 * rate,
             qPrintable(QString::number(averageRate)));
    QCOMPARE(s.totalDecoderDrops(), quint64(0));
    QCOMPARE(s.seqDrops, quint64(0));
    QVERIFY(s.rttMedianMs >= 0 && s.rttMedianMs < 50);
}

void TestSessionPty::killedSimulatorIsLostAndReconnects()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("hatpic"));
    const QString csv = dir.filePath(QStringLiteral("run.csv"));
    auto sim = std::make_unique<SimProcess>(QStringList{QStringLiteral("--link"), link});
    QVERIFY2(!sim->path().isEmpty(), qPrintable(sim->errors()));

    DeviceClient client;
    Collector c;
    QList<SessionState> states;
    connect(&client, &DeviceClient::samplesReady, this,
            [&](const SampleBatch &b) { c.samples.append(b); });
    connect(&client, &DeviceClient::stateChanged, this,
            [&](SessionState s, const StateDetail &) { states.append(s); });
    ConnectOptions o;
    o.port = link;
    client.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(client.state(), SessionState::Connected, kConnectTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(c.samples.size() > 100, kConnectTimeoutMs);
    client.startRecording(csv);
    QTRY_VERIFY_WITH_TIMEOUT(client.recordingStatus().samples > 500, kConnectTimeoutMs);

    sim->kill();
    QTRY_COMPARE_WITH_TIMEOUT(client.state(), SessionState::Lost, kConnectTimeoutMs);
    // The recording stays open and waits for the device (recording.md, "Link losses").
    QTRY_VERIFY(client.recordingStatus().waiting);
    QVERIFY(client.recordingStatus().active);
    QVERIFY(client.recordingStatus().error.isEmpty());
    const double tLost = c.lastT();

    // Same --link path, new pty behind it: the session finds it by itself.
    sim = std::make_unique<SimProcess>(QStringList{QStringLiteral("--link"), link});
    QVERIFY2(!sim->path().isEmpty(), qPrintable(sim->errors()));
    QTRY_COMPARE_WITH_TIMEOUT(client.state(), SessionState::Connected, kConnectTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(c.after(tLost) > 100, kConnectTimeoutMs);
    QVERIFY(states.contains(SessionState::Detecting));
    double last = -1;
    for (const Sample &s : std::as_const(c.samples)) {
        QVERIFY(s.t_s >= last);
        last = s.t_s;
    }
    QTRY_VERIFY(client.stats().referenceGaps >= 1); // p_ref held across the loss

    // One recording across the restart: every sample received before the loss, then the
    // rows of the restarted simulator, the first of them marked as the gap's end.
    QTRY_VERIFY(!client.recordingStatus().waiting);
    const double tResumed = c.lastT();
    QTRY_VERIFY_WITH_TIMEOUT(c.after(tResumed) > 100, kConnectTimeoutMs);
    client.stopRecording();
    QTRY_VERIFY(!client.recordingStatus().active);
    QCOMPARE(client.recordingStatus().gaps, 1u);
    const RecordingReadResult r = readRecording(csv);
    QVERIFY2(r.recording, qPrintable(r.error));
    QVERIFY(r.warnings.isEmpty());
    QCOMPARE(quint64(r.recording->samples.size()), client.recordingStatus().samples);
    QVERIFY(std::any_of(r.recording->samples.cbegin(), r.recording->samples.cend(),
                        [&](const Sample &s) { return s.t_s == tLost; }));
    QVERIFY(r.recording->samples.last().t_s > tResumed);
    QCOMPARE(r.recording->events.size(), 1);
    QVERIFY2(r.recording->events.first().text.startsWith(u"gap: link lost after t_s "),
             qPrintable(r.recording->events.first().text));
    QVERIFY(r.recording->events.first().t_s > tLost);
}

QTEST_GUILESS_MAIN(TestSessionPty)
#include "tst_sessionpty.moc"
