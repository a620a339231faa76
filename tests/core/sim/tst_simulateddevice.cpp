// SimulatedDevice offline (no pty): v2 commands and replies, telemetry, watchdog, link
// throttling, the ideal model, the servo plant, and the legacy firmware emulation.
#include "model/admittance.h"
#include "model/stiffness.h"
#include "profile/profile.h"
#include "session/sessiontypes.h"
#include "sim/simulateddevice.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

using namespace hatpic;
using namespace Qt::StringLiterals;

Q_DECLARE_METATYPE(hatpic::v2::AckStatus)

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

DeviceParams f32Params(DeviceParams p)
{
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        p.setField(i, double(float(p.field(i))));
    return p;
}

HandInput handOf(const QString &spec)
{
    const std::optional<HandInput> h = HandInput::parse(spec);
    return h.value_or(HandInput{});
}

// Drives a device like a host would: frames in, decoded frames out.
class Host
{
public:
    explicit Host(const SimulatedDevice::Config &config) : device(config) {}

    void send(quint8 seq, const v2::Message &message)
    {
        device.receive(v2::encodeFrame(seq, message));
    }
    void sendRaw(const QByteArray &bytes) { device.receive(bytes); }

    //! Takes what the link carried so far; decodes it and keeps the raw bytes.
    QList<v2::Frame> take()
    {
        const QByteArray bytes = device.takeOutput();
        raw += bytes;
        QList<v2::Frame> frames;
        decoder.feed(bytes, frames);
        return frames;
    }
    //! The first frame of type T in what the link carried by now (advances a little if needed).
    template<typename T> std::optional<v2::Frame> reply()
    {
        for (int i = 0; i < 50; ++i) {
            for (const v2::Frame &f : take()) {
                if (std::holds_alternative<T>(f.message))
                    return f;
            }
            device.advance(1e-3);
        }
        return std::nullopt;
    }
    std::optional<v2::Ack> ack()
    {
        const std::optional<v2::Frame> f = reply<v2::Ack>();
        if (!f)
            return std::nullopt;
        return std::get<v2::Ack>(f->message);
    }
    DeviceParams params()
    {
        send(200, v2::GetParams{});
        const std::optional<v2::Frame> f = reply<v2::Params>();
        return f ? std::get<v2::Params>(f->message).params : DeviceParams{};
    }

    SimulatedDevice device;
    v2::FrameDecoder decoder{v2::Direction::FromDevice};
    QByteArray raw;
};

SimulatedDevice::Config fastConfig()
{
    SimulatedDevice::Config c;
    c.throttle = false; // replies are available at once
    return c;
}

QList<v2::Telemetry> telemetryOf(const QList<v2::Frame> &frames, QList<quint8> *seqs = nullptr)
{
    QList<v2::Telemetry> out;
    for (const v2::Frame &f : frames) {
        if (const auto *t = std::get_if<v2::Telemetry>(&f.message)) {
            out.append(*t);
            if (seqs)
                seqs->append(f.seq);
        }
    }
    return out;
}

} // namespace

class TestSimulatedDevice : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void hello_data();
    void hello();
    void getParamsGivesPowerUpBlock();
    void setParams_data();
    void setParams();
    void setParamsTakesEffectNextCycle();
    void setStreamClamps_data();
    void setStreamClamps();
    void helloStopsStreaming();
    void telemetryConsistent();
    void telemetryClockWraps();
    void watchdog();
    void watchdogHoldsNoLongerThanItsTimeAtLowRates();
    void feedbackAppliedWhateverSeq();
    void zeroAndRepeatedSeq();
    void repeatedCommandAnsweredNotApplied();
    void refusedFrames_data();
    void refusedFrames();
    void pingPong();
    void saveParamsPersistsAndReloads();
    void saveParamsWithoutStateFile();
    void saveParamsStorageError();
    void invalidStateFileIgnored();
    void throttling_data();
    void throttling();
    void fullQueueDropsTelemetryAsSeqGap();
    void idealMatchesModel_data();
    void idealMatchesModel();
    void cycleSample_data();
    void cycleSample();
    void setHandRestartsTimeBase();
    void plantSettlesAtSpringEquilibrium_data();
    void plantSettlesAtSpringEquilibrium();
    void plantMeasurementsQuantised();
    void noiseIsSeeded();
    void legacyBootTextAndFrameRate();
    void legacyPositionWraps();
    void legacyFeedback();
    void legacyBusyWaitHazard();
    void legacyIgnoresV2();
};

void TestSimulatedDevice::hello_data()
{
    QTest::addColumn<double>("rate");
    QTest::addColumn<int>("maxStream");
    QTest::newRow("1 kHz control") << 1000.0 << 1000;
    QTest::newRow("500 Hz control") << 500.0 << 500;
    QTest::newRow("2.5 kHz control") << 2500.0 << 2500;
}

void TestSimulatedDevice::hello()
{
    QFETCH(double, rate);
    QFETCH(int, maxStream);
    SimulatedDevice::Config c = fastConfig();
    c.controlRateHz = rate;
    c.deviceId = 0x12345678;
    c.tauLimit = 0.5;
    Host host(c);
    host.send(0, v2::Hello{});
    const std::optional<v2::Frame> f = host.reply<v2::HelloReply>();
    QVERIFY(f);
    const auto r = std::get<v2::HelloReply>(f->message);
    QCOMPARE(r.protocolVersion, quint8(2));
    QCOMPARE(int(r.maxStreamHz), maxStream);
    QCOMPARE(r.deviceId, 0x12345678u);
    QCOMPARE(r.tauLimit, 0.5f);
    QCOMPARE(r.firmware, u"hatpic-sim 0.1"_s);
    QCOMPARE(host.device.streamRate(), quint16(0)); // off after power-up
}

