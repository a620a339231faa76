// DeviceSession driven directly on the test thread, against the in-process simulator ("sim"):
// what it streams. Complete v2 and legacy samples, listeners seeing each sample before its
// batch, garbage counted while the stream continues, seq gaps, rates and RTT, recording events
// on the right row, a full disk during a session, severed and silent links reconnecting.
#include "model/reference.h"
#include "model/stiffness.h"
#include "session/devicesession.h"
#include "sessionharness.h"
#include "sim/simlink.h"
#include "sim/simulateddevice.h"
#include "simulatoroptions.h"
#include "telemetry/recordingreader.h"

#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

QByteArray randomGarbage(int n, quint32 seed)
{
    QByteArray out;
    quint32 x = seed;
    for (int i = 0; i < n; ++i) {
        x = x * 1664525u + 1013904223u;
        out.append(static_cast<char>(x >> 24));
    }
    return out;
}

} // namespace

class TestDeviceSessionStream : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void v2SamplesAreComplete();
    void legacySamplesAreModelEstimated();
    void sampleListenersSeeEachSampleBeforeItsBatch();
    void garbageIsCountedAndStreamContinues();
    void seqGapsAreCounted();
    void statsReportRatesAndRtt();
    void recordingEventsOnParamAndHostChanges();
    void recordingWriteErrorKeepsSession();
    void severedLinkReconnects();
    void silentLinkIsLostAndReconnects();
};

void TestDeviceSessionStream::v2SamplesAreComplete()
{
    Harness h;
    const ConnectOptions o = simOptions(WireProtocol::V2, ProtocolChoice::Auto,
                                        *HandInput::parse(QStringLiteral("sine:0.05:2")));
    h.session.connectDevice(o);
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() >= 500, kConnectTimeoutMs);
    double lastT = -1;
    qint64 lastArrival = 0;
    bool moved = false;
    for (const Sample &s : std::as_const(h.samples)) {
        QVERIFY2(s.t_s >= lastT, "t_s must not go back");
        lastT = s.t_s;
        // Stamped when decoded, on the host's steady clock (the plots' latency probe).
        QVERIFY(s.arrival_ns > 0 && s.arrival_ns >= lastArrival);
        QVERIFY(s.arrival_ns <= sampleClockNs());
        lastArrival = s.arrival_ns;
        for (double v :
             {s.theta, s.omega, s.tau, s.tau_rec, s.tau_ext, s.tau_total, s.v_ref, s.p_ref})
            QVERIFY(std::isfinite(v));
        QCOMPARE(s.flags & kFlagModelEstimated, 0);
        QCOMPARE(s.tau_total, std::clamp(s.tau_rec + s.tau_ext, -0.44, 0.44));
        QCOMPARE(s.v_ref, referenceVelocity(HostParams(), DeviceParams(), s.theta));
        moved = moved || std::abs(s.theta) > 0.01;
    }
    QVERIFY(moved);
    // 1 kHz telemetry: consecutive samples 1 ms apart on the device clock.
    const Sample &a = h.samples[h.samples.size() - 2];
    const Sample &b = h.samples.last();
    QCOMPARE(b.t_us - a.t_us, quint32(1000));
    QCOMPARE(qRound64((b.t_s - a.t_s) * 1e6), qint64(1000));
    // p_ref is the trapezoidal integral of v_ref over those device timestamps.
    QVERIFY(qAbs(b.p_ref - (a.p_ref + 0.5 * (a.v_ref + b.v_ref) * 1e-3)) < 1e-12);
}

void TestDeviceSessionStream::legacySamplesAreModelEstimated()
{
    Harness h;
    const ConnectOptions o = simOptions(WireProtocol::Legacy, ProtocolChoice::Auto,
                                        *HandInput::parse(QStringLiteral("const:0.05")));
    h.session.connectDevice(o);
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() >= 4, kConnectTimeoutMs);
    QCOMPARE(h.session.deviceInfo().protocol, WireProtocol::Legacy);
    for (const Sample &s : std::as_const(h.samples)) {
        QVERIFY(s.flags & kFlagModelEstimated);
        QVERIFY(std::isnan(s.omega));
        QVERIFY(std::isnan(s.tau));
        QVERIFY(std::isfinite(s.theta));
        QCOMPARE(s.tau_rec, recenteringTorque(DeviceParams(), s.theta));
        QVERIFY(std::isfinite(s.p_ref));
    }
    // The host clock stands in for the device's: ~200 ms between legacy frames.
    const double dt = h.samples.last().t_s - h.samples[h.samples.size() - 2].t_s;
    QVERIFY2(dt > 0.1 && dt < 0.4, qPrintable(QString::number(dt)));
}

