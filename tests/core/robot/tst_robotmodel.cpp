// The simulated robot held to robot.md: its rules, one step by hand, the controller's clamp, a
// wall that pushes and never pulls, the rest against the wall, and the loop's equilibrium.
#include "robot/loopequilibrium.h"
#include "robot/robotmodel.h"

#include "model/stiffness.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace hatpic;
using namespace hatpic::robot;

class TestRobotModel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void defaultsAreRobotMd();
    void badValuesAreNamed_data();
    void badValuesAreNamed();
    void oneStepBySemiImplicitEuler();
    void stiffnessBoundIsTheStepsStability_data();
    void stiffnessBoundIsTheStepsStability();
    void unstableStepIsRefused();
    void controllerIsClamped();
    void wallPushesNeverPulls();
    void restsAgainstTheWall();
    void equilibriumOfRobotMd();
    void equilibriumOutsideTheNotch();
    void noEquilibriumAwayFromTheWall();
};

void TestRobotModel::defaultsAreRobotMd()
{
    const RobotParams p;
    QCOMPARE(p.mass, 1.5);
    QCOMPARE(p.kv, 40.0);
    QCOMPARE(p.fMax, 20.0);
    QCOMPARE(p.wall, 0.05);
    QCOMPARE(p.wallStiffness, 200.0);
    QCOMPARE(p.wallDamping, 5.0);
    QCOMPARE(p.start, 0.0);
    QVERIFY(validate(p).empty());
    QCOMPARE(RobotModel::kStep, 1e-3);
}

void TestRobotModel::badValuesAreNamed_data()
{
    QTest::addColumn<QString>("field");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("message");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QTest::newRow("mass 0") << "mass" << 0.0 << "mass: must be > 0, got 0";
    QTest::newRow("mass NaN") << "mass" << nan << "mass: must be a finite number, got nan";
    QTest::newRow("kv negative") << "kv" << -1.0 << "kv: must be ≥ 0, got -1";
    QTest::newRow("fmax 0") << "fmax" << 0.0 << "fmax: must be > 0, got 0";
    QTest::newRow("wall inf") << "wall" << std::numeric_limits<double>::infinity()
                              << "wall: must be a finite number, got inf";
    QTest::newRow("k_w negative") << "wall-stiffness" << -2.0
                                  << "wall-stiffness: must be ≥ 0, got -2";
    QTest::newRow("b_w negative") << "wall-damping" << -0.5
                                  << "wall-damping: must be ≥ 0, got -0.5";
    QTest::newRow("start NaN") << "start" << nan << "start: must be a finite number, got nan";
}

void TestRobotModel::badValuesAreNamed()
{
    QFETCH(QString, field);
    QFETCH(double, value);
    QFETCH(QString, message);
    RobotParams p;
    double *target = field == u"mass"             ? &p.mass
                     : field == u"kv"             ? &p.kv
                     : field == u"fmax"           ? &p.fMax
                     : field == u"wall"           ? &p.wall
                     : field == u"wall-stiffness" ? &p.wallStiffness
                     : field == u"wall-damping"   ? &p.wallDamping
                                                  : &p.start;
    *target = value;
    const auto violations = validate(p);
    QCOMPARE(violations.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(violations.front().field), field);
    QCOMPARE(QString::fromStdString(violations.front().message()), message);
}

void TestRobotModel::oneStepBySemiImplicitEuler()
{
    RobotModel robot;
    robot.step(0.1);
    // F_c = 40 · 0.1 = 4 N; v = h · 4 / 1.5; x = h · v (the new v).
    QCOMPARE(robot.controlForce(), 4.0);
    const double v = 1e-3 * 4.0 / 1.5;
    QCOMPARE(robot.velocity(), v);
    QCOMPARE(robot.position(), 1e-3 * v);
    QCOMPARE(robot.wallForce(), 0.0);
}

void TestRobotModel::stiffnessBoundIsTheStepsStability_data()
{
    QTest::addColumn<double>("mass");
    QTest::addColumn<double>("kv");
    QTest::addColumn<double>("wallDamping");
    QTest::newRow("robot.md") << 1.5 << 40.0 << 5.0;
    QTest::newRow("light, damped") << 0.2 << 100.0 << 50.0;
    QTest::newRow("heavy, wall undamped") << 20.0 << 400.0 << 0.0;
}

// Pressed into the wall (v_ref 1 m/s, F_max out of the way) from 10 % past its rest, the robot
// settles against the wall just below the bound and never does just above it: the bound is
// the integrator's, not a guess.
void TestRobotModel::stiffnessBoundIsTheStepsStability()
{
    QFETCH(double, mass);
    QFETCH(double, kv);
    QFETCH(double, wallDamping);
    const RobotParams p{.mass = mass, .kv = kv, .fMax = 1e9, .wallDamping = wallDamping};
    const double bound = stiffnessBound(p);
    QVERIFY(bound > 0);
    const double vRef = 1;
    const double restForce = kv * vRef; // at rest v = 0: F_e = F_c = K_v·v_ref
    // The largest |F_e − K_v·v_ref| / (K_v·v_ref) over the last 0.2 s of 3 s.
    const auto unrest = [&](double k) {
        RobotParams q = p;
        q.wallStiffness = k;
        q.start = q.wall + 1.1 * restForce / k;
        RobotModel robot(q);
        double worst = 0;
        for (int i = 0; i < 3000; ++i) {
            robot.step(vRef);
            if (i >= 2800)
                worst = std::max(worst, std::abs(robot.wallForce() - restForce) / restForce);
        }
        return worst;
    };
    QVERIFY2(unrest(0.98 * bound) < 1e-6, qPrintable(QString::number(unrest(0.98 * bound))));
    QVERIFY2(unrest(1.02 * bound) > 0.5, qPrintable(QString::number(unrest(1.02 * bound))));
    RobotParams below = p;
    below.wallStiffness = 0.98 * bound;
    QVERIFY(validate(below).empty());
    below.wallStiffness = 1.02 * bound;
    QCOMPARE(validate(below).size(), std::size_t(1));
}

