// A real DeviceSession against a simulated joystick whose link injects faults: in process
// (the "sim" port, SimLink's FaultInjector) and over a real pseudo-terminal (hatpic-sim
// --faults). The session's counters must equal what was injected, no damaged or repeated
// frame may become a sample, a cut must lose nothing already received, and a command must
// be applied once, whole, or fail with a reason.
#include "link/faultinjector.h"
#include "protocol/v2codec.h"
#include "session/devicesession.h"
#include "session/samplelisteners.h"
#include "session/sessionwording.h"
#include "sim/simlink.h"
#include "simulatoroptions.h"
#include "telemetry/recordingreader.h"

#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>
#include <optional>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

constexpr int kConnectMs = 5000;
constexpr int kPushEndsMs = 8000;

FaultSpec faultSpec(const QString &text)
{
    QString error;
    const auto spec = FaultSpec::parse(text, &error);
    if (!spec)
        qFatal("%s", qPrintable(error));
    return *spec;
}

ConnectOptions simWithFaults(const QString &faults, quint64 seed)
{
    SimulatedDevice::Config config;
    config.faults = faultSpec(faults);
    config.seed = seed;
    return test::simulatorOptions(config, ProtocolChoice::V2);
}

// What the receiver has seen of the faults, less what the session counted: constant while
// the session counts right (it is not zero: the session starts counting at connect).
struct Unaccounted
{
    qint64 lost = 0;
    qint64 corrupted = 0;
    qint64 duplicated = 0;
    qint64 otherDrops = 0;
    friend bool operator==(const Unaccounted &, const Unaccounted &) = default;
};

Unaccounted unaccounted(const FaultCounts &seen, const LinkStats &stats, quint64 deviceDrops = 0)
{
    const quint64 crc = stats.decoderDrops[std::size_t(v2::DropReason::Crc)];
    return {qint64(seen.streamLost + seen.streamCorrupted + deviceDrops) - qint64(stats.seqDrops),
            qint64(seen.corrupted) - qint64(crc),
            qint64(seen.streamDuplicated) - qint64(stats.duplicates),
            qint64(stats.totalDecoderDrops() - crc)};
}

char *toString(const Unaccounted &u)
{
    return qstrdup(qPrintable(u"lost %1, corrupted %2, duplicated %3, other drops %4"_s.arg(u.lost)
                                  .arg(u.corrupted)
                                  .arg(u.duplicated)
                                  .arg(u.otherDrops)));
}

// Samples in arrival order, each device frame at most once, on the device's cycle grid.
void verifySamplesAreWholeFrames(const QList<Sample> &samples)
{
    QVERIFY(samples.size() > 1);
    for (qsizetype i = 1; i < samples.size(); ++i) {
        const quint32 step = samples[i].t_us - samples[i - 1].t_us;
        QVERIFY2(step > 0 && step % 1000 == 0, qPrintable(u"sample %1: t_us %2 after %3"_s.arg(i)
                                                              .arg(samples[i].t_us)
                                                              .arg(samples[i - 1].t_us)));
        QVERIFY(std::isfinite(samples[i].theta) && std::abs(samples[i].theta) < 10);
    }
}

// Tells when every frame the device has made so far has reached the session: its newest
// cycle's frame is the newest sample. Only then are the losses behind the newest frame all
// revealed as seq gaps (a gap shows when the next frame arrives, and a tick of the simulated
// device may end with frames its full output queue dropped) and none is in flight, so the
// session's counters can be compared with what was injected. Every cycle must be streamed.
class Settled : public SampleListener
{
public:
    Settled(DeviceSession &session, SimulatedDevice &device) : m_session(session)
    {
        device.setCycleObserver(
            [this](const SimulatedDevice::Cycle &c) { m_madeUs = c.toSample().t_us; });
        session.sampleListeners().add(this);
    }
    ~Settled() { m_session.sampleListeners().remove(this); }
    Settled(const Settled &) = delete;
    Settled &operator=(const Settled &) = delete;

    void sampleDecoded(const Sample &sample) override { m_receivedUs = sample.t_us; }
    bool operator()() const { return m_madeUs && m_receivedUs == m_madeUs; }

private:
    DeviceSession &m_session;
    std::optional<quint32> m_madeUs;     // all on the test's thread, which runs the session
    std::optional<quint32> m_receivedUs; // and the simulated device
};