void TestSimulatedDevice::getParamsGivesPowerUpBlock()
{
    SimulatedDevice::Config c = fastConfig();
    c.params.K_max = 0.9;
    c.params.theta0 = 0.1;
    Host host(c);
    QCOMPARE(host.params(), f32Params(c.params));
    QCOMPARE(host.device.params(), f32Params(c.params));
}

void TestSimulatedDevice::setParams_data()
{
    QTest::addColumn<DeviceParams>("block");
    QTest::addColumn<int>("field"); // -1 = accepted
    const DeviceParams ok;
    auto with = [&](int index, double value) {
        DeviceParams p = ok;
        p.setField(index, value);
        return p;
    };
    QTest::newRow("defaults accepted") << ok << -1;
    DeviceParams stiff = ok;
    stiff.K_max = 2.0;
    stiff.K_min = 1.0;
    stiff.theta0 = -0.3;
    QTest::newRow("stiffer block accepted") << stiff << -1;
    QTest::newRow("D_adm too small") << with(0, 1e-7) << 0;
    QTest::newRow("M_adm zero") << with(1, 0.0) << 1;
    QTest::newRow("K_min above K_max") << with(2, 0.5) << 2;
    QTest::newRow("K_max above 50") << with(3, 60.0) << 3;
    QTest::newRow("N zero") << with(4, 0.0) << 4;
    QTest::newRow("N is NaN") << with(4, std::nan("")) << 4;
    QTest::newRow("Q_dz equal to N") << with(5, ok.N) << 5;
    QTest::newRow("theta0 above pi") << with(6, 3.5) << 6;
    QTest::newRow("theta0 = pi, above pi as f32") << with(6, std::numbers::pi) << 6;
    QTest::newRow("theta0 infinite") << with(6, INFINITY) << 6;
    DeviceParams two = with(1, -1.0);
    two.theta0 = 9;
    QTest::newRow("two violations name the first") << two << 1;
}

void TestSimulatedDevice::setParams()
{
    QFETCH(DeviceParams, block);
    QFETCH(int, field);
    SimulatedDevice::Config c = fastConfig();
    c.params.K_min = 0.2; // differs from every row's block, so a change would show
    Host host(c);
    const DeviceParams before = host.params();
    host.send(17, v2::SetParams{block});
    const std::optional<v2::Ack> ack = host.ack();
    QVERIFY(ack);
    QCOMPARE(ack->ackedSeq, quint8(17));
    if (field < 0) {
        QCOMPARE(ack->status, v2::AckStatus::Ok);
        QCOMPARE(ack->field, v2::kNoField);
        QCOMPARE(host.params(), f32Params(block));
    } else {
        QCOMPARE(ack->status, v2::AckStatus::OutOfRange);
        QCOMPARE(int(ack->field), field);
        QCOMPARE(host.params(), before); // all or nothing
    }
}

void TestSimulatedDevice::setParamsTakesEffectNextCycle()
{
    SimulatedDevice::Config c = fastConfig();
    c.ideal = true;
    c.hand = handOf(u"const:0.03"_s);
    Host host(c);
    for (int i = 0; i < 100; ++i)
        host.device.step();
    DeviceParams next = host.device.params();
    next.K_max = 1.5;
    next.K_min = 0.5;
    next.Q_dz = 0.0;
    next = f32Params(next);
    const SimulatedDevice::Cycle before = host.device.step();
    QCOMPARE(before.tau_rec, recenteringTorque(host.device.params(), before.theta));
    host.send(3, v2::SetParams{next});
    QCOMPARE(host.ack()->status, v2::AckStatus::Ok);
    // Read back at once, in force from the next cycle on, never mixed.
    QCOMPARE(host.device.params(), next);
    const SimulatedDevice::Cycle after = host.device.step();
    QCOMPARE(after.tau_rec, recenteringTorque(next, after.theta));
    QVERIFY(after.tau_rec != recenteringTorque(DeviceParams{}, after.theta));
}

void TestSimulatedDevice::setStreamClamps_data()
{
    QTest::addColumn<int>("baud");
    QTest::addColumn<bool>("throttle");
    QTest::addColumn<double>("rate");
    QTest::addColumn<int>("request");
    QTest::addColumn<int>("expected");
    // 43 wire bytes per frame (TELEMETRY with τ_fx, τ_pc and R), 10 bits per byte.
    QTest::newRow("115200 cannot carry 1 kHz") << 115200 << true << 1000.0 << 1000 << 267;
    QTest::newRow("115200 carries 200 Hz") << 115200 << true << 1000.0 << 200 << 200;
    QTest::newRow("921600 carries 1 kHz") << 921600 << true << 1000.0 << 1000 << 1000;
    QTest::newRow("921600 above max_stream_hz") << 921600 << true << 1000.0 << 5000 << 1000;
    QTest::newRow("921600 at 5 kHz control") << 921600 << true << 5000.0 << 5000 << 2143;
    QTest::newRow("no throttle: only max_stream_hz") << 115200 << false << 1000.0 << 1000 << 1000;
    QTest::newRow("zero stops") << 921600 << true << 1000.0 << 0 << 0;
    QTest::newRow("odd rate 333 Hz") << 921600 << true << 1000.0 << 333 << 333;
}

void TestSimulatedDevice::setStreamClamps()
{
    QFETCH(int, baud);
    QFETCH(bool, throttle);
    QFETCH(double, rate);
    QFETCH(int, request);
    QFETCH(int, expected);
    SimulatedDevice::Config c;
    c.baud = baud;
    c.throttle = throttle;
    c.controlRateHz = rate;
    c.ideal = true; // cheap; the link is what matters here
    Host host(c);
    host.send(1, v2::SetStream{quint16(request)});
    const std::optional<v2::Ack> ack = host.ack();
    QVERIFY(ack);
    QCOMPARE(ack->status, v2::AckStatus::Ok); // clamping is not an error
    QCOMPARE(int(host.device.streamRate()), expected);
    host.take();
    // Frames produced over the next two seconds: the clamped rate, ±1.
    QList<v2::Telemetry> frames;
    for (int i = 0; i < 200; ++i) {
        host.device.advance(0.01);
        frames += telemetryOf(host.take());
    }
    QVERIFY2(std::abs(frames.size() - 2 * expected) <= 2,
             qPrintable(u"%1 frames in 2 s"_s.arg(frames.size())));
}

