// The static torque τ_rec + τ_det + τ_wall (ω = 0), the detents' rest positions, the walls and
// the sample angles that resolve them, against hand-computed values.
#include "model/staticcurve.h"
#include "model/stiffness.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

using namespace hatpic;

namespace {

constexpr double kPi = std::numbers::pi;

EffectParams detents(double a, double s, double r)
{
    return {.detent_strength = a, .detent_spacing = s, .detent_range = r};
}

//! Walls at θ0 + lo and θ0 + hi with K_w = k; their damping never enters the static torque.
EffectParams walls(double lo, double hi, double k)
{
    return {.wall_min = lo, .wall_max = hi, .wall_stiffness = k, .wall_damping = 0.5};
}

//! K_min = K_max = k, no dead zone: τ_rec = −k·(θ − θ0) everywhere.
DeviceParams linear(double k, double theta0)
{
    return {.K_min = k, .K_max = k, .N = 0.2, .Q_dz = 0, .theta0 = theta0};
}

bool near(double a, double b)
{
    return std::abs(a - b) < 1e-12;
}

} // namespace

class TestStaticCurve : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void defaultsAddNothing();
    void detentsAddToTheRecentering();
    void wallsPushBackWithoutDamping();
    void restPositions();
    void wallAnglesOnlyWhenActiveAndInside();
    void halfRange();
    void samplesResolveFineDetents();
    void samplesAreBounded();
    void samplesMarkTheRangeEdge();
    void splitsTauFx();
};

void TestStaticCurve::defaultsAddNothing()
{
    const DeviceParams p;
    const EffectParams fx;
    QVERIFY(!shapesStaticTorque(fx));
    for (double theta : {-1.0, -0.1, 0.0, 0.03, 0.5, 3.0})
        QVERIFY(staticTorque(p, fx, theta) == recenteringTorque(p, theta)); // exactly
    QVERIFY(detentRestPositions(fx, 0, -kPi, kPi).empty());
    QVERIFY(!wallAngles(fx, 0, -10, 10).low && !wallAngles(fx, 0, -10, 10).high);
    QCOMPARE(effectsHalfRange(fx), 0.0);
    QVERIFY(effectSampleAngles(fx, 0, -1, 1).empty());
}

void TestStaticCurve::detentsAddToTheRecentering()
{
    // τ = −0.5·(θ − 0.1) − 0.04·sin(2π·e/0.2), e = θ − 0.1, for |e| ≤ 0.45.
    const DeviceParams p = linear(0.5, 0.1);
    const EffectParams fx = detents(0.04, 0.2, 0.45);
    QVERIFY(shapesStaticTorque(fx));
    // e = 0.05: a quarter period, sin = 1 → −0.025 − 0.04 = −0.065.
    QVERIFY(near(staticTorque(p, fx, 0.15), -0.065));
    // e = −0.15: three quarters back, sin(−1.5π) = 1 → 0.075 − 0.04 = 0.035.
    QVERIFY(near(staticTorque(p, fx, -0.05), 0.035));
    // e = 0.2: a rest position, sin = 0 → −0.1.
    QVERIFY(near(staticTorque(p, fx, 0.3), -0.1));
    // e = 0.5: beyond R, τ_rec alone.
    QVERIFY(near(staticTorque(p, fx, 0.6), -0.25));
}

void TestStaticCurve::wallsPushBackWithoutDamping()
{
    const DeviceParams p = linear(0.5, 0.0);
    const EffectParams fx = walls(-0.3, 0.4, 2.0);
    QVERIFY(shapesStaticTorque(fx));
    QVERIFY(near(staticTorque(p, fx, 0.35), -0.175));           // inside: τ_rec only
    QVERIFY(near(staticTorque(p, fx, 0.5), -0.25 - 2.0 * 0.1)); // 0.1 beyond wall_max
    QVERIFY(near(staticTorque(p, fx, -0.5), 0.25 + 2.0 * 0.2)); // 0.2 beyond wall_min
    QVERIFY(near(staticTorque(p, fx, 0.4), -0.2));              // on the wall: not beyond
}

