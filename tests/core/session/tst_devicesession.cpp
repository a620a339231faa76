// DeviceSession driven directly on the test thread, against the in-process simulator ("sim")
// and against real pseudo-terminals (openpty + QSerialPort).
#include "link/seriallink.h"
#include "model/reference.h"
#include "model/stiffness.h"
#include "protocol/v2codec.h"
#include "session/devicesession.h"
#include "session/sessionwording.h"
#include "sim/simlink.h"
#include "sim/simulateddevice.h"
#include "sim/simulatorhost.h"
#include "simulatoroptions.h"
#include "telemetry/recordingreader.h"

#include <QSignalSpy>
#include <QSocketNotifier>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <fcntl.h>
#include <map>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

constexpr int kConnectTimeoutMs = 5000;
constexpr int kCommandWaitMs = 3000;

ConnectOptions simOptions(WireProtocol protocol, ProtocolChoice choice = ProtocolChoice::Auto,
                          const HandInput &hand = {})
{
    SimulatedDevice::Config config;
    config.protocol = protocol;
    config.hand = hand;
    return test::simulatorOptions(config, choice);
}

//! A failed outcome in words, for a test's failure message.
QString statusText(const Outcome &o)
{
    return SessionWording::commandFailure(o);
}

//! Parameters as a device holds them: each field rounded to float32.
DeviceParams asFloat(const DeviceParams &p)
{
    DeviceParams out;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        out.setField(i, double(float(p.field(i))));
    return out;
}

//! A session with everything it emits collected.
struct Harness
{
    DeviceSession session;
    QList<Sample> samples;
    // A std::map: a QHash of Outcome trips GCC 12 -O3 -Wmaybe-uninitialized (a false positive).
    std::map<quint64, Outcome> results;
    QList<QPair<SessionState, StateDetail>> states;
    QList<DeviceParams> params;
    QList<RecordingStatus> recording;
    LinkStats lastStats;
    quint64 nextId = 0;

    Harness()
    {
        QObject::connect(&session.samples(), &SamplePipeline::samplesReady,
                         [this](const SampleBatch &b) { samples.append(b); });
        QObject::connect(&session, &DeviceSession::stateChanged,
                         [this](SessionState s, const StateDetail &d) {
                             states.append({s, d});
                         });
        QObject::connect(&session.samples(), &SamplePipeline::deviceTuningChanged,
                         [this](const DeviceTuning &t) {
                             if (t.params)
                                 params.append(*t.params);
                         });
        QObject::connect(&session.samples(), &SamplePipeline::recordingChanged,
                         [this](const RecordingStatus &r) { recording.append(r); });
        QObject::connect(&session, &DeviceSession::statsUpdated,
                         [this](const LinkStats &s) { lastStats = s; });
    }
    //! Sends `request`; its outcome lands in `results` under `id`.
    void send(quint64 id, const Request &request)
    {
        session.request(request, [this, id](const Outcome &o) { results.insert_or_assign(id, o); });
    }
    bool sawState(SessionState s) const
    {
        return std::any_of(states.cbegin(), states.cend(),
                           [s](const auto &p) { return p.first == s; });
    }
    StateDetail detailOf(SessionState s) const
    {
        for (auto it = states.crbegin(); it != states.crend(); ++it) {
            if (it->first == s)
                return it->second;
        }
        return {};
    }
    qsizetype samplesAfter(double t) const
    {
        return std::count_if(samples.cbegin(), samples.cend(),
                             [t](const Sample &s) { return s.t_s > t; });
    }
    double lastT() const { return samples.isEmpty() ? -1.0 : samples.last().t_s; }
    ~Harness() { QObject::disconnect(&session, nullptr, nullptr, nullptr); }
};

//! The master side of a pseudo-terminal that the test plays the device on.
class PtyPeer
{
public:
    PtyPeer()
    {
        char name[256] = {};
        int slave = -1;
        if (::openpty(&m_master, &slave, name, nullptr, nullptr) == 0) {
            ::close(slave);
            ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
            m_path = QString::fromLocal8Bit(name);
            m_notifier = std::make_unique<QSocketNotifier>(m_master, QSocketNotifier::Read);
            QObject::connect(m_notifier.get(), &QSocketNotifier::activated, [this] {
                char buf[4096];
                const ssize_t n = ::read(m_master, buf, sizeof buf);
                if (n > 0)
                    m_received.append(buf, n);
            });
        }
    }
    ~PtyPeer()
    {
        m_notifier.reset();
        if (m_master >= 0)
            ::close(m_master);
    }
    bool isValid() const { return m_master >= 0; }
    QString path() const { return m_path; }
    QByteArray received() const { return m_received; }
    //! Baud rate the client side has set (a pty's two ends share one termios) [bit/s].
    speed_t baud() const
    {
        termios t{};
        return ::tcgetattr(m_master, &t) == 0 ? ::cfgetospeed(&t) : B0;
    }

private:
    int m_master = -1;
    QString m_path;
    QByteArray m_received;
    std::unique_ptr<QSocketNotifier> m_notifier;
};

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