void TestSimulatedDevice::helloStopsStreaming()
{
    Host host(fastConfig());
    host.send(1, v2::SetStream{100});
    host.device.advance(0.1);
    QVERIFY(!telemetryOf(host.take()).isEmpty());
    host.send(2, v2::Hello{});
    QVERIFY(host.reply<v2::HelloReply>());
    host.take();
    host.device.advance(0.1);
    QVERIFY(telemetryOf(host.take()).isEmpty());
    QCOMPARE(host.device.streamRate(), quint16(0));
}

void TestSimulatedDevice::telemetryConsistent()
{
    // Real plant; a hand that sweeps through dead zone, notch and outer band; feedback that
    // sometimes saturates and sometimes stops (stale).
    SimulatedDevice::Config c = fastConfig();
    c.hand = handOf(u"sine:0.08:1"_s);
    c.noise = 0.002;
    Host host(c);
    host.send(1, v2::SetStream{1000});
    QVERIFY(host.ack());
    const DeviceParams p = host.device.params();
    QList<v2::Telemetry> frames;
    QList<quint8> seqs;
    for (int ms = 0; ms < 3000; ++ms) {
        if (ms < 1000 && ms % 50 == 0)
            host.send(quint8(ms), v2::SetFeedback{(ms / 50) % 4 == 0 ? 0.5f : -0.05f});
        host.device.advance(1e-3);
        frames += telemetryOf(host.take(), &seqs);
    }
    QCOMPARE(frames.size(), 3000);
    int dead = 0, notch = 0, outer = 0, saturated = 0, stale = 0;
    for (int i = 0; i < frames.size(); ++i) {
        const v2::Telemetry &t = frames.at(i);
        const double theta = t.theta;
        const auto where = qPrintable(u"frame %1"_s.arg(i));
        // tau_rec is exactly what the model gives for that very theta and params.
        QVERIFY2(t.tau_rec == float(recenteringTorque(p, theta)), where);
        const StiffnessZone zone = stiffnessZone(p, theta);
        QCOMPARE(bool(t.flags & v2::kFlagDeadZone), zone == StiffnessZone::DeadZone);
        QCOMPARE(bool(t.flags & v2::kFlagNotch), zone == StiffnessZone::Notch);
        const double sum = double(t.tau_rec) + double(t.tau_ext);
        if (std::abs(std::abs(sum) - 0.44) > 1e-6)
            QVERIFY2(bool(t.flags & v2::kFlagSaturated) == (std::abs(sum) > 0.44), where);
        if (t.flags & v2::kFlagFeedbackStale)
            QCOMPARE(t.tau_ext, 0.0f);
        QCOMPARE(t.flags & 0xF0, 0);
        if (i > 0) {
            QCOMPARE(quint8(seqs.at(i) - seqs.at(i - 1)), quint8(1));
            QCOMPARE(t.t_us - frames.at(i - 1).t_us, 1000u);
        }
        dead += zone == StiffnessZone::DeadZone;
        notch += zone == StiffnessZone::Notch;
        outer += zone == StiffnessZone::Outer;
        saturated += bool(t.flags & v2::kFlagSaturated);
        stale += bool(t.flags & v2::kFlagFeedbackStale);
    }
    // The run must actually have covered every case it checks.
    QVERIFY(dead > 0);
    QVERIFY(notch > 0);
    QVERIFY(outer > 0);
    QVERIFY(saturated > 0);
    QVERIFY(stale > 0);
}

void TestSimulatedDevice::telemetryClockWraps()
{
    SimulatedDevice::Config c = fastConfig();
    c.ideal = true;
    c.controlRateHz = 10; // 2^32 µs is ~4295 s: 42950 cycles
    Host host(c);
    host.send(1, v2::SetStream{10});
    QVERIFY(host.ack());
    quint32 previous = 0;
    bool wrapped = false;
    quint64 n = 0;
    for (int i = 0; i < 44000; ++i) {
        host.device.advance(0.1);
        for (const v2::Telemetry &t : telemetryOf(host.take())) {
            QCOMPARE(t.t_us, quint32((n * 100000ull) & 0xFFFFFFFFull));
            if (n > 0 && t.t_us < previous)
                wrapped = true;
            previous = t.t_us;
            ++n;
        }
    }
    QVERIFY(wrapped);
}

void TestSimulatedDevice::watchdog()
{
    SimulatedDevice::Config c = fastConfig();
    c.ideal = true;
    Host host(c);
    // Power-up: the watchdog runs from t = 0, so the flag rises at 200 ms.
    SimulatedDevice::Cycle cycle;
    for (int i = 0; i < 200; ++i) {
        cycle = host.device.step();
        QVERIFY2(!(cycle.flags & v2::kFlagFeedbackStale), qPrintable(QString::number(i)));
    }
    cycle = host.device.step(); // t = 200 ms
    QVERIFY(cycle.flags & v2::kFlagFeedbackStale);
    QVERIFY(host.device.feedbackStale());

    host.send(9, v2::SetFeedback{0.1f}); // arrives at t = 201 ms
    cycle = host.device.step();
    QVERIFY(!(cycle.flags & v2::kFlagFeedbackStale));
    QCOMPARE(cycle.tau_ext, double(0.1f));
    for (int i = 0; i < 198; ++i)
        cycle = host.device.step();
    QCOMPARE(cycle.tau_ext, double(0.1f)); // t = 399 ms: 198 ms after
    QVERIFY(!(cycle.flags & v2::kFlagFeedbackStale));
    cycle = host.device.step(); // t = 400 ms: 199 ms after
    QVERIFY(!(cycle.flags & v2::kFlagFeedbackStale));
    cycle = host.device.step(); // t = 401 ms: 200 ms without feedback
    QVERIFY(cycle.flags & v2::kFlagFeedbackStale);
    QCOMPARE(cycle.tau_ext, 0.0);

    // A non-finite value is not applied and does not feed the watchdog.
    host.send(10, v2::SetFeedback{std::numeric_limits<float>::quiet_NaN()});
    cycle = host.device.step();
    QVERIFY(cycle.flags & v2::kFlagFeedbackStale);
    QCOMPARE(cycle.tau_ext, 0.0);
}