void TestStaticCurve::restPositions()
{
    // s = 0.2, R = 0.8: 9 rest positions θ0 + i·0.2, i = −4 … 4 (R a multiple of s).
    const EffectParams fx = detents(0.03, 0.2, 0.8);
    const auto all = detentRestPositions(fx, 0.1, -kPi, kPi);
    QCOMPARE(all.size(), std::size_t(9));
    for (int i = 0; i < 9; ++i)
        QVERIFY(near(all[std::size_t(i)], 0.1 + (i - 4) * 0.2));
    QVERIFY(std::is_sorted(all.begin(), all.end()));
    // Each is stable: τ_det falls through zero there.
    const EffectShape<double> shape = EffectShape<double>::from(fx);
    for (double theta : all) {
        const double e = theta - 0.1;
        QVERIFY(std::abs(detentTorque(shape, e)) < 1e-12);
        // Pulled back from either side (at ±R the outer side has no detent torque).
        if (e - 0.01 >= -0.8)
            QVERIFY(detentTorque(shape, e - 0.01) > 0);
        if (e + 0.01 <= 0.8)
            QVERIFY(detentTorque(shape, e + 0.01) < 0);
    }
    // Clipped to the view.
    const auto seen = detentRestPositions(fx, 0.1, 0.0, 0.35);
    QCOMPARE(seen.size(), std::size_t(2));
    QVERIFY(near(seen[0], 0.1) && near(seen[1], 0.3));
    // R not a multiple of s: 0.5 holds i = −2 … 2.
    QCOMPARE(detentRestPositions(detents(0.03, 0.2, 0.5), 0, -kPi, kPi).size(), std::size_t(5));
    // Off: A = 0, or R = 0.
    QVERIFY(detentRestPositions(detents(0, 0.2, 0.8), 0, -kPi, kPi).empty());
    QVERIFY(detentRestPositions(detents(0.03, 0.2, 0), 0, -kPi, kPi).empty());
}

void TestStaticCurve::wallAnglesOnlyWhenActiveAndInside()
{
    WallAngles w = wallAngles(walls(-0.5, 0.5, 1.0), 0.2, -1, 1);
    QVERIFY(w.low && w.high);
    QVERIFY(near(*w.low, -0.3));
    QVERIFY(near(*w.high, 0.7));
    w = wallAngles(walls(-0.5, 0.5, 1.0), 0.2, -1, 0.6); // wall_max outside the view
    QVERIFY(w.low && !w.high);
    w = wallAngles(walls(-0.5, 0.5, 0.0), 0.2, -1, 1); // K_w = 0: no wall
    QVERIFY(!w.low && !w.high);
}

void TestStaticCurve::halfRange()
{
    QVERIFY(near(effectsHalfRange(detents(0.03, 0.2, 0.8)), 0.9));
    QVERIFY(near(effectsHalfRange(walls(-0.2, 0.4, 1.0)), 0.5));
    // The default walls at ±π are the ends of travel: they do not widen the view.
    QCOMPARE(effectsHalfRange(walls(-kPi, kPi, 1.0)), 0.0);
    QCOMPARE(effectsHalfRange(detents(0.03, 0.5, kPi)), kPi);
}

void TestStaticCurve::samplesResolveFineDetents()
{
    // s = 0.01 over ±π/2: 314 periods, each with kSamplesPerDetent samples on its phase grid,
    // so every crest (e = ±s/4) is sampled and the curve reaches ±A.
    const EffectParams fx = detents(0.02, 0.01, 1.0);
    const auto x = effectSampleAngles(fx, 0, -kPi / 2, kPi / 2);
    const DeviceParams p = linear(0.0, 0.0);
    double lo = 0;
    double hi = 0;
    for (double theta : x) {
        const double tau = staticTorque(p, fx, theta);
        lo = std::min(lo, tau);
        hi = std::max(hi, tau);
    }
    QVERIFY(near(lo, -0.02) && near(hi, 0.02));
    // Every period holds kSamplesPerDetent samples.
    const auto inPeriod = std::count_if(
        x.begin(), x.end(), [](double t) { return t >= 0.3 - 1e-12 && t < 0.31 - 1e-12; });
    QCOMPARE(inPeriod, kSamplesPerDetent);
}