void TestDeviceSessionStream::sampleListenersSeeEachSampleBeforeItsBatch()
{
    struct Listener : SampleListener
    {
        QList<Sample> seen;
        void sampleDecoded(const Sample &sample) override { seen.append(sample); }
    } listener;
    Harness h;
    h.session.sampleListeners().add(&listener);
    qsizetype batched = 0;
    bool listenerFirst = true;
    QObject::connect(&h.session.samples(), &SamplePipeline::samplesReady,
                     [&](const SampleBatch &batch) {
                         // Every sample of a batch reached the listener before the batch went out.
                         for (qsizetype i = 0; i < batch.size(); ++i) {
                             listenerFirst = listenerFirst && batched + i < listener.seen.size() &&
                                             listener.seen[batched + i].t_s == batch[i].t_s &&
                                             listener.seen[batched + i].theta == batch[i].theta;
                         }
                         batched += batch.size();
                     });
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > 200, kConnectTimeoutMs);
    QVERIFY(listenerFirst);
    for (const Sample &s : std::as_const(listener.seen))
        QVERIFY(s.arrival_ns > 0); // dated when decoded
    h.session.sampleListeners().remove(&listener);
    const qsizetype seen = listener.seen.size();
    const qsizetype before = h.samples.size();
    QTRY_VERIFY(h.samples.size() > before + 50);
    QCOMPARE(listener.seen.size(), seen); // removed: never called again
}

void TestDeviceSessionStream::garbageIsCountedAndStreamContinues()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > 100, kConnectTimeoutMs);
    const LinkStats before = h.session.stats();
    QCOMPARE(before.totalDecoderDrops(), quint64(0));
    // A frame with a bad CRC, a run without delimiter, then random bytes.
    QByteArray garbage = QByteArray::fromHex("0511223344") + '\0';
    garbage += QByteArray(300, '\x55') + '\0';
    garbage += randomGarbage(500, 7) + '\0';
    test::simLinkOf(h.session)->injectToHost(garbage);
    const LinkStats after = h.session.stats();
    QVERIFY(after.totalDecoderDrops() >= 3);
    QVERIFY(after.decoderDrops[int(v2::DropReason::Overflow)] >= 1);
    const double t = h.lastT();
    QTRY_VERIFY_WITH_TIMEOUT(h.samplesAfter(t) > 100, kCommandWaitMs);
    QCOMPARE(h.session.state(), SessionState::Connected);
}

void TestDeviceSessionStream::seqGapsAreCounted()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > 100, kConnectTimeoutMs);
    QCOMPARE(h.session.stats().seqDrops, quint64(0));
    // Swallow the device's output for a while: those telemetry frames never arrive.
    SimulatedDevice *device = test::simLinkOf(h.session)->device();
    const double silencedAt = device->time();
    test::simLinkOf(h.session)->setSilenced(true);
    QTRY_VERIFY(device->time() > silencedAt + 0.05);
    test::simLinkOf(h.session)->setSilenced(false);
    const double t = h.lastT();
    QTRY_VERIFY_WITH_TIMEOUT(h.samplesAfter(t) > 10, kCommandWaitMs);
    const LinkStats s = h.session.stats();
    QVERIFY2(s.seqDrops >= 20, qPrintable(QString::number(s.seqDrops)));
    // Every frame the device sent is either a sample or a counted drop (modulo 256 per gap).
    const quint32 span = h.samples.last().t_us - h.samples.first().t_us;
    const quint64 expected = span / 1000 + 1;
    QCOMPARE(quint64(h.samples.size()) + s.seqDrops, expected);
}

