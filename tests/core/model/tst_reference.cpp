// Tests for host-side reference generation (model.md § 4).

#include "model/reference.h"

#include <QTest>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace {

using hatpic::DeviceParams;
using hatpic::HostParams;
using hatpic::ReferenceGenerator;

HostParams host(double v_max, bool hold,
                hatpic::ReferenceMode mode = hatpic::ReferenceMode::Translation)
{
    HostParams h;
    h.v_max = v_max;
    h.ref_deadzone = hold;
    h.mode = mode;
    return h;
}

DeviceParams device(double theta0, double Q_dz = 0.02)
{
    DeviceParams d;
    d.theta0 = theta0;
    d.Q_dz = Q_dz;
    return d;
}

constexpr std::uint64_t kWrap = std::uint64_t(1) << 32;

} // namespace

Q_DECLARE_METATYPE(hatpic::HostParams)
Q_DECLARE_METATYPE(hatpic::DeviceParams)

class TestReference : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void velocity_data();
    void velocity();
    void firstSampleStartsAtZero();
    void trapezoidExactForLinearRamp_data();
    void trapezoidExactForLinearRamp();
    void deadZoneHoldStopsDrift();
    void timestampWrapAround();
    void gapRule_data();
    void gapRule();
    void gapAcrossWrapAndBackwardsTime();
    void resetPositionKeepsIntegrating();
    void clearForgetsEverything();
};

void TestReference::velocity_data()
{
    QTest::addColumn<HostParams>("h");
    QTest::addColumn<DeviceParams>("d");
    QTest::addColumn<double>("theta");
    QTest::addColumn<double>("v");

    const HostParams on = host(1.0, true);
    const HostParams off = host(1.0, false);
    const DeviceParams centered = device(0.0);
    QTest::newRow("linear: e = 0.5") << on << centered << 0.5 << 0.25;
    QTest::newRow("linear: e = -1") << on << centered << -1.0 << -0.5;
    QTest::newRow("e = 2 reaches v_max exactly") << on << centered << 2.0 << 1.0;
    QTest::newRow("e = 3 saturates at +v_max") << on << centered << 3.0 << 1.0;
    QTest::newRow("e = -3 saturates at -v_max") << on << centered << -3.0 << -1.0;
    QTest::newRow("v_max 100, e = 1") << host(100.0, true) << centered << 1.0 << 50.0;
    QTest::newRow("v_max 100, e = 2.5 saturates") << host(100.0, true) << centered << 2.5 << 100.0;
    QTest::newRow("rotation mode: same formula")
        << host(2.0, true, hatpic::ReferenceMode::Rotation) << centered << 0.3 << 0.3;
    QTest::newRow("hold on: inside dead zone") << on << centered << 0.01 << 0.0;
    QTest::newRow("hold on: just under Q_dz") << on << centered << std::nextafter(0.02, 0.0) << 0.0;
    QTest::newRow("hold on: negative, inside dead zone") << on << centered << -0.019 << 0.0;
    QTest::newRow("hold on: at Q_dz is outside") << on << centered << 0.02 << 0.01;
    QTest::newRow("hold off: inside dead zone") << off << centered << 0.01 << 0.005;
    QTest::newRow("hold off: at center") << off << centered << 0.0 << 0.0;
    QTest::newRow("hold on, Q_dz = 0: no hold") << on << device(0.0, 0.0) << 0.001 << 0.0005;
    QTest::newRow("theta0 1: e = 0.5") << on << device(1.0) << 1.5 << 0.25;
    QTest::newRow("theta0 1: theta 0 gives e = -1") << on << device(1.0) << 0.0 << -0.5;
    QTest::newRow("theta0 1: dead zone around theta0") << on << device(1.0) << 1.01 << 0.0;
    QTest::newRow("theta0 1: theta 0.01 is not in the dead zone")
        << on << device(1.0) << 0.01 << -0.495;
    QTest::newRow("theta0 -pi: saturates")
        << on << device(-std::numbers::pi) << std::numbers::pi << 1.0;
}

void TestReference::velocity()
{
    QFETCH(HostParams, h);
    QFETCH(DeviceParams, d);
    QFETCH(double, theta);
    QFETCH(double, v);
    const double got = hatpic::referenceVelocity(h, d, theta);
    QVERIFY2(std::abs(got - v) <= 1e-15 * std::max(1.0, std::abs(v)),
             qPrintable(QString::number(got, 'g', 17)));
    QVERIFY(std::abs(got) <= h.v_max);
}

