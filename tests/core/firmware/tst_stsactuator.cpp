// StsActuator (servo.md § 3–4) against the emulated STS3032: start, measure, command, disable;
// its measurements must equal the simulator's quantisation bit for bit.
#include "stsbustest.h"

#include "firmware/stsactuator.h"
#include "firmware/stsbus.h"

#include <QTest>

#include <array>
#include <random>

using namespace hatpic;
using namespace ststest;
using fw::StsBus;
namespace sts = fw::sts;

class TestStsActuator : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void starts();
    void measuresLikeTheSimulator_data();
    void measuresLikeTheSimulator();
    void noiseLikeTheSimulator();
    void commands_data();
    void commands();
    void disables();
    void failsWithoutTouchingData();
};

void TestStsActuator::starts()
{
    ServoPlant plant(0.44, 0.3);
    plant.setTorqueEnabled(false); // the emulation's torque enable mirrors it
    EmulatedSts3032 off(plant, {});
    EmulatedServoPort port(off);
    StsBus bus(port);
    fw::StsActuator<double> actuator(bus, {});
    QCOMPARE(bus.timeoutUs(), StsBus::kDefaultTimeoutUs);
    QCOMPARE(int(off.reg(sts::kRegTorqueEnable)), 0);
    double theta = 0;
    QVERIFY(actuator.start(theta));
    QCOMPARE(theta, simTheta(0.3));
    QCOMPARE(actuator.modelNumber(), EmulatedSts3032::kDefaultModelNumber);
    QCOMPARE(int(off.reg(sts::kRegMode)), 0);
    QCOMPARE(int(off.reg(sts::kRegTorqueEnable)), 1);
    QVERIFY(plant.torqueEnabled());
    // Goal = present position before torque on.
    QCOMPARE(plant.command(), std::round(0.3 * 4096 / kTwoPi) * (kTwoPi / 4096));
    QCOMPARE(int(bus.stats().requests), 6);
    QCOMPARE(int(bus.stats().errors()), 0);

    // A servo that reports an unknown model number is used all the same.
    EmulatedSts3032::Config odd;
    odd.modelNumber = 0xBEEF;
    Rig clone(0.0, odd);
    fw::StsActuator<float> f(clone.bus, {});
    float thetaF = 1;
    QVERIFY(f.start(thetaF));
    QCOMPARE(thetaF, 0.0f);
    QCOMPARE(f.modelNumber(), std::uint16_t(0xBEEF));
}

void TestStsActuator::measuresLikeTheSimulator_data()
{
    QTest::addColumn<double>("theta0");
    QTest::addColumn<double>("command");
    QTest::addColumn<double>("handTorque");
    QTest::addColumn<int>("centerTick");

    QTest::newRow("at rest") << 0.0 << 0.0 << 0.0 << 1000;
    QTest::newRow("held against a push") << 0.2 << 0.2 << 0.1 << 1000;
    QTest::newRow("pushed the other way") << -0.4 << -0.4 << -0.15 << 1000;
    QTest::newRow("moving to a new goal") << 0.0 << 1.0 << 0.0 << 1000;
    QTest::newRow("saturated load") << 0.0 << 0.5 << -0.8 << 1000;
    QTest::newRow("below tick 0 (not wrapped)") << -1.0 << -2.0 << 0.0 << 1000;
    QTest::newRow("other center") << 0.1 << -0.3 << 0.05 << 2048;
}

void TestStsActuator::measuresLikeTheSimulator()
{
    QFETCH(double, theta0);
    QFETCH(double, command);
    QFETCH(double, handTorque);
    QFETCH(int, centerTick);

    EmulatedSts3032::Config config;
    config.centerTick = centerTick;
    Rig rig(theta0, config);
    fw::StsActuator<double>::Config ac;
    ac.centerTick = centerTick;
    fw::StsActuator<double> actuator(rig.bus, ac);
    fw::StsActuator<float>::Config fc;
    fc.centerTick = centerTick;
    fw::StsActuator<float> actuatorF(rig.bus, fc);
    double theta = 0;
    QVERIFY(actuator.start(theta));
    rig.plant.setCommand(command); // goal beyond 0…4095 is fine for the plant itself
    for (int cycle = 0; cycle < 200; ++cycle) {
        for (int i = 0; i < 10; ++i)
            rig.plant.step(1e-4, handTorque);
        fw::Measurement<double> m;
        QVERIFY(actuator.measure(m));
        QCOMPARE(m.theta, simTheta(rig.plant.theta()));
        QCOMPARE(m.omega, simTheta(rig.plant.omega()));
        QCOMPARE(m.tau, simTau(rig.plant.motorTorque(), 0.44));
        fw::Measurement<float> mf;
        QVERIFY(actuatorF.measure(mf));
        QCOMPARE(double(mf.theta), m.theta);
        const std::int32_t load = sts::decodeSignMagnitude(
            sts::word(rig.servo.reg(sts::kRegPresentLoad), rig.servo.reg(sts::kRegPresentLoad + 1)),
            sts::kLoadSignBit);
        QCOMPARE(mf.tau, sts::loadToTorque(load, double(0.44f)));
        // Held in place against the hand, the servo resists: τ ≈ −τ_op (servo.md § 3).
        if (cycle == 199 && command == theta0 && handTorque != 0)
            QCOMPARE(std::round(m.tau * 1000), std::round(-handTorque * 1000));
    }
    QCOMPARE(int(rig.bus.stats().errors()), 0);
}

