// fw::DeviceCore with four knobs on its own seams: each knob its own servo (a canned one), so a
// fault, a block or a feedback value of one knob is seen to reach that knob alone; every knob
// in one TELEMETRY frame. The same core on real ptys: tests/core/fwhost/tst_firmwarehostknobs.
#include "devicecoretest.h"
#include "hostframes.h"

#include "firmware/devicecore.h"
#include "firmware/stsactuator.h"
#include "firmware/stsbus.h"
#include "protocol/v2codec.h"

#include <QTest>

#include <numbers>

using namespace hatpic;
using namespace devicecoretest;

namespace {

constexpr double kTick = 2.0 * std::numbers::pi / 4096;

//! One knob's hardware: a canned servo on a bus of its own (the core cannot tell).
struct Knob
{
    CannedServo servo;
    fw::StsBus bus{servo, 0};
    fw::StsActuator<double> actuator{bus, {}};
};

//! A device core over four knobs.
struct FourKnobs
{
    FourKnobs()
        : core(config(), host,
               std::array<fw::Actuator<double> *, 4>{&knobs[0].actuator, &knobs[1].actuator,
                                                     &knobs[2].actuator, &knobs[3].actuator},
               clock, nullptr)
    {}
    static fw::DeviceCore<double>::Config config()
    {
        fw::DeviceCore<double>::Config c;
        c.deviceId = 0x4B4E4234;
        c.firmware = "knobs";
        return c;
    }
    void send(std::uint8_t seq, const v2::Message &m) { sendToDevice(host, seq, m); }
    void cycle()
    {
        clock.now += 1000;
        core.controlCycle(clock.now);
        core.serviceHost();
    }
    QList<v2::Frame> received() { return framesFromDevice(host, decoder); }

    std::array<Knob, 4> knobs;
    FixedHostPort host;
    ManualClock clock;
    fw::DeviceCore<double> core;
    v2::FrameDecoder decoder{v2::Direction::FromDevice};
};

} // namespace

class TestDeviceKnobs : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void everyKnobInOneFrame()
    {
        FourKnobs rig;
        QVERIFY(rig.core.start(0));
        QCOMPARE(rig.core.axes(), 4);
        for (int k = 0; k < 4; ++k)
            rig.knobs[std::size_t(k)].servo.setPresent(1000 + 10 * (k + 1), 0, 0);
        rig.send(1, v2::Hello{});
        rig.send(2, v2::SetStream{1000});
        rig.cycle();
        rig.cycle();
        bool hello = false;
        QList<v2::Telemetry> frames;
        for (const v2::Frame &f : rig.received()) {
            if (const auto *reply = std::get_if<v2::HelloReply>(&f.message)) {
                hello = true;
                QCOMPARE(reply->axes, std::optional<std::uint8_t>(4));
                QVERIFY(reply->capabilities & v2::kCapabilityAxes);
            } else if (const auto *t = std::get_if<v2::Telemetry>(&f.message)) {
                frames.append(*t);
            }
        }
        QVERIFY(hello);
        QVERIFY(!frames.isEmpty());
        const v2::Telemetry &last = frames.last();
        QCOMPARE(last.theta, float(10 * kTick));
        for (int k = 1; k < 4; ++k) {
            QVERIFY(last.more[std::size_t(k - 1)]);
            QCOMPARE(last.more[std::size_t(k - 1)]->theta, float(10 * (k + 1) * kTick));
        }
    }

    void aBlockAndFeedbackReachTheirKnobAlone()
    {
        FourKnobs rig;
        QVERIFY(rig.core.start(0));
        DeviceParams soft;
        soft.K_max = 0.2;
        rig.send(1, v2::SetParams{soft, 2});
        v2::SetFeedback feedback{0.0f};
        feedback.more = {0.0f, 0.0f, 0.05f};
        rig.send(2, feedback);
        rig.cycle();
        rig.cycle();
        QCOMPARE(rig.core.params(2).K_max, double(0.2f));
        QCOMPARE(rig.core.params(0).K_max, double(float(DeviceParams{}.K_max)));
        QCOMPARE(rig.core.controller(2).params().K_max, double(0.2f));
        QCOMPARE(rig.core.controller(1).params().K_max, double(float(DeviceParams{}.K_max)));
        QCOMPARE(rig.core.controller(3).last().tau_ext, double(0.05f));
        QCOMPARE(rig.core.controller(0).last().tau_ext, 0.0);
        QCOMPARE(rig.core.controller(1).last().tau_ext, 0.0);

        // A knob the device does not have: refused, naming the axis; nothing changes.
        rig.send(3, v2::SetParams{DeviceParams{}, 4});
        rig.send(4, v2::Zero{7});
        rig.cycle();
        int refused = 0;
        for (const v2::Frame &f : rig.received()) {
            if (const auto *ack = std::get_if<v2::Ack>(&f.message); ack && ack->ackedSeq >= 3) {
                QCOMPARE(ack->status, v2::AckStatus::OutOfRange);
                QCOMPARE(ack->field, v2::kAxisField);
                ++refused;
            }
        }
        QCOMPARE(refused, 2);
        QCOMPARE(rig.core.params(2).K_max, double(0.2f));
    }

    void oneKnobsFaultLeavesTheOthersRunning()
    {
        FourKnobs rig;
        QVERIFY(rig.core.start(0));
        rig.send(1, v2::SetStream{1000});
        rig.knobs[2].servo.corruptReplies = true;
        for (std::uint32_t i = 0; i < fw::Controller<double>::kMaxConsecutiveBusErrors; ++i)
            rig.cycle();
        QVERIFY(rig.core.controller(2).faulted());
        QCOMPARE(rig.knobs[2].servo.regs[fw::sts::kRegTorqueEnable], std::uint8_t(0));
        for (int k : {0, 1, 3}) {
            QVERIFY(!rig.core.controller(k).faulted());
            QCOMPARE(rig.knobs[std::size_t(k)].servo.regs[fw::sts::kRegTorqueEnable],
                     std::uint8_t(1));
        }
        rig.cycle();
        QString log;
        v2::Telemetry last;
        for (const v2::Frame &f : rig.received()) {
            if (const auto *l = std::get_if<v2::Log>(&f.message))
                log = v2::toQString(l->text);
            else if (const auto *t = std::get_if<v2::Telemetry>(&f.message))
                last = *t;
        }
        QCOMPARE(log, QStringLiteral("knob 3: servo bus: 100 consecutive errors, torque disabled"));
        QVERIFY(last.more[1]->flags & v2::kFlagTorqueOff);
        QVERIFY(!(last.flags & v2::kFlagTorqueOff));
        QVERIFY(!(last.more[0]->flags & v2::kFlagTorqueOff));
        QVERIFY(!(last.more[2]->flags & v2::kFlagTorqueOff));
    }
};

QTEST_GUILESS_MAIN(TestDeviceKnobs)
#include "tst_deviceknobs.moc"
