// Tests for the step figures and the second-order fit against analytic responses.
#include "analysis/stepresponse.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace hatpic::analysis;

namespace {

//! ẍ + 2ζω_n·ẋ + ω_n²·x = ω_n² from rest, by classical Runge–Kutta with step h: an independent
//! reference for the closed forms.
double integrateStep(double t, double omegaN, double zeta, double h = 1e-5)
{
    double x = 0, v = 0;
    auto accel = [&](double xx, double vv) {
        return omegaN * omegaN * (1 - xx) - 2 * zeta * omegaN * vv;
    };
    const int steps = static_cast<int>(std::lround(t / h));
    for (int i = 0; i < steps; ++i) {
        const double k1x = v, k1v = accel(x, v);
        const double k2x = v + h / 2 * k1v, k2v = accel(x + h / 2 * k1x, v + h / 2 * k1v);
        const double k3x = v + h / 2 * k2v, k3v = accel(x + h / 2 * k2x, v + h / 2 * k2v);
        const double k4x = v + h * k3v, k4v = accel(x + h * k3x, v + h * k3v);
        x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    }
    return x;
}

struct Series
{
    std::vector<double> t, y;
};

Series sampled(double omegaN, double zeta, double dt, double duration, double offset = 0,
               double gain = 1, double noise = 0, unsigned seed = 1)
{
    Series s;
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal(0, noise > 0 ? noise : 1);
    for (double t = -0.05; t <= duration + dt / 2; t += dt) {
        s.t.push_back(t);
        s.y.push_back(offset + gain * secondOrderStep(t, omegaN, zeta) +
                      (noise > 0 ? normal(rng) : 0));
    }
    return s;
}

//! Time at which s first reaches `level` (bisection on the closed form, 1e-9 s).
double reaches(double level, double omegaN, double zeta, double hi)
{
    double lo = 0;
    for (int i = 0; i < 60; ++i) {
        const double mid = (lo + hi) / 2;
        (secondOrderStep(mid, omegaN, zeta) < level ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

} // namespace

class TestStepResponse : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void closedFormMatchesIntegration_data();
    void closedFormMatchesIntegration();
    void metricsOfUnderdamped();
    void metricsOfDownwardStep();
    void metricsNeverSettled();
    void tailMeanTakesTheEnd();
    void fitRecovers_data();
    void fitRecovers();
    void fitRefusesFlatOrShort();
};

void TestStepResponse::closedFormMatchesIntegration_data()
{
    QTest::addColumn<double>("zeta");
    QTest::newRow("under-damped 0.2") << 0.2;
    QTest::newRow("under-damped 0.79") << 0.79;
    QTest::newRow("critical 1") << 1.0;
    QTest::newRow("near critical 1.0000001") << 1.0000001;
    QTest::newRow("over-damped 2.5") << 2.5;
}

void TestStepResponse::closedFormMatchesIntegration()
{
    QFETCH(double, zeta);
    const double omegaN = 63.2;
    QCOMPARE(secondOrderStep(0, omegaN, zeta), 0.0);
    QCOMPARE(secondOrderStep(-1, omegaN, zeta), 0.0);
    for (double t : {0.005, 0.02, 0.05, 0.1, 0.3})
        QVERIFY2(std::abs(secondOrderStep(t, omegaN, zeta) - integrateStep(t, omegaN, zeta)) < 1e-6,
                 qPrintable(QString::number(t)));
}

void TestStepResponse::metricsOfUnderdamped()
{
    const double omegaN = 20, zeta = 0.5, dt = 1e-4;
    const Series s = sampled(omegaN, zeta, dt, 3.0, 0.1, 0.5);
    const StepMetrics m = stepMetrics(s.t, s.y, 0.1, 0.6);
    // Textbook figures: overshoot e^{−πζ/√(1−ζ²)}, peak at π/ω_d.
    const double root = std::sqrt(1 - zeta * zeta);
    QVERIFY(std::abs(m.overshoot - std::exp(-std::numbers::pi * zeta / root)) < 1e-5);
    QVERIFY(std::abs(m.peakTime - std::numbers::pi / (omegaN * root)) < dt);
    const double rise = reaches(0.9, omegaN, zeta, 0.15) - reaches(0.1, omegaN, zeta, 0.15);
    QVERIFY2(std::abs(m.riseTime - rise) < 1e-6, qPrintable(QString::number(m.riseTime)));
    // Settling: inside the 2 % band from settlingTime on, outside one sample before.
    QVERIFY(m.settlingTime > 0);
    for (std::size_t i = 0; i < s.t.size(); ++i) {
        if (s.t[i] >= m.settlingTime)
            QVERIFY(std::abs(s.y[i] - 0.6) <= 0.02 * 0.5);
    }
    QVERIFY(std::abs(0.1 + 0.5 * secondOrderStep(m.settlingTime - dt, omegaN, zeta) - 0.6) >
            0.02 * 0.5);
    // Close to the classic envelope estimate 4/(ζω_n) = 0.4 s.
    QVERIFY(m.settlingTime > 0.3 && m.settlingTime < 0.45);
}

void TestStepResponse::metricsOfDownwardStep()
{
    const Series s = sampled(30, 0.3, 1e-4, 2.0, 1.0, -0.2);
    const StepMetrics m = stepMetrics(s.t, s.y, 1.0, 0.8);
    const Series up = sampled(30, 0.3, 1e-4, 2.0, 0.0, 0.2);
    const StepMetrics u = stepMetrics(up.t, up.y, 0.0, 0.2);
    QVERIFY(std::abs(m.overshoot - u.overshoot) < 1e-9);
    QVERIFY(std::abs(m.riseTime - u.riseTime) < 1e-9);
    QVERIFY(std::abs(m.settlingTime - u.settlingTime) < 1e-9);
}

void TestStepResponse::metricsNeverSettled()
{
    // A ramp that never reaches its "final" level: no rise end, no settling.
    const std::vector<double> t{0, 1, 2, 3};
    const std::vector<double> y{0, 0.2, 0.4, 0.6};
    const StepMetrics m = stepMetrics(t, y, 0, 1);
    QVERIFY(std::isnan(m.riseTime));
    QVERIFY(std::isnan(m.settlingTime));
    QCOMPARE(m.overshoot, 0.0);
}

void TestStepResponse::tailMeanTakesTheEnd()
{
    const std::vector<double> y{5, 5, 5, 5, 5, 5, 5, 5, 1, 3};
    QCOMPARE(tailMean(y, 0.2), 2.0);
    QCOMPARE(tailMean(y, 0.01), 3.0); // at least one value
    QVERIFY(std::isnan(tailMean(std::vector<double>{})));
}

void TestStepResponse::fitRecovers_data()
{
    QTest::addColumn<double>("omegaN");
    QTest::addColumn<double>("zeta");
    QTest::addColumn<double>("noise");
    QTest::newRow("default knob, clean") << 63.2 << 0.79 << 0.0;
    QTest::newRow("ringing, clean") << 40.0 << 0.15 << 0.0;
    QTest::newRow("critical, clean") << 50.0 << 1.0 << 0.0;
    QTest::newRow("over-damped, clean") << 80.0 << 3.0 << 0.0;
    QTest::newRow("default knob, 1 % noise") << 63.2 << 0.79 << 0.01;
    QTest::newRow("ringing, 1 % noise") << 40.0 << 0.15 << 0.01;
}

void TestStepResponse::fitRecovers()
{
    QFETCH(double, omegaN);
    QFETCH(double, zeta);
    QFETCH(double, noise);
    const double gain = 0.05, offset = 0.03;
    // 1 kHz for long enough to settle, as the device streams it.
    const double duration = std::min(
        3.0, 10 / (zeta < 1 ? zeta * omegaN : omegaN * (zeta - std::sqrt(zeta * zeta - 1))));
    const Series s = sampled(omegaN, zeta, 1e-3, duration, offset, gain, noise * gain);
    const SecondOrderFit fit = fitSecondOrderStep(s.t, s.y);
    QVERIFY2(fit.ok, fit.problem.c_str());
    const double tolerance = noise > 0 ? 0.01 : 1e-4;
    QVERIFY2(std::abs(fit.omegaN / omegaN - 1) < tolerance,
             qPrintable(QString::number(fit.omegaN)));
    QVERIFY2(std::abs(fit.zeta / zeta - 1) < tolerance, qPrintable(QString::number(fit.zeta)));
    QVERIFY(std::abs(fit.gain / gain - 1) < tolerance);
    QVERIFY(std::abs(fit.offset - offset) < tolerance * gain);
    QVERIFY(fit.rmsResidual <= 1.2 * noise * gain + 1e-9);
}

void TestStepResponse::fitRefusesFlatOrShort()
{
    const std::vector<double> t{0, 0.001, 0.002};
    const std::vector<double> y{0, 0.1, 0.2};
    const SecondOrderFit shortFit = fitSecondOrderStep(t, y);
    QVERIFY(!shortFit.ok);
    QVERIFY(!shortFit.problem.empty());
    std::vector<double> tf, yf;
    for (int i = 0; i < 100; ++i) {
        tf.push_back(i * 1e-3);
        yf.push_back(0.25);
    }
    const SecondOrderFit flat = fitSecondOrderStep(tf, yf);
    QVERIFY(!flat.ok);
    QCOMPARE(flat.problem, std::string("The response does not change after the step."));
}

QTEST_APPLESS_MAIN(TestStepResponse)
#include "tst_stepresponse.moc"