void TestSimulatedDevice::watchdogHoldsNoLongerThanItsTimeAtLowRates()
{
    // At 37 Hz a period is 27 ms. A SET_FEEDBACK arriving just before a cycle's interval ends
    // is rendered from that cycle's start on: its 200 ms run from there, not from its arrival
    // (issue 27: 8 cycles, 216 ms).
    SimulatedDevice::Config c = fastConfig();
    c.ideal = true;
    c.controlRateHz = 37;
    Host host(c);
    const double period = 1.0 / c.controlRateHz;
    for (int i = 0; i < 10; ++i)
        host.device.step();
    host.send(1, v2::SetFeedback{0.1f});
    QVERIFY(host.device.step().tau_ext == double(0.1f)); // fresh feedback for the clock to run
    for (int i = 0; i < 10; ++i)
        host.device.step();
    host.device.advance(period * 0.99); // the next cycle's interval is nearly over
    host.send(2, v2::SetFeedback{0.2f});
    double first = -1;
    double end = -1;
    for (int i = 0; i < 20; ++i) {
        const SimulatedDevice::Cycle cycle = host.device.step();
        if (cycle.tau_ext == double(0.2f)) {
            if (first < 0)
                first = cycle.t;
            end = cycle.t + period; // in force until the next cycle
        }
    }
    QVERIFY(first >= 0);
    const double held = end - first;
    QVERIFY2(held <= 0.200 + 1e-9, qPrintable(u"held %1 ms"_s.arg(held * 1e3)));
    QVERIFY2(held > 0.200 - period, qPrintable(u"held %1 ms"_s.arg(held * 1e3)));
}

void TestSimulatedDevice::feedbackAppliedWhateverSeq()
{
    SimulatedDevice::Config c = fastConfig();
    c.ideal = true;
    Host host(c);
    host.send(5, v2::SetFeedback{0.02f});
    QCOMPARE(host.device.step().tau_ext, double(0.02f));
    host.send(5, v2::SetFeedback{-0.03f}); // same seq: still applied
    QCOMPARE(host.device.step().tau_ext, double(-0.03f));
    host.send(5, v2::SetFeedback{-0.03f}); // and no reply to feedback
    host.device.advance(0.01);
    QVERIFY(host.take().isEmpty());
}

void TestSimulatedDevice::zeroAndRepeatedSeq()
{
    SimulatedDevice::Config c = fastConfig();
    c.hand = handOf(u"const:0.03"_s);
    Host host(c);
    for (int i = 0; i < 500; ++i)
        host.device.step();
    const SimulatedDevice::Cycle at = host.device.step();
    QVERIFY(at.theta > 0.05); // the hand has moved the knob
    host.send(5, v2::Zero{});
    std::optional<v2::Ack> ack = host.ack();
    QVERIFY(ack);
    QCOMPARE(ack->status, v2::AckStatus::Ok);
    // (Read through the API: a GET_PARAMS would become the last command remembered.)
    const double theta0 = host.device.params().theta0;
    QCOMPARE(theta0, double(float(at.theta)));

    // The knob keeps going (the spring now centres at theta0); a retry of ZERO seq 5 must not
    // move theta0 again, a new ZERO must.
    for (int i = 0; i < 300; ++i)
        host.device.step();
    host.take();
    host.send(5, v2::Zero{});
    ack = host.ack();
    QVERIFY(ack);
    QCOMPARE(ack->status, v2::AckStatus::Ok);
    QCOMPARE(host.device.params().theta0, theta0);
    host.send(6, v2::Zero{});
    QCOMPARE(host.ack()->status, v2::AckStatus::Ok);
    QVERIFY(host.device.params().theta0 > theta0 + 0.01);
}

void TestSimulatedDevice::repeatedCommandAnsweredNotApplied()
{
    Host host(fastConfig());
    DeviceParams first;
    first.K_max = 0.8;
    DeviceParams second;
    second.K_max = 1.6;
    host.send(9, v2::SetParams{first});
    host.device.advance(0.001);
    const QByteArray firstReply = host.device.takeOutput();
    QVERIFY(!firstReply.isEmpty());
    // Same type and seq (a host retry): the same reply bytes, nothing applied.
    host.send(9, v2::SetParams{second});
    host.device.advance(0.001);
    QCOMPARE(host.device.takeOutput(), firstReply);
    QCOMPARE(host.device.params(), f32Params(first));
    // Same seq but another type is a new command.
    host.send(9, v2::SetStream{10});
    QCOMPARE(host.ack()->ackedSeq, quint8(9));
    QCOMPARE(host.device.streamRate(), quint16(10));
    // Then the same SET_PARAMS seq again is new too (only the last command is remembered).
    host.send(9, v2::SetParams{second});
    QCOMPARE(host.ack()->status, v2::AckStatus::Ok);
    QCOMPARE(host.device.params(), f32Params(second));
}