class TestDeviceSession : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void detectsProtocol_data();
    void detectsProtocol();
    void v2SamplesAreComplete();
    void legacySamplesAreModelEstimated();
    void pushParamsReadsBack();
    void invalidParamsAreRefusedOnTheHost();
    void rejectionLeavesDeviceParamsUnchanged();
    void lostCommandIsRetried_data();
    void lostCommandIsRetried();
    void legacyCommandsAreUnsupported_data();
    void legacyCommandsAreUnsupported();
    void commandsWhenDisconnected();
    void feedbackReachesTheDevice();
    void feedbackWatchdog();
    void sampleListenersSeeEachSampleBeforeItsBatch();
    void garbageIsCountedAndStreamContinues();
    void seqGapsAreCounted();
    void statsReportRatesAndRtt();
    void recordingEventsOnParamAndHostChanges();
    void recordingWriteErrorKeepsSession();
    void severedLinkReconnects();
    void silentLinkIsLostAndReconnects();
    void detectionFailsOnSilentPty();
    void helloOnPtyHasNoLetterI();
    void autoDetectionListensAtLegacyRateThenAsksAtV2Rate();
    void detectsOverPty_data();
    void detectsOverPty();
    void openFailureNamesThePort();
    void theLinkIsTheCallers();
    void stalledPortKeepsWriteBufferBounded();
};

void TestDeviceSession::detectsProtocol_data()
{
    QTest::addColumn<int>("deviceProtocol");
    QTest::addColumn<int>("choice");
    QTest::newRow("auto finds v2") << int(WireProtocol::V2) << int(ProtocolChoice::Auto);
    QTest::newRow("auto finds legacy") << int(WireProtocol::Legacy) << int(ProtocolChoice::Auto);
    QTest::newRow("forced v2") << int(WireProtocol::V2) << int(ProtocolChoice::V2);
    QTest::newRow("forced legacy") << int(WireProtocol::Legacy) << int(ProtocolChoice::Legacy);
    // A forced protocol makes the built-in simulator speak it, whatever its config says: the
    // tuner's and hatpicctl's "--port sim --protocol legacy" leave the config at v2.
    QTest::newRow("forced legacy, simulator configured v2")
        << int(WireProtocol::V2) << int(ProtocolChoice::Legacy);
}

void TestDeviceSession::detectsProtocol()
{
    QFETCH(int, deviceProtocol);
    QFETCH(int, choice);
    Harness h;
    QSignalSpy info(&h.session, &DeviceSession::deviceInfoChanged);
    h.session.connectDevice(simOptions(WireProtocol(deviceProtocol), ProtocolChoice(choice)));
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    QCOMPARE(info.count(), 1);
    const DeviceInfo di = info.first().first().value<DeviceInfo>();
    if (ProtocolChoice(choice) == ProtocolChoice::Legacy)
        deviceProtocol = int(WireProtocol::Legacy);
    QCOMPARE(int(di.protocol), deviceProtocol);
    QVERIFY(di.simulated);
    QCOMPARE(di.port, QStringLiteral("sim"));
    if (WireProtocol(deviceProtocol) == WireProtocol::V2) {
        QCOMPARE(di.protocolVersion, quint8(2));
        QCOMPARE(di.deviceId, SimulatedDevice::Config().deviceId);
        QVERIFY(di.canSetParams());
        QTRY_VERIFY_WITH_TIMEOUT(!h.params.isEmpty(), kCommandWaitMs); // GET_PARAMS at connect
        QCOMPARE(h.params.first(), asFloat(DeviceParams()));
    } else {
        QCOMPARE(di.protocolVersion, quint8(0));
        QVERIFY(!di.canSetParams());
        QVERIFY(h.params.isEmpty());
    }
    // Opening → Detecting → Connected, in that order.
    QVERIFY(h.states.size() >= 3);
    QCOMPARE(h.states[0].first, SessionState::Opening);
    QCOMPARE(h.states[1].first, SessionState::Detecting);
    QCOMPARE(h.states.last().first, SessionState::Connected);
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() >= 3, kConnectTimeoutMs);
    h.session.disconnectDevice();
    QCOMPARE(h.session.state(), SessionState::Disconnected);
}