// One "name=value" figure from a hatpic-sim summary line that starts with `line`.
quint64 figure(const QString &summary, const QString &line, const QString &name)
{
    const QRegularExpression re(QRegularExpression::escape(line) + u"[^\\n]*\\b"_s +
                                QRegularExpression::escape(name) + u"=(\\d+)"_s);
    const QRegularExpressionMatch m = re.match(summary);
    return m.hasMatch() ? m.captured(1).toULongLong() : ~quint64(0);
}

} // namespace

class TestSessionFaults : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { registerSessionMetaTypes(); }

    void countersEqualWhatWasInjected()
    {
        // Lost frames are those the link dropped plus those the device itself could not
        // queue (SimulatedDevice::telemetryDropped, also seen as seq gaps).
        DeviceSession session;
        QList<Sample> samples;
        connect(&session.samples(), &SamplePipeline::samplesReady,
                [&samples](const SampleBatch &b) { samples.append(b); });
        session.connectDevice(
            simWithFaults(u"drop=0.02,corrupt=0.01,dup=0.01,delay=0.01:5ms,hdrop=0.05"_s, 9));
        QTRY_VERIFY_WITH_TIMEOUT(samples.size() > 100, kConnectMs);
        const FaultInjector *faults = test::simLinkOf(session)->faults();
        QVERIFY(faults);
        SimulatedDevice *device = test::simLinkOf(session)->device();
        QCOMPARE(double(device->streamRate()),
                 device->config().controlRateHz); // each cycle streamed
        const Settled settled(session, *device);
        QTRY_VERIFY_WITH_TIMEOUT(settled(), kConnectMs);
        const Unaccounted before =
            unaccounted(faults->toHostSeen(), session.stats(), device->telemetryDropped());
        const FaultCounts seenBefore = faults->toHostSeen();
        QTest::qWait(2500);
        QTRY_VERIFY_WITH_TIMEOUT(settled(), kConnectMs);
        QCOMPARE(unaccounted(faults->toHostSeen(), session.stats(), device->telemetryDropped()),
                 before);
        QCOMPARE(before.otherDrops, 0);
        // Faults did happen in the window: the comparison above is not of zeros.
        const FaultCounts &seen = faults->toHostSeen();
        QVERIFY2(seen.streamLost - seenBefore.streamLost > 10, qPrintable(faults->summary()));
        QVERIFY(seen.corrupted - seenBefore.corrupted > 5);
        QVERIFY(seen.streamDuplicated - seenBefore.streamDuplicated > 5);
        QVERIFY(seen.delayed - seenBefore.delayed > 5);
        QVERIFY(faults->toDeviceCounts().dropped > 0);
        QCOMPARE(session.state(), SessionState::Connected);
        session.disconnectDevice();
        verifySamplesAreWholeFrames(samples);
        const LinkStats stats = session.stats();
        QCOMPARE(quint64(samples.size()), stats.frames - stats.duplicates - stats.nonFinite);
    }

    void aCutLosesNothingReceivedBeforeIt()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath(u"cut.csv"_s);
        DeviceSession session;
        QList<Sample> samples;
        QList<RecordingStatus> recording;
        connect(&session.samples(), &SamplePipeline::samplesReady,
                [&samples](const SampleBatch &b) { samples.append(b); });
        connect(&session.samples(), &SamplePipeline::recordingChanged,
                [&recording](const RecordingStatus &r) { recording.append(r); });
        // 1.2 s at 1 kHz: more frames than the u8 seq can count, less than the silence that
        // declares the device lost (2 s).
        session.connectDevice(simWithFaults(u"cut=1500ms:1200ms"_s, 1));
        QTRY_VERIFY_WITH_TIMEOUT(!samples.isEmpty(), kConnectMs);
        session.startRecording(csv, u"tst_sessionfaults"_s);
        QVERIFY(!recording.isEmpty() && recording.last().active);
        const FaultInjector *faults = test::simLinkOf(session)->faults();
        QCOMPARE(faults->toHostCounts().cut, quint64(0)); // recording before the cut
        QTRY_VERIFY_WITH_TIMEOUT(faults->toHostCounts().cut > 0, kConnectMs);
        QTRY_VERIFY_WITH_TIMEOUT(faults->toHostSeen().cut > 1000, kConnectMs); // cut is over
        QTest::qWait(300);
        QCOMPARE(session.state(), SessionState::Connected);
        QCOMPARE(session.stats().seqDrops, faults->toHostSeen().streamLost);
        session.stopRecording();
        QVERIFY2(recording.last().error.isEmpty(), qPrintable(recording.last().error));
        const RecordingReadResult read = readRecording(csv);
        QVERIFY2(read.recording, qPrintable(read.error));
        const QList<Sample> &rows = read.recording->samples;
        // Every sample the session handed out while recording is in the file, in order.
        // (The file keeps t_s, exact; its t_us is derived from t_s.)
        qsizetype at = 0;
        while (at < samples.size() && samples[at].t_s != rows.first().t_s)
            ++at;
        QVERIFY(at < samples.size());
        QCOMPARE(rows.size(), qsizetype(recording.last().samples));
        QCOMPARE(at + rows.size(), samples.size());
        QVERIFY(rows.size() > 500); // from before the cut to after it
        for (qsizetype i = 0; i < rows.size(); ++i) {
            QCOMPARE(rows[i].t_s, samples[at + i].t_s);
            QCOMPARE(rows[i].theta, samples[at + i].theta);
            QCOMPARE(rows[i].tau, samples[at + i].tau);
        }
        verifySamplesAreWholeFrames(samples);
    }

    void aPushDuringACut_data()
    {
        QTest::addColumn<QString>("cut");
        QTest::addColumn<bool>("completes");
        // Four sends 250 ms apart cover 1 s: a shorter cut is retried through, a longer one
        // times out.
        QTest::newRow("short cut: completes after it") << u"cut=1s:600ms"_s << true;
        QTest::newRow("long cut: fails with a reason") << u"cut=1s:1500ms"_s << false;
    }
    void aPushDuringACut()
    {
        QFETCH(QString, cut);
        QFETCH(bool, completes);
        DeviceSession session;
        QList<Outcome> finished;
        QSignalSpy samples(&session.samples(), &SamplePipeline::samplesReady);
        session.connectDevice(simWithFaults(cut, 1));
        QTRY_VERIFY_WITH_TIMEOUT(samples.size() > 0, kConnectMs);
        const FaultInjector *faults = test::simLinkOf(session)->faults();
        QTRY_VERIFY_WITH_TIMEOUT(faults->toHostCounts().cut > 0, kConnectMs);
        const SimulatedDevice *device = test::simLinkOf(session)->device();
        const DeviceParams before = device->params();
        const quint64 appliedBefore = device->paramsApplied();
        DeviceParams wanted = before;
        wanted.K_max = 0.7;
        wanted.N = 0.2;
        session.request(request::Push{{wanted, std::nullopt}},
                        [&finished](const Outcome &o) { finished.append(o); });
        // A push ends by itself after its last try (about 1 s); the wait only bounds a hang,
        // with room for a loaded machine.
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, kPushEndsMs);
        const Outcome result = finished.first();
        QCOMPARE(session.state(), SessionState::Connected);
        if (completes) {
            QVERIFY2(result.ok(), qPrintable(SessionWording::commandFailure(result)));
            QCOMPARE(device->params().K_max, double(0.7f));
            QCOMPARE(device->params().N, double(0.2f));
            QCOMPARE(device->paramsApplied(), appliedBefore + 1);
        } else {
            const auto *timedOut = std::get_if<outcome::TimedOut>(&result.result);
            QVERIFY2(timedOut, qPrintable(SessionWording::commandFailure(result)));
            // The reason is structured: which step went unanswered, after how many frames.
            QCOMPARE(timedOut->step, CommandKind::SetParams);
            QVERIFY(timedOut->attempts > 1);
            QCOMPARE(device->params(), before); // nothing of it applied
            QCOMPARE(device->paramsApplied(), appliedBefore);
        }
    }

    void lostSetParamsAreRetriedAndAppliedOnce()
    {
        // A third of the host's frames and of the device's answers lost: retries carry every
        // push through, and a retry the device already applied is answered, not applied.
        DeviceSession session;
        QList<Outcome> finished;
        QSignalSpy samples(&session.samples(), &SamplePipeline::samplesReady);
        session.connectDevice(simWithFaults(u"hdrop=0.3,drop=0.3"_s, 5));
        QTRY_VERIFY_WITH_TIMEOUT(samples.size() > 0, kConnectMs);
        const SimulatedDevice *device = test::simLinkOf(session)->device();
        const FaultInjector *faults = test::simLinkOf(session)->faults();
        const quint64 appliedBefore = device->paramsApplied();
        const quint64 hostDropsBefore = faults->toDeviceCounts().dropped;
        const quint64 retriesBefore = session.stats().retries;
        constexpr int kPushes = 12;
        quint64 missed = 0; // pushes the device never received
        double previous = device->params().K_max;
        for (int i = 1; i <= kPushes; ++i) {
            DeviceParams p = device->params();
            p.K_max = 0.3 + 0.02 * i;
            session.request(request::Push{{p, std::nullopt}},
                            [&finished](const Outcome &o) { finished.append(o); });
            QTRY_COMPARE_WITH_TIMEOUT(finished.size(), i, kPushEndsMs);
            const Outcome r = finished.last();
            // A timed-out push's last frame may still be on its way (the emulated UART, the
            // device's next cycle): let it land before counting.
            if (!r.ok())
                QTest::qWait(300);
            // Applied exactly once when acknowledged; at most once, and then whole, when
            // every answer was lost.
            const quint64 applied = device->paramsApplied() - appliedBefore;
            const bool reached = applied == quint64(i) - missed; // this push was applied
            if (r.ok()) {
                QVERIFY(reached);
            } else {
                QVERIFY(std::holds_alternative<outcome::TimedOut>(r.result));
                QVERIFY(reached || applied == quint64(i) - missed - 1);
                if (!reached)
                    ++missed;
            }
            // Whole or not at all: the pushed set, or the one before it.
            QTRY_COMPARE(device->params().K_max, reached ? double(float(p.K_max)) : previous);
            previous = device->params().K_max;
        }
        QVERIFY(faults->toDeviceCounts().dropped > hostDropsBefore);
        QVERIFY(session.stats().retries > retriesBefore);
        QVERIFY(missed <= 2);
    }