void TestSimulatedDevice::refusedFrames_data()
{
    QTest::addColumn<int>("type");
    QTest::addColumn<QByteArray>("payload");
    QTest::addColumn<v2::AckStatus>("status");
    QTest::newRow("unknown type 0x42") << 0x42 << QByteArray() << v2::AckStatus::UnknownType;
    QTest::newRow("device type TELEMETRY sent to device")
        << 0x90 << QByteArray(25, '\1') << v2::AckStatus::UnknownType;
    QTest::newRow("HELLO with a payload")
        << 0x01 << QByteArray(1, '\0') << v2::AckStatus::BadLength;
    QTest::newRow("SET_PARAMS one byte short")
        << 0x03 << QByteArray(27, '\0') << v2::AckStatus::BadLength;
    QTest::newRow("SET_STREAM one byte")
        << 0x04 << QByteArray(1, '\x10') << v2::AckStatus::BadLength;
    QTest::newRow("PING two bytes") << 0x07 << QByteArray(2, '\x10') << v2::AckStatus::BadLength;
}

void TestSimulatedDevice::refusedFrames()
{
    QFETCH(int, type);
    QFETCH(QByteArray, payload);
    QFETCH(v2::AckStatus, status);
    Host host(fastConfig());
    const DeviceParams before = host.device.params();
    host.sendRaw(v2::encodePacket(quint8(type), 77, payload));
    const std::optional<v2::Ack> ack = host.ack();
    QVERIFY(ack);
    QCOMPARE(ack->ackedSeq, quint8(77));
    QCOMPARE(ack->status, status);
    QCOMPARE(ack->field, v2::kNoField);
    QCOMPARE(host.device.params(), before);
    QCOMPARE(host.device.streamRate(), quint16(0));
}

void TestSimulatedDevice::pingPong()
{
    Host host(fastConfig());
    host.send(4, v2::Ping{0xDEADBEEF});
    const std::optional<v2::Frame> f = host.reply<v2::Pong>();
    QVERIFY(f);
    QCOMPARE(std::get<v2::Pong>(f->message).token, 0xDEADBEEFu);
}

void TestSimulatedDevice::saveParamsPersistsAndReloads()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"state.json"_s);
    SimulatedDevice::Config c = fastConfig();
    c.stateFile = path;
    DeviceParams saved;
    saved.D_adm = 3e-4;
    saved.K_max = 1.2;
    saved.theta0 = -0.25;
    {
        Host host(c);
        QCOMPARE(host.params(), f32Params(DeviceParams{})); // no file yet: the defaults
        host.send(1, v2::SetParams{saved});
        QCOMPARE(host.ack()->status, v2::AckStatus::Ok);
        QVERIFY(!QFile::exists(path)); // only SAVE_PARAMS writes
        host.send(2, v2::SaveParams{});
        QCOMPARE(host.ack()->status, v2::AckStatus::Ok);
    }
    const ProfileReadResult read = readProfile(path);
    QVERIFY2(read.ok(), qPrintable(read.errors.join(u"; "_s)));
    // The file holds each float's shortest decimal (1.2, not 1.2000000476837158).
    QCOMPARE(read.profile->device, tidyDeviceParams(f32Params(saved)));
    QCOMPARE(read.profile->device.K_max, 1.2);
    // Power-up again: the saved block is restored and the device starts at its theta0.
    Host again(c);
    QVERIFY(again.device.stateWarning().isEmpty());
    QCOMPARE(again.params(), f32Params(saved));
    const double ticks = std::round(double(float(saved.theta0)) * 4096 / kTwoPi);
    QCOMPARE(again.device.step().theta, double(float(ticks * kTwoPi / 4096.0)));
}

void TestSimulatedDevice::saveParamsWithoutStateFile()
{
    Host host(fastConfig());
    host.send(1, v2::SaveParams{});
    QCOMPARE(host.ack()->status, v2::AckStatus::Ok); // kept in the process's "flash"
}

void TestSimulatedDevice::saveParamsStorageError()
{
    QTemporaryDir dir;
    SimulatedDevice::Config c = fastConfig();
    c.stateFile = dir.filePath(u"missing-dir/state.json"_s);
    Host host(c);
    // Known at start…
    QCOMPARE(host.device.saveWarning(), u"SAVE_PARAMS cannot write state file " + c.stateFile +
                                            u": its folder " + dir.filePath(u"missing-dir"_s) +
                                            u" does not exist.");
    // …and said with the system's words when it happens: the LOG first, then the ACK.
    host.send(1, v2::SaveParams{});
    host.device.advance(1e-3);
    const QList<v2::Frame> frames = host.take();
    QCOMPARE(frames.size(), 2);
    const auto *log = std::get_if<v2::Log>(&frames.at(0).message);
    QVERIFY(log);
    QCOMPARE(v2::toQString(log->text), u"SAVE_PARAMS failed: cannot write profile \""_s +
                                           c.stateFile + u"\": No such file or directory"_s);
    const auto *ack = std::get_if<v2::Ack>(&frames.at(1).message);
    QVERIFY(ack);
    QCOMPARE(ack->status, v2::AckStatus::StorageError);
}

void TestSimulatedDevice::invalidStateFileIgnored()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"state.json"_s);
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{ this is not a profile");
    file.close();
    SimulatedDevice::Config c = fastConfig();
    c.stateFile = path;
    c.params.K_max = 0.7;
    Host host(c);
    QVERIFY(host.device.stateWarning().contains(path));
    QCOMPARE(host.params(), f32Params(c.params));
}

void TestSimulatedDevice::throttling_data()
{
    QTest::addColumn<int>("baud");
    QTest::newRow("115200") << 115200;
    QTest::newRow("921600") << 921600;
    QTest::newRow("57600") << 57600;
}

