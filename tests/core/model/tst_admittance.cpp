// Tests for the admittance filter step (model.md § 3): exact zero-order-hold solution of
// D ω̇ + M ω = u for constant u and no spring.

#include "model/admittance.h"

#include <QTest>

#include <cmath>
#include <limits>

namespace {

using hatpic::AdmittanceState;
using hatpic::DeviceParams;

DeviceParams filter(double D, double M)
{
    DeviceParams p;
    p.D_adm = D;
    p.M_adm = M;
    return p;
}

// Closed-form solution at time t from (θ0, ω0) under constant u, in long double.
struct Exact
{
    long double theta;
    long double omega;
    long double scale; // sum of the magnitudes of θ's terms, for a relative error
};

Exact exactSolution(const DeviceParams &p, double theta0, double omega0, double u, long double t)
{
    const long double D = p.D_adm;
    const long double M = p.M_adm;
    const long double alpha = M / D;
    const long double wInf = u / M;
    const long double decay = -std::expm1(-alpha * t); // 1 − e^{−αt}
    const long double w0 = omega0;
    Exact e;
    e.omega = wInf + (w0 - wInf) * (1.0L - decay);
    const long double a = wInf * t;
    const long double b = (w0 - wInf) * decay / alpha;
    e.theta = theta0 + a + b;
    e.scale = std::abs(static_cast<long double>(theta0)) + std::abs(a) + std::abs(b);
    return e;
}

double relativeError(double actual, long double exact, long double scale)
{
    if (scale == 0)
        return static_cast<double>(std::abs(actual - exact));
    return static_cast<double>(std::abs(actual - exact) / scale);
}

} // namespace

class TestAdmittance : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void matchesAnalyticSolution_data();
    void matchesAnalyticSolution();
    void largeStepsStayBounded_data();
    void largeStepsStayBounded();
    void tinyStepsKeepPrecision_data();
    void tinyStepsKeepPrecision();
    void nearlyUndampedFilter();
    void restStaysAtRest();
    void oneStepEqualsTwoHalfSteps();
};

void TestAdmittance::matchesAnalyticSolution_data()
{
    QTest::addColumn<double>("D");
    QTest::addColumn<double>("M");
    QTest::addColumn<double>("u");
    QTest::addColumn<double>("theta0");
    QTest::addColumn<double>("omega0");
    QTest::addColumn<double>("h");
    QTest::addColumn<int>("steps");

    QTest::newRow("defaults, push from rest, 1 kHz")
        << 1e-4 << 1e-2 << 0.05 << 0.0 << 0.0 << 1e-3 << 5000;
    QTest::newRow("defaults, negative torque, theta0 != 0")
        << 1e-4 << 1e-2 << -0.2 << 0.3 << 0.0 << 1e-3 << 5000;
    QTest::newRow("defaults, coasting to rest (u = 0)")
        << 1e-4 << 1e-2 << 0.0 << -0.1 << 4.0 << 1e-4 << 20000;
    QTest::newRow("defaults, opposing initial rate")
        << 1e-4 << 1e-2 << 0.3 << 0.0 << -12.0 << 5e-4 << 10000;
    QTest::newRow("heavy and slow (D 1, M 10)") << 1.0 << 10.0 << 1.0 << 0.0 << 0.5 << 2e-3 << 5000;
    QTest::newRow("light and stiff in time (alpha 1e7, alpha h 1e4)")
        << 1e-6 << 10.0 << 0.44 << 0.0 << 0.0 << 1e-3 << 2000;
    QTest::newRow("slow decay (alpha 1e-2)") << 1.0 << 1e-2 << 0.01 << 1.0 << 0.1 << 1e-3 << 20000;
    QTest::newRow("alpha h = 1 exactly") << 1e-3 << 1.0 << -0.1 << 0.0 << 2.0 << 1e-3 << 3000;
    QTest::newRow("irregular 3.7 ms step")
        << 2e-4 << 1.2e-2 << 0.07 << -0.4 << 0.0 << 3.7e-3 << 2000;
}