void TestStsActuator::noiseLikeTheSimulator()
{
    EmulatedSts3032::Config config;
    config.noise = 0.01;
    config.seed = 7;
    Rig rig(0.1, config);
    fw::StsActuator<double> actuator(rig.bus, {});
    double theta = 0;
    QVERIFY(actuator.start(theta)); // reads the position only: no noise drawn
    std::mt19937_64 rng(7);
    std::normal_distribution<double> noise{0.0, 1.0};
    for (int cycle = 0; cycle < 500; ++cycle) {
        for (int i = 0; i < 10; ++i)
            rig.plant.step(1e-4, 0.05);
        fw::Measurement<double> m;
        QVERIFY(actuator.measure(m));
        const double load = rig.plant.motorTorque() + 0.01 * noise(rng);
        QCOMPARE(m.tau, simTau(load, 0.44));
    }
}

void TestStsActuator::commands_data()
{
    QTest::addColumn<double>("theta");
    QTest::addColumn<int>("goal");
    const double tick = kTwoPi / 4096;
    QTest::newRow("center") << 0.0 << 1000;
    QTest::newRow("a tick and a bit") << 1.4 * tick << 1001;
    QTest::newRow("0.6 tick back") << -0.6 * tick << 999;
    QTest::newRow("clamped at 0") << -2.0 << 0;
    QTest::newRow("clamped at 4095") << 5.0 << 4095;
}

void TestStsActuator::commands()
{
    QFETCH(double, theta);
    QFETCH(int, goal);
    Rig rig;
    fw::StsActuator<double> actuator(rig.bus, {});
    QVERIFY(actuator.command(theta, 123.0));
    QCOMPARE(sts::word(rig.servo.reg(42), rig.servo.reg(43)), std::uint16_t(goal));
    QCOMPARE(rig.plant.command(), (goal - 1000) * (kTwoPi / 4096));
    fw::StsActuator<float> actuatorF(rig.bus, {});
    QVERIFY(actuatorF.command(float(theta), 0.0f));
    QCOMPARE(sts::word(rig.servo.reg(42), rig.servo.reg(43)), std::uint16_t(goal));
}

void TestStsActuator::disables()
{
    Rig rig(0.2);
    fw::StsActuator<double> actuator(rig.bus, {});
    double theta = 0;
    QVERIFY(actuator.start(theta));
    actuator.disable();
    actuator.disable(); // safe twice
    QCOMPARE(int(rig.servo.reg(sts::kRegTorqueEnable)), 0);
    QVERIFY(!rig.plant.torqueEnabled());
    rig.plant.step(1e-4, 0.1);
    QCOMPARE(rig.plant.motorTorque(), 0.0);
}

void TestStsActuator::failsWithoutTouchingData()
{
    ScriptedPort port;
    StsBus bus(port);
    fw::StsActuator<double> actuator(bus, {});
    fw::Measurement<double> m{1, 2, 3};
    port.script = {QByteArray::fromHex("ffff010800e8030a80f40589")}; // corrupt
    QVERIFY(!actuator.measure(m));
    port.script = {};
    QVERIFY(!actuator.measure(m));                                   // missing
    port.script = {QByteArray::fromHex("ffff020800e8030a80f40587")}; // foreign
    QVERIFY(!actuator.measure(m));
    QCOMPARE(m.theta, 1.0);
    QCOMPARE(m.omega, 2.0);
    QCOMPARE(m.tau, 3.0);
    QVERIFY(!actuator.command(0.1, 0));
    QCOMPARE(int(bus.stats().errors()), 4);
    // A good reply after errors is used again: the actuator does not latch failures.
    port.script = {kFeedback};
    QVERIFY(actuator.measure(m));
    QCOMPARE(m.theta, 0.0);
    QCOMPARE(m.omega, double(float(-10 * (kTwoPi / 4096))));
    QCOMPARE(m.tau, double(float(-500 * (0.44 * 1e-3))));
}

QTEST_GUILESS_MAIN(TestStsActuator)
#include "tst_stsactuator.moc"
