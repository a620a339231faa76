// Tests for the re-centering stiffness and torque (model.md § 2).

#include "model/stiffness.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <random>

namespace {

using hatpic::DeviceParams;
using hatpic::StiffnessZone;

DeviceParams params(double K_min, double K_max, double N, double Q_dz, double theta0)
{
    DeviceParams p;
    p.K_min = K_min;
    p.K_max = K_max;
    p.N = N;
    p.Q_dz = Q_dz;
    p.theta0 = theta0;
    return p;
}

bool closeTo(double actual, double expected, double tolerance = 1e-12)
{
    return std::abs(actual - expected) <= tolerance * std::max(1.0, std::abs(expected));
}

} // namespace

Q_DECLARE_METATYPE(hatpic::DeviceParams)
Q_DECLARE_METATYPE(hatpic::StiffnessZone)

class TestStiffness : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void stiffness_data();
    void stiffness();
    void torquePullsTowardCenter();
    void notchJumpAtDeadZoneEdgeOnly();
    void outerBandFallsMonotonically();
};

void TestStiffness::stiffness_data()
{
    QTest::addColumn<DeviceParams>("p");
    QTest::addColumn<double>("theta");
    QTest::addColumn<StiffnessZone>("zone");
    QTest::addColumn<double>("K");   // expected K_rec [N·m/rad]
    QTest::addColumn<double>("tau"); // expected τ_rec [N·m]

    // Defaults: K_min 0.15, K_max 0.4, N 0.1, Q_dz 0.02, θ0 0.
    const DeviceParams d;
    const double underQ = std::nextafter(0.02, 0.0);
    const double overN = std::nextafter(0.1, 1.0);
    QTest::newRow("a = 0") << d << 0.0 << StiffnessZone::DeadZone << 0.0 << 0.0;
    QTest::newRow("just under Q_dz") << d << underQ << StiffnessZone::DeadZone << 0.0 << 0.0;
    QTest::newRow("at Q_dz: notch") << d << 0.02 << StiffnessZone::Notch << 0.4 << -0.008;
    QTest::newRow("inside notch") << d << 0.05 << StiffnessZone::Notch << 0.4 << -0.02;
    QTest::newRow("at N: still notch") << d << 0.1 << StiffnessZone::Notch << 0.4 << -0.04;
    QTest::newRow("just over N: outer, ~K_max")
        << d << overN << StiffnessZone::Outer << 0.4 << -0.04;
    QTest::newRow("1.5 N: halfway") << d << 0.15 << StiffnessZone::Outer << 0.275 << -0.04125;
    QTest::newRow("2 N: K_min") << d << 0.2 << StiffnessZone::Outer << 0.15 << -0.03;
    QTest::newRow("2.6 N: literal K_t = 0, clamped")
        << d << 0.26 << StiffnessZone::Outer << 0.15 << -0.039;
    QTest::newRow("10 N: literal K_t = -1.85, clamped")
        << d << 1.0 << StiffnessZone::Outer << 0.15 << -0.15;
    QTest::newRow("pi/2") << d << std::numbers::pi / 2 << StiffnessZone::Outer << 0.15
                          << -0.15 * std::numbers::pi / 2;
    QTest::newRow("negative: just under Q_dz")
        << d << -underQ << StiffnessZone::DeadZone << 0.0 << 0.0;
    QTest::newRow("negative: at Q_dz") << d << -0.02 << StiffnessZone::Notch << 0.4 << 0.008;
    QTest::newRow("negative: at N") << d << -0.1 << StiffnessZone::Notch << 0.4 << 0.04;
    QTest::newRow("negative: 1.5 N") << d << -0.15 << StiffnessZone::Outer << 0.275 << 0.04125;
    QTest::newRow("negative: 2 N") << d << -0.2 << StiffnessZone::Outer << 0.15 << 0.03;
    QTest::newRow("negative: 10 N") << d << -1.0 << StiffnessZone::Outer << 0.15 << 0.15;

    // θ0 ≠ 0: everything is measured from θ0 (the paper's −K·θ would be wrong here).
    const DeviceParams c = params(0.15, 0.4, 0.1, 0.02, 0.5);
    QTest::newRow("theta0 0.5: at center") << c << 0.5 << StiffnessZone::DeadZone << 0.0 << 0.0;
    QTest::newRow("theta0 0.5: at theta = 0") << c << 0.0 << StiffnessZone::Outer << 0.15 << 0.075;
    QTest::newRow("theta0 0.5: dead zone") << c << 0.51 << StiffnessZone::DeadZone << 0.0 << 0.0;
    QTest::newRow("theta0 0.5: notch") << c << 0.55 << StiffnessZone::Notch << 0.4 << -0.02;
    QTest::newRow("theta0 0.5: 1.5 N below")
        << c << 0.35 << StiffnessZone::Outer << 0.275 << 0.04125;
    QTest::newRow("theta0 -pi: 2 N above")
        << params(0.15, 0.4, 0.1, 0.02, -std::numbers::pi) << -std::numbers::pi + 0.2
        << StiffnessZone::Outer << 0.15 << -0.03;

    // Special parameter sets.
    const DeviceParams flat = params(0.3, 0.3, 0.1, 0.02, 0.0);
    QTest::newRow("K_min = K_max: constant beyond Q_dz")
        << flat << 0.17 << StiffnessZone::Outer << 0.3 << -0.051;
    const DeviceParams zeroMin = params(0.0, 0.4, 0.1, 0.02, 0.0);
    QTest::newRow("K_min = 0: no torque past 2N")
        << zeroMin << 0.5 << StiffnessZone::Outer << 0.0 << 0.0;
    const DeviceParams noDead = params(0.15, 0.4, 0.1, 0.0, 0.0);
    QTest::newRow("Q_dz = 0: a = 0 is in the notch")
        << noDead << 0.0 << StiffnessZone::Notch << 0.4 << 0.0;
    const DeviceParams zero = params(0.0, 0.0, 0.1, 0.02, 0.0);
    QTest::newRow("K_max = 0: no torque anywhere")
        << zero << 0.15 << StiffnessZone::Outer << 0.0 << 0.0;
    const DeviceParams wide = params(0.1, 1.0, std::numbers::pi / 2, 0.5, 0.0);
    QTest::newRow("N = pi/2: all of the usable range is notch")
        << wide << std::numbers::pi / 2 << StiffnessZone::Notch << 1.0 << -std::numbers::pi / 2;
}