// Many steps of the filter agree with the closed-form solution at every sample to 1e-9.
void TestAdmittance::matchesAnalyticSolution()
{
    QFETCH(double, D);
    QFETCH(double, M);
    QFETCH(double, u);
    QFETCH(double, theta0);
    QFETCH(double, omega0);
    QFETCH(double, h);
    QFETCH(int, steps);
    const DeviceParams p = filter(D, M);
    QVERIFY(hatpic::validate(p).empty());

    AdmittanceState s{theta0, omega0};
    double worstTheta = 0;
    double worstOmega = 0;
    for (int k = 1; k <= steps; ++k) {
        s = hatpic::admittanceStep(p, s, u, h);
        const Exact e = exactSolution(p, theta0, omega0, u, static_cast<long double>(k) * h);
        worstTheta = std::max(worstTheta, relativeError(s.theta, e.theta, e.scale));
        const long double omegaScale =
            std::abs(static_cast<long double>(omega0)) + std::abs(static_cast<long double>(u) / M);
        worstOmega = std::max(worstOmega, relativeError(s.omega, e.omega, omegaScale));
    }
    QVERIFY2(worstTheta < 1e-9, qPrintable(QString::number(worstTheta)));
    QVERIFY2(worstOmega < 1e-9, qPrintable(QString::number(worstOmega)));
}

void TestAdmittance::largeStepsStayBounded_data()
{
    QTest::addColumn<double>("D");
    QTest::addColumn<double>("M");
    QTest::addColumn<double>("h");

    QTest::newRow("defaults, h = 1e3 s (alpha h = 1e5)") << 1e-4 << 1e-2 << 1e3;
    QTest::newRow("lightest, heaviest damping, h = 1e3 s (alpha h = 1e10)") << 1e-6 << 10.0 << 1e3;
    QTest::newRow("defaults, h = 1 s") << 1e-4 << 1e-2 << 1.0;
    QTest::newRow("alpha h = 1e4 at 1 kHz") << 1e-6 << 10.0 << 1e-3;
}

// Where explicit Euler would diverge (α·h > 2), the exact step lands on the steady state and
// never overshoots it.
void TestAdmittance::largeStepsStayBounded()
{
    QFETCH(double, D);
    QFETCH(double, M);
    QFETCH(double, h);
    const DeviceParams p = filter(D, M);
    const double alpha = M / D;
    const double u = 0.3;
    const double wInf = u / M;

    AdmittanceState s{0.0, -50.0};
    for (int k = 0; k < 1000; ++k) {
        const AdmittanceState next = hatpic::admittanceStep(p, s, u, h);
        QVERIFY(std::isfinite(next.theta) && std::isfinite(next.omega));
        // ω moves monotonically from ω_k toward u/M without passing it.
        QVERIFY(std::abs(next.omega - wInf) <=
                std::abs(s.omega - wInf) + 4 * std::numeric_limits<double>::epsilon() * wInf);
        s = next;
    }
    QVERIFY(std::abs(s.omega - wInf) <= 1e-12 * std::abs(wInf));

    // One step from rest: e^{−αh} underflows to 0, so the result is the steady state.
    if (alpha * h > 800) {
        const AdmittanceState one = hatpic::admittanceStep(p, {1.0, 2.0}, u, h);
        QCOMPARE(one.omega, wInf);
        const double expectedTheta = 1.0 + wInf * h + (2.0 - wInf) / alpha;
        QVERIFY(std::abs(one.theta - expectedTheta) <= 1e-14 * std::abs(expectedTheta));
    }
}

void TestAdmittance::tinyStepsKeepPrecision_data()
{
    QTest::addColumn<double>("D");
    QTest::addColumn<double>("M");
    QTest::addColumn<double>("h");
    QTest::addColumn<double>("omega0");

    QTest::newRow("defaults, alpha h = 1e-12, from rest") << 1e-4 << 1e-2 << 1e-14 << 0.0;
    QTest::newRow("defaults, alpha h = 1e-12, moving") << 1e-4 << 1e-2 << 1e-14 << 3.0;
    QTest::newRow("slow filter, alpha h = 1e-12 at 1 kHz") << 1.0 << 1e-9 << 1e-3 << 0.0;
    QTest::newRow("alpha h = 1e-6") << 1e-4 << 1e-2 << 1e-8 << 0.0;
    QTest::newRow("alpha h = 0.3 (series side)") << 1e-4 << 1e-2 << 3e-3 << 0.0;
    QTest::newRow("alpha h = 0.7 (closed-form side)") << 1e-4 << 1e-2 << 7e-3 << 0.0;
}

