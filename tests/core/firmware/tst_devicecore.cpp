// fw::DeviceCore on its own seams: no allocation after start (a counting allocator), bus
// errors held and, 100 in a row, torque off with a LOG; the float build (the ESP32's) tracking
// the double build (the simulator's). Protocol semantics are covered through the simulator,
// which runs this same core (tst_simulateddevice, tst_simulateddevicelink).
#include "devicecoretest.h"
#include "hostframes.h"

#include "firmware/devicecore.h"
#include "firmware/stsactuator.h"
#include "firmware/stsbus.h"
#include "protocol/v2codec.h"

#include <QTest>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <numbers>

using namespace hatpic;
using namespace devicecoretest;

// ---- counting allocator: counts every operator new while armed ----
namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
} // namespace

void *operator new(std::size_t size)
{
    if (g_counting.load(std::memory_order_relaxed))
        g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void *p = std::malloc(size ? size : 1))
        return p;
    throw std::bad_alloc();
}
void operator delete(void *p) noexcept
{
    std::free(p);
}
void operator delete(void *p, std::size_t) noexcept
{
    std::free(p);
}

namespace {

constexpr double kTick = 2.0 * std::numbers::pi / 4096;

//! A device core on canned hardware, as the ESP32 glue wires it.
template<typename T> struct Rig
{
    explicit Rig(std::uint32_t busTimeoutUs = 0, double rateHz = 1000)
        : bus(servo, busTimeoutUs), actuator(bus, {}),
          core(config(rateHz), host, actuator, clock, nullptr)
    {}
    static typename fw::DeviceCore<T>::Config config(double rateHz)
    {
        typename fw::DeviceCore<T>::Config c;
        c.control.rateHz = rateHz;
        c.deviceId = 0x54455354;
        c.firmware = "test";
        return c;
    }
    void send(std::uint8_t seq, const v2::Message &m) { sendToDevice(host, seq, m); }
    //! Runs one cycle 1 ms after the previous one, and the link context after it.
    const fw::CycleRecord<T> &cycle()
    {
        clock.now += 1000;
        const fw::CycleRecord<T> &r = core.controlCycle(clock.now);
        core.serviceHost();
        return r;
    }
    QList<v2::Frame> received() { return framesFromDevice(host, decoder); }

    CannedServo servo;
    FixedHostPort host;
    ManualClock clock;
    fw::StsBus bus;
    fw::StsActuator<T> actuator;
    fw::DeviceCore<T> core;
    v2::FrameDecoder decoder{v2::Direction::FromDevice};
};

template<typename T> long allocationsOfBusyRun()
{
    Rig<T> rig;
    if (!rig.core.start(0))
        return -1;
    // Everything a host does, pre-encoded outside the counted region.
    std::array<v2::FrameBuffer, 8> frames{};
    std::array<std::size_t, 8> sizes{};
    const v2::Message messages[] = {v2::SetStream{1000},   v2::SetParams{DeviceParams{}},
                                    v2::GetParams{},       v2::Ping{7},
                                    v2::SetFeedback{0.1f}, v2::Zero{},
                                    v2::Hello{},           v2::SetStream{500}};
    for (std::size_t i = 0; i < frames.size(); ++i)
        sizes[i] = v2::encodeFrame(std::uint8_t(i + 1), messages[i], frames[i]);
    std::array<std::uint8_t, 4096> drain;

    g_allocations = 0;
    g_counting = true;
    for (int k = 0; k < 3000; ++k) {
        if (k % 50 == 0) {
            const std::size_t i = std::size_t(k / 50) % frames.size();
            rig.host.toDevice.push(std::span(frames[i]).first(sizes[i]));
        }
        rig.servo.setPresent(1000 + (k / 10) % 40, (k % 7) - 3, -(k % 300));
        rig.cycle();
        while (rig.host.toHost.pop(drain) > 0) {
        }
    }
    g_counting = false;
    return g_allocations.load();
}

} // namespace

class TestDeviceCore : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void noAllocationAfterStart();
    void busErrorHoldsMeasurementAndCommand();
    void hundredBusErrorsDisableTorque();
    void floatBuildTracksDoubleBuild();
    void commandsBeyondTheQueueAreCountedAndHelloStillStops();
    void feedbackNeverOutlivesTheWatchdog_data();
    void feedbackNeverOutlivesTheWatchdog();
};