void TestDeviceSession::v2SamplesAreComplete()
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

void TestDeviceSession::legacySamplesAreModelEstimated()
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

void TestDeviceSession::pushParamsReadsBack()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2));
    QTRY_VERIFY_WITH_TIMEOUT(!h.params.isEmpty(), kConnectTimeoutMs);
    DeviceParams p;
    p.K_max = 0.6;
    p.K_min = 0.2;
    p.N = 0.12;
    h.send(7, request::Push{{p, std::nullopt}});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(7), kCommandWaitMs);
    const Outcome r = h.results.at(7);
    QVERIFY2(r.ok(), qPrintable(statusText(r)));
    QCOMPARE(std::get<outcome::Done>(r.result).readBack, outcome::ReadBack::Matches);
    QCOMPARE(h.params.last().K_max, double(0.6f));
    QCOMPARE(h.params.last().K_min, double(0.2f));
    QCOMPARE(h.params.last().N, double(0.12f));
    QCOMPARE(test::simLinkOf(h.session)->device()->params().K_max, double(0.6f));

    // ZERO makes the current angle θ0; the read-back shows it.
    h.send(8, request::Zero{});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(8), kCommandWaitMs);
    QVERIFY2(h.results.at(8).ok(), qPrintable(statusText(h.results.at(8))));
    QCOMPARE(h.params.last().theta0, test::simLinkOf(h.session)->device()->params().theta0);

    h.send(9, request::Save{});
    h.send(10, request::Stream{500});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(10), kCommandWaitMs);
    QVERIFY(h.results.at(9).ok());
    QVERIFY(h.results.at(10).ok());
    QTRY_COMPARE_WITH_TIMEOUT(test::simLinkOf(h.session)->device()->streamRate(), quint16(500),
                              kCommandWaitMs);
}

void TestDeviceSession::invalidParamsAreRefusedOnTheHost()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(!h.params.isEmpty(), kConnectTimeoutMs);
    DeviceParams p;
    p.K_min = 0.9; // > K_max
    p.Q_dz = 0.5;  // > N
    h.send(1, request::Push{{p, std::nullopt}});
    QTRY_VERIFY(h.results.contains(1));
    const Outcome r = h.results.at(1);
    const auto *invalid = std::get_if<outcome::Invalid>(&r.result);
    QVERIFY2(invalid, qPrintable(statusText(r)));
    const QString problems = invalid->problems.join(u"; "_s);
    QVERIFY2(problems.contains(u"K_min") && problems.contains(u"Q_dz"), qPrintable(problems));
    QCOMPARE(test::simLinkOf(h.session)->device()->params(), asFloat(DeviceParams()));
}

void TestDeviceSession::rejectionLeavesDeviceParamsUnchanged()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(!h.params.isEmpty(), kConnectTimeoutMs);
    DeviceParams good;
    good.K_max = 0.5;
    h.send(1, request::Push{{good, std::nullopt}});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(1), kCommandWaitMs);
    QVERIFY(h.results.at(1).ok());

    h.session.setValidateBeforeSending(false);
    DeviceParams bad = good;
    bad.K_min = 0.1;
    bad.K_max = 60; // above 50: the device names field 3
    h.send(2, request::Push{{bad, std::nullopt}});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(2), kCommandWaitMs);
    const Outcome r = h.results.at(2);
    const auto *refused = std::get_if<outcome::Refused>(&r.result);
    QVERIFY2(refused, qPrintable(statusText(r)));
    QCOMPARE(refused->status, v2::AckStatus::OutOfRange);
    QCOMPARE(refused->field, 3);
    QCOMPARE(refused->step, CommandKind::SetParams);
    QVERIFY(!refused->applied.params); // its first step: nothing was applied

    h.send(3, request::Read{});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(3), kCommandWaitMs);
    QCOMPARE(h.params.last().K_max, double(0.5f));
    QCOMPARE(h.params.last().K_min, double(float(DeviceParams().K_min)));
}

void TestDeviceSession::lostCommandIsRetried_data()
{
    QTest::addColumn<int>("dropped");
    QTest::addColumn<bool>("succeeds");
    QTest::newRow("one copy lost") << 1 << true;
    QTest::newRow("three copies lost") << 3 << true;
    QTest::newRow("all four copies lost") << 4 << false;
}