// For tiny α·h the displacement must keep full relative precision, not only ω. The reference
// is the Taylor expansion of the exact solution, in long double:
//   ω₁ = ω₀ e^{−x} + (u/D)·h·(1 − x/2 + x²/6 − …)
//   θ₁ − θ₀ = ω₀·h·(1 − x/2 + x²/6 − …) + (u/D)·h²·(1/2 − x/6 + x²/24 − …),  x = α·h.
void TestAdmittance::tinyStepsKeepPrecision()
{
    QFETCH(double, D);
    QFETCH(double, M);
    QFETCH(double, h);
    QFETCH(double, omega0);
    const DeviceParams p = filter(D, M);
    const double u = 0.1;
    const AdmittanceState s = hatpic::admittanceStep(p, {0.0, omega0}, u, h);

    const long double x = static_cast<long double>(M) / D * h;
    long double phi1 = 0;
    long double phi2 = 0;
    long double term = 1;
    for (int n = 0; n < 60; ++n) { // Σ (−x)ⁿ/(n+1)!  and  Σ (−x)ⁿ/(n+2)!
        term /= (n + 1);
        phi1 += term;
        phi2 += term / (n + 2);
        term *= -x;
    }
    const long double accel = static_cast<long double>(u) / D;
    const long double H = h;
    const long double theta = omega0 * H * phi1 + accel * H * H * phi2;
    const long double omega = omega0 * std::exp(-x) + accel * H * phi1;
    const double thetaError = static_cast<double>(std::abs((s.theta - theta) / theta));
    const double omegaError = static_cast<double>(std::abs((s.omega - omega) / omega));
    QVERIFY2(thetaError < 1e-14, qPrintable(QString::number(thetaError)));
    QVERIFY2(omegaError < 1e-14, qPrintable(QString::number(omegaError)));
}

// M_adm may be arbitrarily small (0 < M_adm): the step must reduce to the undamped solution
// ω₁ = ω₀ + (u/D)·h, θ₁ = θ₀ + ω₀·h + (u/D)·h²/2, not overflow through u/M.
void TestAdmittance::nearlyUndampedFilter()
{
    for (double M : {std::numeric_limits<double>::denorm_min(), 1e-300, 1e-200}) {
        const DeviceParams p = filter(1.0, M);
        QVERIFY(hatpic::validate(p).empty());
        const AdmittanceState s = hatpic::admittanceStep(p, {0.5, 2.0}, 0.1, 1e-3);
        QVERIFY(std::isfinite(s.theta) && std::isfinite(s.omega));
        QCOMPARE(s.omega, 2.0 + 0.1 * 1e-3);
        QCOMPARE(s.theta, 0.5 + 2.0 * 1e-3 + 0.1 * 1e-6 / 2);
    }
}

void TestAdmittance::restStaysAtRest()
{
    const DeviceParams p;
    for (double h : {1e-15, 1e-3, 1.0, 1e3}) {
        const AdmittanceState s = hatpic::admittanceStep(p, {0.25, 0.0}, 0.0, h);
        QCOMPARE(s.theta, 0.25);
        QCOMPARE(s.omega, 0.0);
    }
}

// Exactness under a zero-order hold means step lengths compose.
void TestAdmittance::oneStepEqualsTwoHalfSteps()
{
    const DeviceParams p = filter(3e-4, 2e-2);
    for (double h : {1e-6, 1e-3, 0.05, 2.0}) {
        const AdmittanceState a = hatpic::admittanceStep(p, {0.1, -1.0}, 0.2, h);
        const AdmittanceState b = hatpic::admittanceStep(
            p, hatpic::admittanceStep(p, {0.1, -1.0}, 0.2, h / 2), 0.2, h / 2);
        QVERIFY(std::abs(a.theta - b.theta) <= 1e-14 * (std::abs(a.theta) + 1.0));
        QVERIFY(std::abs(a.omega - b.omega) <= 1e-13 * (std::abs(a.omega) + 1.0));
    }
}

QTEST_GUILESS_MAIN(TestAdmittance)
#include "tst_admittance.moc"