void TestSimulatedDevice::throttling()
{
    QFETCH(int, baud);
    SimulatedDevice::Config c;
    c.baud = baud;
    c.ideal = true;
    c.controlRateHz = 5000; // so that the stream alone can fill even the fastest link
    Host host(c);
    QCOMPARE(host.device.baud(), baud);
    QCOMPARE(int(host.device.linkLimitedRate()),
             baud / 10 / 43); // TELEMETRY with τ_fx, τ_pc, R: 43 bytes
    host.send(1, v2::SetStream{65535});
    // A burst of commands on top of the stream: far more reply bytes than the link carries.
    for (int i = 0; i < 3000; ++i)
        host.send(quint8(i), v2::Ping{quint32(i)});
    for (int second = 0; second < 3; ++second) {
        qint64 bytes = 0;
        for (int ms = 0; ms < 1000; ++ms) {
            host.device.advance(1e-3);
            bytes += host.device.takeOutput().size();
            if (ms == 0 && second == 0)
                QVERIFY(bytes <= baud / 10 / 1000 + 1); // nothing arrives at once
        }
        QVERIFY2(bytes <= baud / 10, qPrintable(u"%1 bytes in second %2"_s.arg(bytes).arg(second)));
        QVERIFY2(bytes >= baud / 10 * 9 / 10, qPrintable(u"%1 bytes"_s.arg(bytes)));
    }
}

void TestSimulatedDevice::fullQueueDropsTelemetryAsSeqGap()
{
    SimulatedDevice::Config c;
    c.baud = 115200;
    c.ideal = true;
    Host host(c);
    host.send(1, v2::SetStream{1000}); // clamped to 267/s: fits the link alone
    for (int i = 0; i < 2000; ++i)     // ~10 KB of PONGs fill the 8 KiB TX queue
        host.send(quint8(i + 2), v2::Ping{quint32(i)});
    QList<quint8> seqs;
    for (int ms = 0; ms < 3000; ++ms) {
        host.device.advance(1e-3);
        telemetryOf(host.take(), &seqs);
    }
    QVERIFY(host.device.telemetryDropped() > 0);
    // The stream's first frame has seq 0; every dropped frame shows as a missing seq.
    quint64 gaps = 0;
    quint8 expected = 0;
    for (const quint8 seq : std::as_const(seqs)) {
        gaps += quint8(seq - expected);
        expected = quint8(seq + 1);
    }
    QCOMPARE(gaps, host.device.telemetryDropped());
}

void TestSimulatedDevice::idealMatchesModel_data()
{
    QTest::addColumn<QString>("hand");
    QTest::addColumn<double>("rate");
    QTest::addColumn<double>("feedback");
    QTest::newRow("step at 1 kHz") << u"step:0.05:-0.01"_s << 1000.0 << 0.0;
    QTest::newRow("chirp at 1 kHz") << u"chirp:0.1:0.5:8"_s << 1000.0 << 0.0;
    QTest::newRow("virtual hand at 250 Hz") << u"hand:0.6"_s << 250.0 << 0.0;
    QTest::newRow("sine with feedback at 2 kHz") << u"sine:0.2:1.5"_s << 2000.0 << 0.5;
}

void TestSimulatedDevice::idealMatchesModel()
{
    QFETCH(QString, hand);
    QFETCH(double, rate);
    QFETCH(double, feedback);
    SimulatedDevice::Config c = fastConfig();
    c.ideal = true;
    c.controlRateHz = rate;
    c.hand = handOf(hand);
    c.params.theta0 = 0.05;
    c.passivity = PassivityParams::off(); // model.md alone (the controller: tst_passivity)
    SimulatedDevice device(c);
    if (feedback != 0)
        device.receive(v2::encodeFrame(0, v2::SetFeedback{float(feedback)}));
    const DeviceParams p = f32Params(c.params);
    const double h = 1.0 / rate;
    const double tauExt = double(float(feedback));
    AdmittanceState s{p.theta0, 0.0};
    int saturated = 0;
    for (int k = 0; k < int(3 * rate); ++k) {
        const double t = k * h;
        const bool stale = feedback == 0 ? t >= 0.2 - 1e-12 : false;
        const double tau = -c.hand.torque(t, s.theta, s.omega);
        const double tauRec = recenteringTorque(p, s.theta);
        const double ext = stale ? 0.0 : tauExt;
        const double total = std::clamp(tauRec + ext, -c.tauLimit, c.tauLimit);
        if (feedback != 0 && k % 100 == 0) // keep the watchdog fed
            device.receive(v2::encodeFrame(0, v2::SetFeedback{float(feedback)}));
        const SimulatedDevice::Cycle cycle = device.step();
        const auto where = qPrintable(u"step %1"_s.arg(k));
        QVERIFY2(cycle.t == t, where);
        QVERIFY2(cycle.theta == s.theta, where);
        QVERIFY2(cycle.omega == s.omega, where);
        QVERIFY2(cycle.tau == tau, where);
        QVERIFY2(cycle.tau_rec == tauRec, where);
        QVERIFY2(cycle.tau_ext == ext, where);
        QVERIFY2(cycle.tau_total == total, where);
        saturated += bool(cycle.flags & v2::kFlagSaturated);
        s = admittanceStep(p, s, -tau + total, h);
    }
    QVERIFY(std::abs(s.theta - p.theta0) > 0.01); // the input actually moved the knob
    if (feedback != 0)
        QVERIFY(saturated > 0);
}

void TestSimulatedDevice::cycleSample_data()
{
    QTest::addColumn<double>("rate");
    QTest::newRow("1 kHz") << 1000.0;
    QTest::newRow("3 kHz: periods not whole µs") << 3000.0;
    QTest::newRow("70 Hz") << 70.0;
}