void TestReference::firstSampleStartsAtZero()
{
    ReferenceGenerator g;
    const auto out = g.update(123456789u, host(1.0, false), device(0.0), 1.0);
    QCOMPARE(out.v_ref, 0.5);
    QCOMPARE(out.p_ref, 0.0);
    QVERIFY(!out.gap);
    QCOMPARE(g.gapCount(), std::uint64_t(0));
    // A repeated timestamp adds nothing.
    const auto again = g.update(123456789u, host(1.0, false), device(0.0), 1.0);
    QCOMPARE(again.p_ref, 0.0);
    QVERIFY(!again.gap);
}

void TestReference::trapezoidExactForLinearRamp_data()
{
    QTest::addColumn<double>("theta0");
    QTest::addColumn<double>("e0");    // e at t = 0 [rad]
    QTest::addColumn<double>("slope"); // de/dt [rad/s]
    QTest::addColumn<quint32>("start");

    QTest::newRow("rising from center") << 0.0 << 0.0 << 1.5 << 0u;
    QTest::newRow("falling through center, theta0 0.7") << 0.7 << 0.9 << -1.6 << 5000u;
    QTest::newRow("starting near the wrap") << -0.3 << -1.0 << 1.9 << 4294000000u;
}

// With the hold off and no saturation, v_ref is linear in e; for a linear ramp e(t) it is
// linear in t, which the trapezoidal rule integrates exactly, whatever the (jittery) steps.
void TestReference::trapezoidExactForLinearRamp()
{
    QFETCH(double, theta0);
    QFETCH(double, e0);
    QFETCH(double, slope);
    QFETCH(quint32, start);
    const HostParams h = host(1.0, false);
    const DeviceParams d = device(theta0);
    const double k = h.v_max / 2;

    std::mt19937 rng(3);
    std::uniform_int_distribution<int> jitter(500, 4000); // µs between samples
    ReferenceGenerator g;
    std::uint64_t elapsedUs = 0;
    double worst = 0;
    while (elapsedUs < 1000000) {
        const double t = elapsedUs * 1e-6;
        const double e = e0 + slope * t;
        const auto stamp = static_cast<std::uint32_t>((start + elapsedUs) % kWrap);
        const auto out = g.update(stamp, h, d, theta0 + e);
        QVERIFY(!out.gap);
        const double exact = k * (e0 * t + slope * t * t / 2);
        worst = std::max(worst, std::abs(out.p_ref - exact));
        elapsedUs += static_cast<std::uint64_t>(jitter(rng));
    }
    QVERIFY2(worst < 1e-12, qPrintable(QString::number(worst)));
    QCOMPARE(g.gapCount(), std::uint64_t(0));
}

void TestReference::deadZoneHoldStopsDrift()
{
    // Resting inside the dead zone: with the hold p_ref stays 0, without it p_ref drifts.
    ReferenceGenerator held;
    ReferenceGenerator drifting;
    const DeviceParams d = device(0.0);
    for (std::uint32_t t = 0; t <= 1000000; t += 1000) {
        held.update(t, host(1.0, true), d, 0.015);
        drifting.update(t, host(1.0, false), d, 0.015);
    }
    QCOMPARE(held.position(), 0.0);
    QVERIFY(std::abs(drifting.position() - 0.0075) < 1e-12); // 0.5·0.015 rad·1 s
}

// Δt is taken modulo 2³²: a run across the wrap integrates exactly like one that does not.
void TestReference::timestampWrapAround()
{
    const HostParams h = host(1.0, false);
    const DeviceParams d = device(0.0);
    ReferenceGenerator wrapped;
    ReferenceGenerator plain;
    const std::uint32_t start = 0xFFFFFFFFu - 2500u; // wraps during the third step
    for (int i = 0; i < 10; ++i) {
        const std::uint32_t offset = static_cast<std::uint32_t>(i) * 1000u;
        const double theta = 0.1 * i;
        const auto a = wrapped.update(start + offset, h, d, theta); // unsigned: wraps
        const auto b = plain.update(1000000u + offset, h, d, theta);
        QVERIFY(!a.gap);
        QCOMPARE(a.p_ref, b.p_ref);
    }
    // 0.5·Σ 0.1·i over 9 intervals of 1 ms, trapezoid: 0.5·0.1·1e-3·(Σ_{i=1..9}(2i−1)/2)
    QVERIFY(std::abs(wrapped.position() - 0.5 * 0.1 * 1e-3 * 81.0 / 2) < 1e-15);
    QCOMPARE(wrapped.gapCount(), std::uint64_t(0));
}