void TestDeviceSession::lostCommandIsRetried()
{
    QFETCH(int, dropped);
    QFETCH(bool, succeeds);
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(!h.params.isEmpty(), kConnectTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(!h.samples.isEmpty(), kConnectTimeoutMs); // connect sequence done
    const quint64 retriesBefore = h.session.stats().retries;
    test::simLinkOf(h.session)->dropHostFrames(dropped, quint8(v2::MessageType::SetParams));
    DeviceParams p;
    p.K_max = 0.7;
    h.send(1, request::Push{{p, std::nullopt}});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(1), kCommandWaitMs);
    const Outcome r = h.results.at(1);
    QCOMPARE(test::simLinkOf(h.session)->droppedHostFrames(), dropped);
    QCOMPARE(h.session.stats().retries - retriesBefore, quint64(std::min(dropped, 3)));
    if (succeeds) {
        QVERIFY2(r.ok(), qPrintable(statusText(r)));
        QCOMPARE(test::simLinkOf(h.session)->device()->params().K_max, double(0.7f));
    } else {
        const auto *timedOut = std::get_if<outcome::TimedOut>(&r.result);
        QVERIFY2(timedOut, qPrintable(statusText(r)));
        QCOMPARE(timedOut->step, CommandKind::SetParams);
        QCOMPARE(timedOut->attempts, CommandQueue::kCommandRetries + 1);
        QCOMPARE(timedOut->intervalMs, CommandQueue::kCommandTimeoutMs);
        QCOMPARE(test::simLinkOf(h.session)->device()->params().K_max,
                 double(float(DeviceParams().K_max)));
    }
}

void TestDeviceSession::legacyCommandsAreUnsupported_data()
{
    QTest::addColumn<QString>("command");
    QTest::newRow("push") << QStringLiteral("push");
    QTest::newRow("read") << QStringLiteral("read");
    QTest::newRow("zero") << QStringLiteral("zero");
    QTest::newRow("save") << QStringLiteral("save");
    QTest::newRow("stream") << QStringLiteral("stream");
}

void TestDeviceSession::legacyCommandsAreUnsupported()
{
    QFETCH(QString, command);
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::Legacy, ProtocolChoice::Legacy));
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    if (command == u"push")
        h.send(1, request::Push{{DeviceParams(), std::nullopt}});
    else if (command == u"read")
        h.send(1, request::Read{});
    else if (command == u"zero")
        h.send(1, request::Zero{});
    else if (command == u"save")
        h.send(1, request::Save{});
    else
        h.send(1, request::Stream{100});
    QTRY_VERIFY(h.results.contains(1));
    const Outcome refused = h.results.at(1);
    const auto *unsupported = std::get_if<outcome::Unsupported>(&refused.result);
    QVERIFY(unsupported);
    QCOMPARE(unsupported->why, command == u"stream" ? outcome::Unsupported::Why::FixedRate
                                                    : outcome::Unsupported::Why::NoParameters);
    // Host parameters still apply.
    HostParams host;
    host.v_max = 3;
    host.ref_deadzone = false;
    h.session.setHostParams(host);
    const qsizetype before = h.samples.size();
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > before, kConnectTimeoutMs);
    const Sample &s = h.samples.last();
    QCOMPARE(s.v_ref, referenceVelocity(host, DeviceParams(), s.theta));
}

void TestDeviceSession::commandsWhenDisconnected()
{
    Harness h;
    h.send(1, request::Read{});
    h.send(2, request::Push{{DeviceParams(), std::nullopt}});
    QVERIFY(std::holds_alternative<outcome::NotConnected>(h.results.at(1).result));
    QVERIFY(std::holds_alternative<outcome::NotConnected>(h.results.at(2).result));
}

void TestDeviceSession::feedbackReachesTheDevice()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(!h.samples.isEmpty(), kConnectTimeoutMs);
    h.session.setFeedback(0.1);
    QTRY_VERIFY_WITH_TIMEOUT(!h.samples.isEmpty() && qAbs(h.samples.last().tau_ext - 0.1) < 1e-6,
                             kCommandWaitMs);
    QCOMPARE(h.samples.last().flags & v2::kFlagFeedbackStale, 0);
}