void TestRobotModel::unstableStepIsRefused()
{
    // robot.md's robot: K_v + b_w = 45, so k_w < (4·1.5 − 2·0.001·45)/1e-6 = 5 910 000 N/m.
    RobotParams p;
    QCOMPARE(stiffnessBound(p), 5.91e6);
    p.wallStiffness = 1e7;
    auto violations = validate(p);
    QCOMPARE(violations.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(violations.front().message()),
             QString::fromUtf8("wall-stiffness: must be below (4·m − 2·h·(K_v + b_w))/h² = 5910000 "
                               "N/m for the 1 ms step to be stable, got 1e+07"));
    p = RobotParams{};
    p.kv = 3000; // 2·m/h = 3000 N·s/m
    violations = validate(p);
    QCOMPARE(violations.size(), std::size_t(1));
    QCOMPARE(violations.front().field, std::string("kv"));
    QVERIFY(QString::fromStdString(violations.front().message())
                .contains(QString::fromUtf8("2·m/h = 3000 N·s/m")));
}

void TestRobotModel::controllerIsClamped()
{
    const RobotParams p;
    QCOMPARE(controlForce(p, 10.0, 0.0), 20.0);
    QCOMPARE(controlForce(p, -10.0, 0.0), -20.0);
    QCOMPARE(controlForce(p, 0.2, 0.1), 4.0);
}

void TestRobotModel::wallPushesNeverPulls()
{
    const RobotParams p;
    QCOMPARE(wallForce(p, 0.04, 1.0), 0.0);                   // before the wall
    QCOMPARE(wallForce(p, 0.06, 0.0), 200.0 * (0.06 - 0.05)); // k_w · d
    QCOMPARE(wallForce(p, 0.06, 0.1), 200.0 * 0.01 + 5.0 * 0.1);
    QCOMPARE(wallForce(p, 0.051, -1.0), 0.0); // leaving fast: the damping would pull
    RobotModel robot(RobotParams{.start = 0.06});
    QCOMPARE(robot.estimatedForce(), -2.0);
}

void TestRobotModel::restsAgainstTheWall()
{
    RobotModel robot;
    const double vRef = 0.03125;
    for (int i = 0; i < 20000; ++i) // 20 s
        robot.step(vRef);
    // Against the wall F_c = F_e: K_v · v_ref = k_w · (x − x_w).
    QVERIFY(std::abs(robot.velocity()) < 1e-9);
    QVERIFY(std::abs(robot.position() - (0.05 + 40 * vRef / 200)) < 1e-9);
    QVERIFY(std::abs(robot.wallForce() - 1.25) < 1e-6);
}

void TestRobotModel::equilibriumOfRobotMd()
{
    // robot.md's example: default parameters, v_max 1 m/s, τ_h 0.05 N·m, gain 0.02 N·m/N.
    const auto e = loopEquilibrium(DeviceParams(), HostParams(), 0.05, 0.02, 0.154, RobotParams());
    QVERIFY(e);
    QVERIFY(std::abs(e->theta - 0.0625) < 1e-9);
    QVERIFY(std::abs(e->vRef - 0.03125) < 1e-9);
    QVERIFY(std::abs(e->wallForce - 1.25) < 1e-9);
    QVERIFY(std::abs(e->tauExt - -0.025) < 1e-9);
    QVERIFY(std::abs(e->robotPosition - 0.05625) < 1e-9);
}

void TestRobotModel::equilibriumOutsideTheNotch()
{
    // A harder push with the feedback limited: τ_ext stops at −limit, and the knob goes past
    // the notch band, where K_rec falls. The balance holds wherever it rests.
    const DeviceParams device;
    const auto e = loopEquilibrium(device, HostParams(), 0.1, 0.02, 0.03, RobotParams());
    QVERIFY(e);
    QCOMPARE(e->tauExt, -0.03);
    QVERIFY(e->theta > device.N);
    QVERIFY(std::abs(recenteringTorque(device, e->theta) + 0.1 + e->tauExt) < 1e-9);
    QCOMPARE(e->wallForce, 40 * e->vRef);
    QCOMPARE(e->robotPosition, 0.05 + e->wallForce / 200);
}

void TestRobotModel::noEquilibriumAwayFromTheWall()
{
    // Pushed the other way the robot backs away from the wall for ever.
    QVERIFY(!loopEquilibrium(DeviceParams(), HostParams(), -0.05, 0.02, 0.154, RobotParams()));
}

QTEST_GUILESS_MAIN(TestRobotModel)
#include "tst_robotmodel.moc"