void TestDeviceCore::noAllocationAfterStart()
{
    // The counter works: an allocation in the counted region is seen.
    g_allocations = 0;
    g_counting = true;
    // A direct call: a new-expression paired with a delete may be optimised away.
    ::operator delete(::operator new(16));
    g_counting = false;
    QCOMPARE(g_allocations.load(), 1L);

    QCOMPARE(allocationsOfBusyRun<float>(), 0L);
    QCOMPARE(allocationsOfBusyRun<double>(), 0L);
}

void TestDeviceCore::busErrorHoldsMeasurementAndCommand()
{
    Rig<double> rig;
    QVERIFY(rig.core.start(0));
    rig.servo.setPresent(1030, 0, -20);
    const double theta = rig.cycle().theta;
    QCOMPARE(theta, double(float(30 * kTick)));
    const std::uint16_t goal = rig.servo.word(fw::sts::kRegGoalPosition);

    // One corrupt reply: the new present position is not acted on, no new goal is written.
    rig.servo.corruptReplies = true;
    rig.servo.setPresent(1100, 0, -20);
    const fw::CycleRecord<double> held = rig.cycle();
    QCOMPARE(held.theta, theta);
    QCOMPARE(rig.servo.word(fw::sts::kRegGoalPosition), goal);
    QCOMPARE(rig.core.controller().busErrors(), quint64(1));
    QVERIFY(!rig.core.controller().faulted());

    rig.servo.corruptReplies = false;
    QCOMPARE(rig.cycle().theta, double(float(100 * kTick)));
    QVERIFY(rig.core.controller().busErrors() >= 1);
}

void TestDeviceCore::hundredBusErrorsDisableTorque()
{
    Rig<double> rig;
    QVERIFY(rig.core.start(0));
    QCOMPARE(rig.servo.regs[fw::sts::kRegTorqueEnable], std::uint8_t(1));
    rig.received();
    rig.servo.corruptReplies = true; // the servo still obeys; the master cannot trust a reply
    for (std::uint32_t i = 1; i < fw::Controller<double>::kMaxConsecutiveBusErrors; ++i)
        QCOMPARE(rig.cycle().flags & v2::kFlagTorqueOff, 0);
    QVERIFY(!rig.core.controller().faulted());
    QCOMPARE(rig.servo.regs[fw::sts::kRegTorqueEnable], std::uint8_t(1));
    // The 100th: torque off, and every frame from then on says so (issue 21).
    QCOMPARE(rig.cycle().flags & v2::kFlagTorqueOff, int(v2::kFlagTorqueOff));
    QVERIFY(rig.core.controller().faulted());
    QCOMPARE(rig.servo.regs[fw::sts::kRegTorqueEnable], std::uint8_t(0));

    bool logged = false;
    for (const v2::Frame &f : rig.received()) {
        if (const auto *log = std::get_if<v2::Log>(&f.message))
            logged = logged || v2::toQString(log->text).contains(u"torque disabled");
    }
    QVERIFY(logged);

    // It stays off: a servo that answers again does not get its torque back by itself.
    rig.servo.corruptReplies = false;
    const std::uint64_t writes = rig.servo.writes;
    for (int i = 0; i < 10; ++i)
        QCOMPARE(rig.cycle().flags & v2::kFlagTorqueOff, int(v2::kFlagTorqueOff));
    QCOMPARE(rig.servo.regs[fw::sts::kRegTorqueEnable], std::uint8_t(0));
    QCOMPARE(rig.servo.writes, writes);
}

void TestDeviceCore::floatBuildTracksDoubleBuild()
{
    // A servo that follows its goal exactly and a hand holding 0.02 N·m: both builds settle
    // where the spring balances the hand, τ/K_max = 0.05 rad, within a tick of each other.
    Rig<float> f;
    Rig<double> d;
    QVERIFY(f.core.start(0));
    QVERIFY(d.core.start(0));
    const int load = -int(std::lround(0.02 / 0.44 * 1000)); // the servo holds the hand
    int maxDiff = 0;
    for (int k = 0; k < 2000; ++k) {
        f.servo.setPresent(f.servo.word(fw::sts::kRegGoalPosition), 0, load);
        d.servo.setPresent(d.servo.word(fw::sts::kRegGoalPosition), 0, load);
        const double tf = f.cycle().theta;
        const double td = d.cycle().theta;
        maxDiff = std::max(maxDiff, int(std::lround(std::abs(tf - td) / kTick)));
    }
    QVERIFY2(maxDiff <= 1, qPrintable(QString::number(maxDiff)));
    const double rest = 0.02 / DeviceParams{}.K_max;
    QVERIFY(std::abs(double(f.core.controller().last().theta) - rest) <= 1.5 * kTick);
    QVERIFY(std::abs(d.core.controller().last().theta - rest) <= 1.5 * kTick);
}