void TestSimulatedDevice::cycleSample()
{
    QFETCH(double, rate);
    SimulatedDevice::Config c = fastConfig();
    c.controlRateHz = rate;
    c.hand = handOf(u"sine:0.08:3"_s);
    SimulatedDevice device(c);
    for (int k = 0; k < int(rate); ++k) {
        const SimulatedDevice::Cycle cycle = device.step();
        const Sample s = cycle.toSample();
        const auto where = qPrintable(u"step %1"_s.arg(k));
        QVERIFY2(s.t_s == cycle.t, where);
        // The device clock: 32-bit microseconds of the cycle's time, wrapping.
        QVERIFY2(s.t_us == quint32(quint64(std::llround(cycle.t * 1e6))), where);
        QVERIFY2(s.theta == cycle.theta && s.omega == cycle.omega && s.tau == cycle.tau, where);
        QVERIFY2(s.tau_rec == cycle.tau_rec && s.tau_ext == cycle.tau_ext, where);
        QVERIFY2(s.tau_fx == cycle.tau_fx && s.tau_total == cycle.tau_total, where);
        QVERIFY2(s.tau_pc == cycle.tau_pc && s.pc_reserve == cycle.pc_reserve, where);
        QVERIFY2(s.flags == cycle.flags && s.v_ref == 0 && s.p_ref == 0, where);
    }
}

void TestSimulatedDevice::setHandRestartsTimeBase()
{
    SimulatedDevice::Config c = fastConfig();
    c.ideal = true;
    SimulatedDevice device(c);
    for (int i = 0; i < 1000; ++i)
        device.step();
    HandInput step = handOf(u"step:0.1:0.02"_s);
    device.setHand(step);
    QCOMPARE(device.hand(), step);
    // The step happens kStepTime after setHand, not after power-up (the cycle exactly at
    // the step time is skipped: which side of it a rounded time lands on is not the point).
    const int before = int(std::lround(HandInput::kStepTime * 1000));
    for (int i = 0; i < before; ++i)
        QCOMPARE(device.step().tau, -0.02);
    device.step();
    for (int i = 0; i < 10; ++i)
        QCOMPARE(device.step().tau, -0.1);
}

void TestSimulatedDevice::plantSettlesAtSpringEquilibrium_data()
{
    QTest::addColumn<double>("torque");
    QTest::addColumn<double>("expectedE");
    const DeviceParams p;
    // Notch band: e = τ/K_max. Far side: e = τ/K_min (beyond 2N, where K_rec = K_min).
    QTest::newRow("push +0.03 into notch band") << 0.03 << 0.03 / p.K_max;
    QTest::newRow("push -0.02 into notch band") << -0.02 << -0.02 / p.K_max;
    QTest::newRow("push +0.06 beyond 2N") << 0.06 << 0.06 / p.K_min;
    // Too weak to leave the dead zone: held at its edge, where K_rec jumps to K_max.
    QTest::newRow("push -0.005 held at dead-zone edge") << -0.005 << -p.Q_dz;
}

void TestSimulatedDevice::plantSettlesAtSpringEquilibrium()
{
    QFETCH(double, torque);
    QFETCH(double, expectedE);
    SimulatedDevice::Config c = fastConfig();
    c.hand.kind = HandInput::Kind::Constant;
    c.hand.amplitude = torque;
    SimulatedDevice device(c);
    const DeviceParams p = device.params();
    for (int i = 0; i < 3000; ++i)
        device.step();
    // At rest the knob dithers by about a tick around the equilibrium (position and load
    // are quantised, the servo lags); at the notch edge it chatters a little. So judge the
    // last second as a whole.
    const double tick = kTwoPi / 4096;
    const double quantum = 0.44e-3;
    double sumE = 0;
    double sumTau = 0;
    double maxOmega = 0;
    double maxDeviation = 0;
    const int n = 1000;
    for (int i = 0; i < n; ++i) {
        const SimulatedDevice::Cycle cycle = device.step();
        const double e = cycle.theta - p.theta0;
        sumE += e;
        sumTau += cycle.tau;
        maxOmega = std::max(maxOmega, std::abs(cycle.omega));
        maxDeviation = std::max(maxDeviation, std::abs(e - expectedE));
    }
    const double meanE = sumE / n;
    const double meanTau = sumTau / n;
    // Equilibrium of the spring: K_rec(θ)·e = τ_op, to within a tick and a load quantum.
    const double tolerance = 1.5 * tick + quantum / p.K_min;
    QVERIFY2(std::abs(meanE - expectedE) < tolerance,
             qPrintable(u"mean e = %1, expected %2"_s.arg(meanE).arg(expectedE)));
    QVERIFY2(maxDeviation <= 4 * tick, qPrintable(QString::number(maxDeviation)));
    QVERIFY2(maxOmega < 0.5, qPrintable(QString::number(maxOmega)));
    // The servo's load balances the hand: τ ≈ −τ_op.
    QVERIFY2(std::abs(meanTau + torque) <= 2 * quantum, qPrintable(QString::number(meanTau)));
}

void TestSimulatedDevice::plantMeasurementsQuantised()
{
    SimulatedDevice::Config c = fastConfig();
    c.hand = handOf(u"sine:0.1:2"_s);
    SimulatedDevice device(c);
    bool moved = false;
    for (int i = 0; i < 1000; ++i) {
        const SimulatedDevice::Cycle cycle = device.step();
        const double ticks = cycle.theta * 4096 / kTwoPi;
        QVERIFY2(std::abs(ticks - std::round(ticks)) < 1e-3, qPrintable(QString::number(ticks)));
        const double loads = cycle.tau / 0.44e-3;
        QVERIFY2(std::abs(loads - std::round(loads)) < 1e-3, qPrintable(QString::number(loads)));
        QVERIFY(std::abs(cycle.tau) <= 0.44 + 1e-6);
        moved = moved || std::abs(cycle.theta) > 0.05;
    }
    QVERIFY(moved);
}

void TestSimulatedDevice::noiseIsSeeded()
{
    auto run = [](quint64 seed) {
        SimulatedDevice::Config c = fastConfig();
        c.noise = 0.003;
        c.seed = seed;
        SimulatedDevice device(c);
        QList<double> taus;
        for (int i = 0; i < 200; ++i)
            taus.append(device.step().tau);
        return taus;
    };
    const QList<double> a = run(7);
    QCOMPARE(run(7), a);
    QVERIFY(run(8) != a);
    QVERIFY(std::any_of(a.begin(), a.end(), [](double v) { return v != 0; }));
}

