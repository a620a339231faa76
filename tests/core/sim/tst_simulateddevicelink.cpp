// SimulatedDevice offline (no pty): its stream and its link. SET_STREAM's clamping and HELLO
// stopping the stream, telemetry consistent frame by frame and its clock's wrap, the watchdog,
// throttling to the baud rate, and a full queue showing as seq gaps.
#include "devicehost.h"
#include "model/stiffness.h"
#include "session/sessiontypes.h"
#include "sim/simulateddevice.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace hatpic;
using namespace Qt::StringLiterals;
using test::fastConfig;
using test::handOf;
using test::Host;
using test::telemetryOf;

Q_DECLARE_METATYPE(hatpic::v2::AckStatus)

class TestSimulatedDeviceLink : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void setStreamClamps_data();
    void setStreamClamps();
    void helloStopsStreaming();
    void telemetryConsistent();
    void telemetryClockWraps();
    void watchdog();
    void watchdogHoldsNoLongerThanItsTimeAtLowRates();
    void throttling_data();
    void throttling();
    void fullQueueDropsTelemetryAsSeqGap();
};

void TestSimulatedDeviceLink::setStreamClamps_data()
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

void TestSimulatedDeviceLink::setStreamClamps()
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

void TestSimulatedDeviceLink::helloStopsStreaming()
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

void TestSimulatedDeviceLink::telemetryConsistent()
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

void TestSimulatedDeviceLink::telemetryClockWraps()
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

void TestSimulatedDeviceLink::watchdog()
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

void TestSimulatedDeviceLink::watchdogHoldsNoLongerThanItsTimeAtLowRates()
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

void TestSimulatedDeviceLink::throttling_data()
{
    QTest::addColumn<int>("baud");
    QTest::newRow("115200") << 115200;
    QTest::newRow("921600") << 921600;
    QTest::newRow("57600") << 57600;
}

void TestSimulatedDeviceLink::throttling()
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

void TestSimulatedDeviceLink::fullQueueDropsTelemetryAsSeqGap()
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

QTEST_GUILESS_MAIN(TestSimulatedDeviceLink)
#include "tst_simulateddevicelink.moc"