void TestDeviceSessionStream::statsReportRatesAndRtt()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(h.lastStats.rttLastMs >= 0 && h.lastStats.framesPerSecond > 900,
                             kConnectTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(h.session.stats().framesPerSecond > 900, 3000);
    const LinkStats s = h.session.stats();
    QVERIFY2(s.framesPerSecond < 1100, qPrintable(QString::number(s.framesPerSecond)));
    QVERIFY(s.bytesPerSecond > 900 * 31);
    QVERIFY(s.rttMedianMs >= 0);
    QVERIFY(s.rttMaxMs >= s.rttLastMs);
    QCOMPARE(s.referenceGaps, quint64(0));
}

void TestDeviceSessionStream::recordingEventsOnParamAndHostChanges()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString csv = dir.filePath(QStringLiteral("run.csv"));
    Harness h;
    // The hand holds θ in the notch band.
    const ConnectOptions o = simOptions(WireProtocol::V2, ProtocolChoice::V2,
                                        *HandInput::parse(QStringLiteral("const:0.03")));
    h.session.connectDevice(o);
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > 500, kConnectTimeoutMs);
    h.session.startRecording(csv, QStringLiteral("tst_devicesession"));
    QVERIFY(!h.recording.isEmpty() && h.recording.last().active);
    const qsizetype atStart = h.samples.size();
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > atStart + 100, kCommandWaitMs);

    DeviceParams p;
    p.K_max = 0.6;
    h.send(1, request::Push{{p, std::nullopt}});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(1), kCommandWaitMs);
    const qsizetype afterPush = h.samples.size();
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > afterPush + 100, kCommandWaitMs);
    HostParams host;
    host.v_max = 2;
    h.session.setHostParams(host);
    h.session.resetReference();
    const double t = h.lastT();
    QTRY_VERIFY_WITH_TIMEOUT(h.samplesAfter(t) > 20, kCommandWaitMs);
    h.session.stopRecording();
    QVERIFY(!h.recording.last().active);
    QVERIFY(h.recording.last().error.isEmpty());

    const RecordingReadResult rr = readRecording(csv);
    QVERIFY2(rr.recording, qPrintable(rr.error));
    const Recording &rec = *rr.recording;
    QVERIFY(rec.hasMetadata);
    QCOMPARE(rec.metadata.source, QStringLiteral("tst_devicesession"));
    QCOMPARE(rec.metadata.device.protocol, WireProtocol::V2);
    QCOMPARE(rec.metadata.params, asFloat(DeviceParams())); // exact: the device's float32 values
    QCOMPARE(rec.events.size(), 2);
    QCOMPARE(rec.events[0].text, QStringLiteral("K_max 0.4 → 0.6"));
    QCOMPARE(rec.events[1].text, QStringLiteral("v_max 1 → 2; p_ref reset to 0"));
    // The event sits on the first sample the device rendered with the new K_max: τ_rec of the
    // row before follows K_max 0.4, τ_rec from that row on follows 0.6 (θ is in the notch band).
    int eventRow = -1;
    for (int i = 0; i < rec.samples.size(); ++i) {
        if (rec.samples[i].t_s == rec.events[0].t_s) {
            eventRow = i;
            break;
        }
    }
    QVERIFY2(eventRow > 0, qPrintable(QStringLiteral("event at %1, row %2 of %3, first t %4")
                                          .arg(rec.events[0].t_s)
                                          .arg(eventRow)
                                          .arg(rec.samples.size())
                                          .arg(rec.samples.first().t_s)));
    auto stiffness = [](const Sample &s) { return -s.tau_rec / s.theta; };
    for (int i : {eventRow - 1, eventRow, eventRow + 1}) {
        const Sample &s = rec.samples[i];
        QVERIFY2(s.theta > 0.02 && s.theta < 0.1, qPrintable(QString::number(s.theta)));
        QVERIFY(s.flags & v2::kFlagNotch);
        const double expected = i < eventRow ? 0.4 : 0.6;
        QVERIFY2(qAbs(stiffness(s) - expected) < 1e-4,
                 qPrintable(QStringLiteral("row %1: K %2").arg(i).arg(stiffness(s))));
    }
    const int resetRow =
        static_cast<int>(std::find_if(rec.samples.cbegin(), rec.samples.cend(),
                                      [&](const Sample &s) { return s.t_s == rec.events[1].t_s; }) -
                         rec.samples.cbegin());
    QVERIFY(resetRow < rec.samples.size());
    QVERIFY(qAbs(rec.samples[resetRow].p_ref) < 1e-3); // p_ref restarted from 0 there
    QCOMPARE(rec.samples.size(), qsizetype(h.recording.last().samples));
}