void TestReference::gapRule_data()
{
    QTest::addColumn<quint32>("dtUs");
    QTest::addColumn<bool>("gap");

    QTest::newRow("1 ms") << 1000u << false;
    QTest::newRow("exactly 0.25 s is integrated") << 250000u << false;
    QTest::newRow("0.25 s + 1 us is a gap") << 250001u << true;
    QTest::newRow("10 s is a gap") << 10000000u << true;
    QTest::newRow("largest representable step is a gap") << 0xFFFFFFFFu << true;
}

void TestReference::gapRule()
{
    QFETCH(quint32, dtUs);
    QFETCH(bool, gap);
    const HostParams h = host(1.0, false);
    const DeviceParams d = device(0.0);
    ReferenceGenerator g;
    g.update(1000u, h, d, 0.2); // v = 0.1
    g.update(2000u, h, d, 0.2); // + 0.1·1 ms
    const double before = g.position();
    QVERIFY(std::abs(before - 1e-4) < 1e-18);
    const auto out = g.update(2000u + dtUs, h, d, 0.6); // v = 0.3
    QCOMPARE(out.gap, gap);
    QCOMPARE(out.v_ref, 0.3);
    if (gap) {
        QCOMPARE(out.p_ref, before);
        QCOMPARE(g.gapCount(), std::uint64_t(1));
    } else {
        const double expected = before + (0.1 + 0.3) / 2 * (dtUs * 1e-6);
        QVERIFY(std::abs(out.p_ref - expected) < 1e-15);
        QCOMPARE(g.gapCount(), std::uint64_t(0));
    }
    // Integration resumes from the sample after the gap.
    const auto next = g.update(2000u + dtUs + 1000u, h, d, 0.6);
    QVERIFY(!next.gap);
    QVERIFY(std::abs(next.p_ref - (out.p_ref + 0.3 * 1e-3)) < 1e-15);
}

void TestReference::gapAcrossWrapAndBackwardsTime()
{
    const HostParams h = host(1.0, false);
    const DeviceParams d = device(0.0);
    ReferenceGenerator g;
    g.update(0xFFFFFF00u, h, d, 0.2);
    // 0x100 µs before the wrap + 300000 µs after it: a 0.300256 s gap.
    auto out = g.update(300000u, h, d, 0.2);
    QVERIFY(out.gap);
    QCOMPARE(out.p_ref, 0.0);
    // A timestamp that goes backwards is, modulo 2³², almost 2³² µs ahead: also a gap.
    out = g.update(299999u, h, d, 0.2);
    QVERIFY(out.gap);
    QCOMPARE(g.gapCount(), std::uint64_t(2));
    QCOMPARE(g.position(), 0.0);
}

void TestReference::resetPositionKeepsIntegrating()
{
    const HostParams h = host(1.0, false);
    const DeviceParams d = device(0.0);
    ReferenceGenerator g;
    g.update(0u, h, d, 1.0);
    g.update(100000u, h, d, 1.0);
    QVERIFY(std::abs(g.position() - 0.05) < 1e-15);
    g.update(0xFFFFFFFFu, h, d, 1.0); // a gap, to see the count survive the reset
    g.resetPosition();
    QCOMPARE(g.position(), 0.0);
    QCOMPARE(g.gapCount(), std::uint64_t(1));
    const auto out = g.update(0xFFFFFFFFu + 100000u, h, d, 1.0); // wraps; Δt = 0.1 s
    QVERIFY(!out.gap);
    QVERIFY(std::abs(out.p_ref - 0.05) < 1e-15);
}

void TestReference::clearForgetsEverything()
{
    const HostParams h = host(1.0, false);
    const DeviceParams d = device(0.0);
    ReferenceGenerator g;
    g.update(0u, h, d, 1.0);
    g.update(10000000u, h, d, 1.0); // gap
    g.update(10100000u, h, d, 1.0);
    QVERIFY(g.position() > 0);
    QCOMPARE(g.gapCount(), std::uint64_t(1));
    g.clear();
    QCOMPARE(g.position(), 0.0);
    QCOMPARE(g.gapCount(), std::uint64_t(0));
    // The next sample is a first sample again: no integration, no gap, whatever its time.
    const auto out = g.update(99u, h, d, 1.0);
    QVERIFY(!out.gap);
    QCOMPARE(out.p_ref, 0.0);
}

QTEST_GUILESS_MAIN(TestReference)
#include "tst_reference.moc"