void TestDeviceSession::feedbackWatchdog()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > 300, kConnectTimeoutMs);
    h.session.setFeedback(0.05);
    QTRY_VERIFY_WITH_TIMEOUT(qAbs(h.samples.last().tau_ext - 0.05) < 1e-6, kCommandWaitMs);
    // With the stream running the device never went stale.
    for (const Sample &s : std::as_const(h.samples))
        QCOMPARE(s.flags & v2::kFlagFeedbackStale, 0);

    h.session.setFeedbackPaused(true);
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.last().flags & v2::kFlagFeedbackStale, kCommandWaitMs);
    QCOMPARE(h.samples.last().tau_ext, 0.0); // a stale device drops τ_ext
    h.session.setFeedbackPaused(false);
    QTRY_VERIFY_WITH_TIMEOUT(!(h.samples.last().flags & v2::kFlagFeedbackStale), kCommandWaitMs);
}

void TestDeviceSession::sampleListenersSeeEachSampleBeforeItsBatch()
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

void TestDeviceSession::garbageIsCountedAndStreamContinues()
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

void TestDeviceSession::seqGapsAreCounted()
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

void TestDeviceSession::statsReportRatesAndRtt()
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

void TestDeviceSession::recordingEventsOnParamAndHostChanges()
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

void TestDeviceSession::recordingWriteErrorKeepsSession()
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

void TestDeviceSession::severedLinkReconnects()
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

void TestDeviceSession::silentLinkIsLostAndReconnects()
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

void TestDeviceSession::detectionFailsOnSilentPty()
{
    PtyPeer peer;
    QVERIFY(peer.isValid());
    Harness h;
    ConnectOptions o;
    o.port = peer.path();
    o.baud = 115200;
    h.session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Disconnected, kConnectTimeoutMs);
    QVERIFY(h.sawState(SessionState::Detecting));
    const StateDetail error = h.detailOf(SessionState::Disconnected);
    QCOMPARE(error.port, peer.path());
    QCOMPARE(error.baud, 115200);
    const auto *noAnswer = error.as<state::NoAnswer>();
    QVERIFY(noAnswer);
    QCOMPARE(noAnswer->listenBaud, 0); // the baud was given: no second rate
    QCOMPARE(noAnswer->legacyFrames, 0);
    QCOMPARE(noAnswer->legacyFramesNeeded, ProtocolDetector::kLegacyFramesNeeded);
    QCOMPARE(noAnswer->listenMs, ProtocolDetector::kListenMs);
    QCOMPARE(noAnswer->helloWaitMs, ProtocolDetector::kHelloWaitMs);
}

void TestDeviceSession::helloOnPtyHasNoLetterI()
{
    // The HELLO sent during detection must not contain 'i', whatever seq the session is at.
    PtyPeer peer;
    QVERIFY(peer.isValid());
    Harness h;
    ConnectOptions o;
    o.port = peer.path();
    for (int round = 0; round < 2; ++round) {
        h.session.connectDevice(o);
        QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Disconnected, kConnectTimeoutMs);
    }
    const QByteArray sent = peer.received();
    QVERIFY(!sent.isEmpty());
    QVERIFY(!sent.contains('i'));
    v2::FrameDecoder decoder(v2::Direction::FromHost);
    QList<v2::Frame> frames;
    decoder.feed(sent, frames);
    // Each detection sends its HELLO kHelloSends times (led by a delimiter, issue 10 #6).
    QCOMPARE(frames.size(), 2 * ProtocolDetector::kHelloSends);
    for (const v2::Frame &f : frames)
        QVERIFY(std::holds_alternative<v2::Hello>(f.message));
}

void TestDeviceSession::autoDetectionListensAtLegacyRateThenAsksAtV2Rate()
{
    // With no baud given, a published-firmware device (115200) and a v2 device (921600) must
    // both be found: listen at 115200, then switch to 921600 before sending HELLO.
    PtyPeer peer;
    QVERIFY(peer.isValid());
    Harness h;
    QList<QPair<StateDetail, speed_t>> seen;
    QObject::connect(&h.session, &DeviceSession::stateChanged,
                     [&](SessionState s, const StateDetail &detail) {
                         if (s == SessionState::Detecting)
                             seen.append({detail, peer.baud()});
                     });
    ConnectOptions o;
    o.port = peer.path();
    h.session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Disconnected, kConnectTimeoutMs);
    QCOMPARE(seen.size(), 2);
    QVERIFY(seen[0].first.is<state::Listening>());
    QCOMPARE(seen[0].second, speed_t(B115200));
    QVERIFY(seen[1].first.is<state::SendingHello>());
    QCOMPARE(seen[1].second, speed_t(B921600));
    const StateDetail failure = h.detailOf(SessionState::Disconnected);
    QVERIFY(failure.is<state::NoAnswer>());
    QCOMPARE(failure.as<state::NoAnswer>()->listenBaud, 115200);
    QCOMPARE(failure.baud, 921600);
}