void TestDeviceSessionStream::recordingWriteErrorKeepsSession()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString csv = dir.filePath(QStringLiteral("full.csv"));
    // A recording cannot be written there (issue 10: a device is not a file; once it was
    // /dev/full and "No space left on device", now it is refused before anything is touched).
    QVERIFY(QFile::link(QStringLiteral("/dev/full"), csv));
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(!h.samples.isEmpty(), kConnectTimeoutMs);
    h.session.startRecording(csv, QStringLiteral("test"));
    QVERIFY(!h.recording.isEmpty());
    QVERIFY(!h.recording.last().active);
    QVERIFY2(h.recording.last().error.contains(csv), qPrintable(h.recording.last().error));
    const double t = h.lastT();
    QTRY_VERIFY_WITH_TIMEOUT(h.samplesAfter(t) > 50, kCommandWaitMs);
    QCOMPARE(h.session.state(), SessionState::Connected);
}

void TestDeviceSessionStream::severedLinkReconnects()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("lost.csv"));
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2));
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > 50, kConnectTimeoutMs);
    h.session.startRecording(csv, QStringLiteral("test"));
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > 300, kCommandWaitMs);

    test::simLinkOf(h.session)->sever(QStringLiteral("unplugged by the test"));
    QCOMPARE(h.session.state(), SessionState::Lost);
    const double tLost = h.lastT(); // the loss flushed the samples still waiting in the batch
    const StateDetail lost = h.detailOf(SessionState::Lost);
    const auto *failed = lost.as<state::LinkFailed>();
    QVERIFY(failed);
    QVERIFY(failed->error.contains(u"unplugged by the test"));
    // The recording waits for the device (tst_recordinggap); everything received before the
    // loss reaches the disk with the next flush and is readable.
    QVERIFY(h.recording.last().active);
    QVERIFY(h.recording.last().waiting);
    QVERIFY(h.recording.last().error.isEmpty());
    auto rowsOnDisk = [&csv] {
        const RecordingReadResult rr = readRecording(csv);
        return rr.recording ? rr.recording->samples : QList<Sample>();
    };
    QTRY_VERIFY(!rowsOnDisk().isEmpty() && rowsOnDisk().last().t_s == tLost);

    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(h.samplesAfter(tLost) > 10, kConnectTimeoutMs);
    // t_s keeps going across the gap (host time), and the reference held across it.
    double last = -1;
    for (const Sample &s : std::as_const(h.samples)) {
        QVERIFY(s.t_s >= last);
        last = s.t_s;
    }
    const auto firstAfter = std::find_if(h.samples.cbegin(), h.samples.cend(),
                                         [&](const Sample &s) { return s.t_s > tLost; });
    QVERIFY(firstAfter->t_s - tLost > 0.25); // reopened after ≥ 500 ms
    QVERIFY(firstAfter->flags & kFlagReferenceGap);
    QCOMPARE(h.session.stats().referenceGaps, quint64(1));
}

void TestDeviceSessionStream::silentLinkIsLostAndReconnects()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > 50, kConnectTimeoutMs);
    test::simLinkOf(h.session)->setSilenced(true); // the port stays, the device says nothing
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Lost,
                              DeviceSession::kSilenceTimeoutMs + 2000);
    QVERIFY(h.detailOf(SessionState::Lost).why ==
            StateDetail::Why(state::Silent{DeviceSession::kSilenceTimeoutMs}));
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
}

QTEST_GUILESS_MAIN(TestDeviceSessionStream)
#include "tst_devicesessionstream.moc"