void TestSimulatedDevice::legacyBootTextAndFrameRate()
{
    SimulatedDevice::Config c;
    c.protocol = WireProtocol::Legacy;
    SimulatedDevice device(c);
    QCOMPARE(device.baud(), 115200);
    legacy::Decoder decoder;
    QList<legacy::Frame> frames;
    QStringList text;
    int firstFrameMs = -1;
    for (int ms = 0; ms < 3100; ++ms) { // frames at 0.2 s, 0.4 s, … 3.0 s
        device.advance(1e-3);
        decoder.feed(device.takeOutput(), frames, &text);
        if (firstFrameMs < 0 && !frames.isEmpty())
            firstFrameMs = ms;
    }
    QCOMPARE(text.value(0), u"STS3032 Torque control"_s);
    QCOMPARE(text.value(1), u"Current pos motor : 1000"_s);
    QCOMPARE(text.value(2), u"1000"_s);
    QCOMPARE(frames.size(), 15); // 5 frames/s
    QVERIFY(firstFrameMs >= 195 && firstFrameMs <= 210);
    for (const legacy::Frame &f : frames)
        QCOMPARE(f, (legacy::Frame{1000, 1000, 1000, 1000})); // at rest, centre tick
    QCOMPARE(decoder.stats().malformed, 0u);
}

void TestSimulatedDevice::legacyPositionWraps()
{
    // Pushed 2 rad negative (K_min region): tick 1000 − 1304 wraps to 4096 − 304.
    SimulatedDevice::Config c;
    c.protocol = WireProtocol::Legacy;
    c.hand = handOf(u"const:-0.3"_s);
    SimulatedDevice device(c);
    legacy::Decoder decoder;
    QList<legacy::Frame> frames;
    SimulatedDevice::Cycle cycle;
    for (int i = 0; i < 8000; ++i) {
        cycle = device.step();
        decoder.feed(device.takeOutput(), frames);
    }
    QVERIFY(cycle.theta < -1.6);
    QVERIFY(!frames.isEmpty());
    const int expected = int(std::lround(cycle.theta * 4096 / kTwoPi)) + 1000 + 4096;
    QVERIFY(frames.last().a >= 0 && frames.last().a < 4096);
    QVERIFY2(std::abs(frames.last().a - expected) <= 2,
             qPrintable(u"%1 vs %2"_s.arg(frames.last().a).arg(expected)));
}

void TestSimulatedDevice::legacyFeedback()
{
    SimulatedDevice::Config c;
    c.protocol = WireProtocol::Legacy;
    c.ideal = true;
    SimulatedDevice device(c);
    QCOMPARE(device.step().tau_ext, 0.0);
    device.receive("ia1350b0c0d0o");
    SimulatedDevice::Cycle cycle = device.step();
    QVERIFY(std::abs(cycle.tau_ext - 0.35 * 0.44) < 1e-12);
    // No watchdog in the published firmware: the force stays.
    for (int i = 0; i < 1000; ++i)
        cycle = device.step();
    QVERIFY(std::abs(cycle.tau_ext - 0.35 * 0.44) < 1e-12);
    QVERIFY(!(cycle.flags & v2::kFlagFeedbackStale));
    // Split over several writes, negative offset.
    device.receive("ia8");
    device.receive("00b0c0d0o");
    QVERIFY(std::abs(device.step().tau_ext + 0.2 * 0.44) < 1e-12);
    // A malformed frame is ignored.
    device.receive("iaxyzb0c0d0o");
    QVERIFY(std::abs(device.step().tau_ext + 0.2 * 0.44) < 1e-12);
}

void TestSimulatedDevice::legacyBusyWaitHazard()
{
    SimulatedDevice::Config c;
    c.protocol = WireProtocol::Legacy;
    c.hand = handOf(u"const:0.05"_s);
    SimulatedDevice device(c);
    legacy::Decoder decoder;
    QList<legacy::Frame> frames;
    device.advance(1.05); // frames at 0.2 s … 1.0 s
    decoder.feed(device.takeOutput(), frames);
    QCOMPARE(frames.size(), 5);

    device.receive("i"); // an 'i' without its 'o': the firmware waits
    const SimulatedDevice::Cycle frozen = device.step();
    frames.clear();
    device.advance(2.0);
    decoder.feed(device.takeOutput(), frames);
    QCOMPARE(frames.size(), 0);
    QCOMPARE(device.step().t, frozen.t); // no control cycle ran

    device.receive("a1000b0c0d0o"); // the 'o' releases it
    device.advance(1.0);
    decoder.feed(device.takeOutput(), frames);
    QVERIFY(frames.size() >= 4 && frames.size() <= 6);
    QVERIFY(device.step().t > frozen.t + 2.9);
}

void TestSimulatedDevice::legacyIgnoresV2()
{
    SimulatedDevice::Config c;
    c.protocol = WireProtocol::Legacy;
    SimulatedDevice device(c);
    device.advance(0.05);
    device.takeOutput();
    // HELLO seq 0 (no 0x69 byte) and a SET_STREAM: no reply, frames keep coming.
    device.receive(QByteArray::fromHex("0201033e2e00"));
    device.receive(v2::encodeFrame(2, v2::SetStream{1000}));
    legacy::Decoder decoder;
    QList<legacy::Frame> frames;
    QStringList text;
    device.advance(1.0);
    const QByteArray out = device.takeOutput();
    decoder.feed(out, frames, &text);
    QCOMPARE(frames.size(), 5);
    QVERIFY(text.isEmpty());
    QVERIFY(!out.contains('\0'));
}

QTEST_GUILESS_MAIN(TestSimulatedDevice)
#include "tst_simulateddevice.moc"