void TestDeviceSession::detectsOverPty_data()
{
    QTest::addColumn<int>("protocol");
    QTest::newRow("v2") << int(WireProtocol::V2);
    QTest::newRow("legacy") << int(WireProtocol::Legacy);
}

void TestDeviceSession::detectsOverPty()
{
    QFETCH(int, protocol);
    SimulatedDevice::Config config;
    config.protocol = WireProtocol(protocol);
    SimulatorHost host(config);
    const QString error = host.start();
    QVERIFY2(error.isEmpty(), qPrintable(error));
    Harness h;
    ConnectOptions o;
    o.port = host.slavePath();
    o.baud = config.protocol == WireProtocol::Legacy ? 115200 : 921600;
    h.session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    QCOMPARE(int(h.session.deviceInfo().protocol), protocol);
    QVERIFY(!h.session.deviceInfo().simulated);
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() >= 3, kConnectTimeoutMs);
    if (config.protocol == WireProtocol::V2) {
        h.session.setFeedback(0.02);
        QTRY_VERIFY_WITH_TIMEOUT(qAbs(h.samples.last().tau_ext - 0.02) < 1e-6, kCommandWaitMs);
    }
    h.session.disconnectDevice();
}

void TestDeviceSession::openFailureNamesThePort()
{
    Harness h;
    ConnectOptions o;
    o.port = QStringLiteral("/dev/hatpic-does-not-exist");
    h.session.connectDevice(o);
    QCOMPARE(h.session.state(), SessionState::Disconnected);
    const StateDetail error = h.detailOf(SessionState::Disconnected);
    QCOMPARE(error.port, o.port);
    QVERIFY(error.is<state::OpenFailed>());
    QVERIFY(!error.as<state::OpenFailed>()->error.isEmpty());
    QVERIFY(h.sawState(SessionState::Opening));
}

// The session reads nothing into the port's name: "sim" without a link is a serial port that
// does not exist, and whether the device is simulated is what its link says.
void TestDeviceSession::theLinkIsTheCallers()
{
    {
        Harness h;
        ConnectOptions o;
        o.port = QString::fromUtf16(kSimPortName);
        h.session.connectDevice(o);
        QCOMPARE(h.session.state(), SessionState::Disconnected);
        const StateDetail error = h.detailOf(SessionState::Disconnected);
        QVERIFY(error.is<state::OpenFailed>());
        QVERIFY(!error.simulated);
    }
    // A link of the caller's own that says it is hardware: a simulator's bytes, not its name.
    struct Hardware : LinkSource
    {
        ByteLink *makeLink(qint32, QObject *parent) override { return new SimLink({}, parent); }
        bool simulated() const override { return false; }
    };
    for (const bool simulated : {false, true}) {
        Harness h;
        ConnectOptions o = test::simulatorOptions();
        if (!simulated)
            o.link = std::make_shared<Hardware>();
        o.port = u"the caller's link"_s;
        h.session.connectDevice(o);
        QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
        QCOMPARE(h.session.deviceInfo().simulated, simulated);
        QCOMPARE(h.detailOf(SessionState::Connected).simulated, simulated);
        QCOMPARE(h.detailOf(SessionState::Connected).port, o.port);
        QTRY_VERIFY_WITH_TIMEOUT(!h.samples.isEmpty(), kConnectTimeoutMs);
    }
}

void TestDeviceSession::stalledPortKeepsWriteBufferBounded()
{
    // A port that takes nothing (here: the peer never reads and no event loop runs to hand
    // QSerialPort's buffer to the kernel) must not make the host's buffer grow.
    PtyPeer peer;
    QVERIFY(peer.isValid());
    SerialLink link(peer.path(), 921600);
    QVERIFY2(link.open(), qPrintable(link.errorString()));
    const QByteArray frame = v2::encodeFrame(0, v2::SetFeedback{0.1f});
    const int writes = 100'000;
    for (int i = 0; i < writes; ++i)
        link.write(frame);
    QVERIFY2(link.bytesToWrite() <= SerialLink::kMaxPendingWriteBytes,
             qPrintable(QString::number(link.bytesToWrite())));
    QVERIFY(link.droppedWrites() > 0);
}

QTEST_GUILESS_MAIN(TestDeviceSession)
#include "tst_devicesession.moc"