void TestStiffness::stiffness()
{
    QFETCH(DeviceParams, p);
    QFETCH(double, theta);
    QFETCH(StiffnessZone, zone);
    QFETCH(double, K);
    QFETCH(double, tau);
    QVERIFY(hatpic::validate(p).empty());
    QCOMPARE(hatpic::stiffnessZone(p, theta), zone);
    const double k = hatpic::recenteringStiffness(p, theta);
    QVERIFY2(closeTo(k, K), qPrintable(QString::number(k, 'g', 17)));
    QVERIFY(k >= p.K_min || zone == StiffnessZone::DeadZone);
    QVERIFY(k <= p.K_max);
    const double t = hatpic::recenteringTorque(p, theta);
    QVERIFY2(closeTo(t, tau), qPrintable(QString::number(t, 'g', 17)));
    if (tau == 0.0)
        QCOMPARE(t, 0.0);
}

// τ_rec never pushes away from θ0, for any valid parameters and any angle.
void TestStiffness::torquePullsTowardCenter()
{
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        DeviceParams p;
        p.K_max = 50 * unit(rng);
        p.K_min = p.K_max * unit(rng);
        p.N = std::numbers::pi / 2 * std::max(unit(rng), 1e-6);
        p.Q_dz = p.N * unit(rng) * 0.999;
        p.theta0 = std::numbers::pi * (2 * unit(rng) - 1);
        QVERIFY(hatpic::validate(p).empty());
        const double theta = p.theta0 + 4 * (2 * unit(rng) - 1);
        const double e = theta - p.theta0;
        const double tau = hatpic::recenteringTorque(p, theta);
        QVERIFY(tau * e <= 0.0);
        const double k = hatpic::recenteringStiffness(p, theta);
        QCOMPARE(tau, -k * e);
        QVERIFY(k >= 0.0 && k <= p.K_max);
    }
}

// K_rec is continuous everywhere except the deliberate 0 → K_max step at a = Q_dz.
void TestStiffness::notchJumpAtDeadZoneEdgeOnly()
{
    const DeviceParams p;
    const double q = p.Q_dz;
    QCOMPARE(hatpic::recenteringStiffness(p, std::nextafter(q, 0.0)), 0.0);
    QCOMPARE(hatpic::recenteringStiffness(p, q), p.K_max);
    // Continuous at N and at 2N.
    for (double edge : {p.N, 2 * p.N}) {
        const double below = hatpic::recenteringStiffness(p, edge - 1e-9);
        const double above = hatpic::recenteringStiffness(p, edge + 1e-9);
        QVERIFY(std::abs(above - below) < 1e-7);
    }
}

void TestStiffness::outerBandFallsMonotonically()
{
    const DeviceParams p;
    double previous = hatpic::recenteringStiffness(p, p.N);
    for (double a = p.N; a <= 1.0; a += 1e-4) {
        const double k = hatpic::recenteringStiffness(p, a);
        QVERIFY(k <= previous);
        previous = k;
    }
    QCOMPARE(previous, p.K_min);
}

QTEST_GUILESS_MAIN(TestStiffness)
#include "tst_stiffness.moc"