void TestStaticCurve::samplesAreBounded()
{
    // An invalid, tiny spacing does not make the sampling unbounded.
    const EffectParams fx = detents(0.02, 1e-9, kPi);
    const auto x = effectSampleAngles(fx, 0, -kPi, kPi);
    QVERIFY(x.size() <= std::size_t(kMaxDetentSamples + 8));
    QVERIFY(x.size() >= std::size_t(kMaxDetentSamples / 2));
    QVERIFY(detentRestPositions(fx, 0, -kPi, kPi).size() <= std::size_t(kMaxDetentSamples));
}

void TestStaticCurve::samplesMarkTheRangeEdge()
{
    // R = 0.33 is not a multiple of s/2: τ_det stops at ±R with a jump; the samples hold the
    // edge and adjacent angles either side of it, τ_det ≠ 0 inside, 0 beyond.
    const EffectParams fx = detents(0.02, 0.2, 0.33);
    const auto x = effectSampleAngles(fx, 0, -1, 1);
    const EffectShape<double> shape = EffectShape<double>::from(fx);
    for (double sign : {-1.0, 1.0}) {
        const double edge = sign * 0.33;
        QVERIFY(std::find(x.begin(), x.end(), edge) != x.end());
        const auto beyond = std::find_if(x.begin(), x.end(), [&](double t) {
            return sign * t > 0.33 && sign * t < 0.33 + 1e-12;
        });
        QVERIFY(beyond != x.end());
        QCOMPARE(detentTorque(shape, *beyond), 0.0);
        const double inside = std::nextafter(*beyond, 0.0);
        QVERIFY(std::find(x.begin(), x.end(), inside) != x.end());
        QVERIFY(detentTorque(shape, inside) != 0.0);
    }
    // Walls are sample angles too (the kink).
    const auto w = effectSampleAngles(walls(-0.25, 0.5, 1.0), 0.1, -1, 1);
    QVERIFY(std::find(w.begin(), w.end(), 0.1 - 0.25) != w.end());
    QVERIFY(std::find(w.begin(), w.end(), 0.1 + 0.5) != w.end());
}

void TestStaticCurve::splitsTauFx()
{
    // Detents A = 0.04, s = 0.2 over ±0.45; walls at ±0.3 with K_w = 2, B_w = 0.5; θ0 = 0.1.
    EffectParams fx = detents(0.04, 0.2, 0.45);
    fx.wall_min = -0.3;
    fx.wall_max = 0.3;
    fx.wall_stiffness = 2.0;
    fx.wall_damping = 0.5;
    // θ = 0.15 (e = 0.05, a quarter period, inside the walls), τ_fx = −0.04 + 0.01 of a cue.
    EffectTorques t = splitEffectTorque(fx, 0.1, 0.15, 3.0, -0.03);
    QVERIFY(near(t.det, -0.04));
    QCOMPARE(t.wall, 0.0);
    QVERIFY(near(t.vib, 0.01));
    // θ = 0.5 (e = 0.4, 0.1 beyond wall_max, moving further in at ω = 2): τ_det = −0.04·sin(4π)
    // ≈ 0, τ_wall = −2·0.1 − 0.5·2 = −1.2; τ_fx = −1.2 → no cue.
    t = splitEffectTorque(fx, 0.1, 0.5, 2.0, -1.2);
    QVERIFY(near(t.wall, -1.2));
    QVERIFY(std::abs(t.det) < 1e-12);
    QVERIFY(std::abs(t.vib) < 1e-12);
    // Moving out of the wall: no damping, τ_wall = −0.2.
    t = splitEffectTorque(fx, 0.1, 0.5, -2.0, -0.2);
    QVERIFY(near(t.wall, -0.2));
    // Unknown τ_fx: every part unknown.
    t = splitEffectTorque(fx, 0.1, 0.15, 0.0, std::numeric_limits<double>::quiet_NaN());
    QVERIFY(std::isnan(t.det) && std::isnan(t.wall) && std::isnan(t.vib));
}

QTEST_GUILESS_MAIN(TestStaticCurve)
#include "tst_staticcurve.moc"