void TestDeviceCore::commandsBeyondTheQueueAreCountedAndHelloStillStops()
{
    // Found writing fuzz_devicecore's invariant: more commands for the control context than its
    // queue holds, between two cycles, were dropped without a reply and without a count; a HELLO
    // among them was answered while its "stop the stream" was lost, so telemetry went on.
    Rig<double> rig;
    QVERIFY(rig.core.start(0));
    rig.received();
    constexpr std::uint8_t kBurst = 12; // the queue holds 8
    for (std::uint8_t seq = 0; seq < kBurst; ++seq)
        rig.send(seq, v2::SetStream{1000});
    rig.send(kBurst, v2::Hello{});
    rig.core.serviceHost();
    const QList<v2::Frame> replies = rig.received();
    QCOMPARE(replies.size() + qsizetype(rig.core.unansweredCommands()), qsizetype(kBurst + 1));
    QVERIFY(rig.core.unansweredCommands() > 0);
    bool helloAnswered = false;
    for (const v2::Frame &f : replies)
        helloAnswered = helloAnswered || std::holds_alternative<v2::HelloReply>(f.message);
    QVERIFY(!helloAnswered); // not applied, so not answered: the host retries it

    // The retry goes through once the control context has drained the queue, and stops the
    // stream for good.
    rig.cycle();
    rig.received();
    rig.send(kBurst, v2::Hello{});
    rig.cycle();
    int helloReplies = 0;
    for (const v2::Frame &f : rig.received()) // and the telemetry of the cycle before it
        helloReplies += std::holds_alternative<v2::HelloReply>(f.message) ? 1 : 0;
    QCOMPARE(helloReplies, 1);
    for (int i = 0; i < 20; ++i)
        rig.cycle();
    QVERIFY(rig.received().isEmpty());
    QCOMPARE(rig.core.streamRate(), std::uint16_t(0));
}

void TestDeviceCore::feedbackNeverOutlivesTheWatchdog_data()
{
    QTest::addColumn<double>("rate");
    QTest::addColumn<std::uint32_t>("arrivalUs"); //!< SET_FEEDBACK's arrival, between cycles
    QTest::newRow("10 Hz, the lowest rate") << 10.0 << 250000u;
    QTest::newRow("10 Hz, just after a cycle") << 10.0 << 200001u;
    QTest::newRow("100 Hz") << 100.0 << 203000u;
    QTest::newRow("1 kHz") << 1000.0 << 200300u;
    QTest::newRow("2.5 kHz") << 2500.0 << 200100u;
}

void TestDeviceCore::feedbackNeverOutlivesTheWatchdog()
{
    // A cycle's τ_ext stays in force until the next cycle. With feedback arriving between
    // cycles, a 2 Hz hatpic-fw-host once rendered τ_ext 0.1 s after the feedback stopped and
    // first read 0 at 0.6 s: the watchdog ran late by up to a period.
    QFETCH(double, rate);
    QFETCH(std::uint32_t, arrivalUs);
    constexpr std::uint32_t kWatchdogUs = fw::Controller<double>::kFeedbackWatchdogUs;
    const auto periodUs = std::uint32_t(std::llround(1e6 / rate));
    Rig<double> rig(0, rate);
    QVERIFY(rig.core.start(0));
    rig.clock.now = arrivalUs;
    rig.send(1, v2::SetFeedback{0.1f});
    rig.core.serviceHost(); // stamped on arrival

    int rendered = 0;
    for (std::uint32_t t = (arrivalUs / periodUs + 1) * periodUs; t < arrivalUs + 2 * kWatchdogUs;
         t += periodUs) {
        rig.clock.now = t;
        const fw::CycleRecord<double> &r = rig.core.controlCycle(t);
        // Rendered exactly while it is still within the watchdog at the next cycle.
        const bool inTime = t + periodUs - arrivalUs <= kWatchdogUs;
        QVERIFY2((r.tau_ext != 0) == inTime, qPrintable(QStringLiteral("cycle at %1 µs").arg(t)));
        QCOMPARE(bool(r.flags & v2::kFlagFeedbackStale), !inTime);
        rendered += inTime;
    }
    QVERIFY(rendered > 0); // fresh feedback is rendered at this rate
}

QTEST_GUILESS_MAIN(TestDeviceCore)
#include "tst_devicecore.moc"