#ifdef HATPIC_SIM_PATH
    void countersEqualWhatHatpicSimInjectedOverAPty()
    {
        // Three cuts of 1 s: inside each, all that came before is drained and the session
        // and hatpic-sim (asked with SIGUSR1) are compared at rest.
        QProcess sim;
        sim.start(QStringLiteral(HATPIC_SIM_PATH),
                  {u"--faults"_s,
                   u"drop=0.02,corrupt=0.01,dup=0.01,delay=0.01:5ms,"
                   u"cut=2s:1s,cut=4s:1s,cut=6s:1s"_s,
                   u"--seed"_s, u"4"_s});
        QVERIFY(sim.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), kConnectMs);
        QElapsedTimer clock;
        clock.start();
        const QString path = QString::fromUtf8(sim.readLine()).trimmed();
        DeviceSession session;
        QSignalSpy samples(&session.samples(), &SamplePipeline::samplesReady);
        ConnectOptions o;
        o.port = path;
        o.protocol = ProtocolChoice::V2;
        session.connectDevice(o);
        QTRY_VERIFY_WITH_TIMEOUT(samples.size() > 0, 1800);
        QList<Unaccounted> views;
        for (const int cutMs : {2000, 4000, 6000}) {
            QTRY_VERIFY_WITH_TIMEOUT(clock.elapsed() > cutMs + 150, 8000);
            const LinkStats stats = session.stats();
            sim.readAllStandardError();
            ::kill(pid_t(sim.processId()), SIGUSR1);
            QString summary;
            QTRY_VERIFY_WITH_TIMEOUT((summary += QString::fromUtf8(sim.readAllStandardError()))
                                         .contains(u"seen host→device"_s),
                                     1000);
            QVERIFY2(clock.elapsed() < cutMs + 950, "the comparison left the cut");
            FaultCounts seen;
            seen.streamLost = figure(summary, u"seen device→host"_s, u"stream_lost"_s);
            seen.corrupted = figure(summary, u"seen device→host"_s, u"corrupted"_s);
            seen.streamCorrupted = figure(summary, u"seen device→host"_s, u"stream_corrupted"_s);
            seen.streamDuplicated = figure(summary, u"seen device→host"_s, u"stream_duplicated"_s);
            views.append(unaccounted(seen, stats));
            QCOMPARE(views.last(), views.first());
            if (cutMs == 6000) {
                QVERIFY2(seen.streamLost > 600, qPrintable(summary)); // the 4 s cut and more
                QVERIFY(seen.corrupted > 10 && seen.streamDuplicated > 10);
            }
        }
        QCOMPARE(session.state(), SessionState::Connected);
        session.disconnectDevice();
        sim.terminate();
        QVERIFY(sim.waitForFinished(3000));
        QCOMPARE(sim.exitCode(), 0);
        QVERIFY(QString::fromUtf8(sim.readAllStandardError()).contains(u"injected device→host"_s));
    }
#endif
};

QTEST_GUILESS_MAIN(TestSessionFaults)
#include "tst_sessionfaults.moc"
