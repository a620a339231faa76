// Tests for the lock-in frequency response and the model's θ/τ_ext against known sines.
#include "analysis/frequencyresponse.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <vector>

using namespace hatpic;
using namespace hatpic::analysis;

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

DeviceParams knob(double D, double M, double K)
{
    DeviceParams p;
    p.D_adm = D;
    p.M_adm = M;
    p.K_max = K;
    return p;
}

std::vector<double> times(double rate, double duration, double start = 0)
{
    std::vector<double> t;
    const int n = static_cast<int>(std::lround(duration * rate));
    for (int i = 0; i <= n; ++i)
        t.push_back(start + i / rate);
    return t;
}

} // namespace

class TestFrequencyResponse : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void lockInRecoversASine_data();
    void lockInRecoversASine();
    void lockInIgnoresHarmonicsAndOffset();
    void lockInCopesWithAMissingSample();
    void wholePeriodsCutsAtAPeriod();
    void pointOfTheSteadyStateIsTheModel();
    void modelBandwidthIsMinus3dB_data();
    void modelBandwidthIsMinus3dB();
    void measuredBandwidthInterpolates();
    void unwrapKeepsPhaseContinuous();
};

void TestFrequencyResponse::lockInRecoversASine_data()
{
    QTest::addColumn<double>("frequency");
    QTest::addColumn<double>("amplitude");
    QTest::addColumn<double>("phase");
    QTest::newRow("1 Hz, 0 rad") << 1.0 << 0.3 << 0.0;
    QTest::newRow("7 Hz, -1 rad") << 7.0 << 0.02 << -1.0;
    QTest::newRow("33.3 Hz, 2.5 rad") << 33.3 << 1.5 << 2.5;
}

void TestFrequencyResponse::lockInRecoversASine()
{
    QFETCH(double, frequency);
    QFETCH(double, amplitude);
    QFETCH(double, phase);
    const std::vector<double> all = times(1000, 4 / frequency + 0.1, 0.25);
    const std::vector<double> t(
        all.begin(), all.begin() + static_cast<std::ptrdiff_t>(wholePeriods(all, frequency)));
    std::vector<double> x;
    for (double ti : t)
        x.push_back(amplitude * std::cos(kTwoPi * frequency * (ti - t.front()) + phase));
    const std::complex<double> a = lockInAmplitude(t, x, frequency);
    // Whole periods to the nearest 1 ms sample: the error is at most ~h·f of the amplitude.
    QVERIFY2(std::abs(a - std::polar(amplitude, phase)) < 0.01 * amplitude,
             qPrintable(QString::number(std::abs(a)) + u' ' + QString::number(std::arg(a))));
}

void TestFrequencyResponse::lockInIgnoresHarmonicsAndOffset()
{
    const double f = 5;
    const std::vector<double> t = times(1000, 1.0); // five whole periods
    std::vector<double> x;
    for (double ti : t)
        x.push_back(0.7 + 0.1 * std::sin(kTwoPi * f * ti) + 0.05 * std::cos(kTwoPi * 3 * f * ti) +
                    0.02 * std::sin(kTwoPi * 2 * f * ti));
    const std::complex<double> a = lockInAmplitude(t, x, f);
    // sin = cos(· − π/2)
    QVERIFY(std::abs(a - std::polar(0.1, -std::numbers::pi / 2)) < 1e-6);
}

void TestFrequencyResponse::lockInCopesWithAMissingSample()
{
    const double f = 10;
    std::vector<double> t = times(1000, 0.5);
    t.erase(t.begin() + 123);
    std::vector<double> x;
    for (double ti : t)
        x.push_back(0.2 * std::cos(kTwoPi * f * ti));
    QVERIFY(std::abs(lockInAmplitude(t, x, f) - std::complex<double>(0.2, 0)) < 1e-4);
}

void TestFrequencyResponse::wholePeriodsCutsAtAPeriod()
{
    const std::vector<double> t = times(1000, 1.0);
    QCOMPARE(wholePeriods(t, 2.5), std::size_t(801)); // 2 periods of 0.4 s end at 0.8 s
    QCOMPARE(wholePeriods(t, 0.5), std::size_t(0));   // shorter than one period
    QCOMPARE(wholePeriods(t, 1), std::size_t(1001));
}

void TestFrequencyResponse::pointOfTheSteadyStateIsTheModel()
{
    // The steady state of D·θ̈ + M·θ̇ + K·θ = u for u = U·cos(ωt) is |H|·U·cos(ωt + arg H).
    const DeviceParams p = knob(1e-4, 1e-2, 0.4);
    for (double f : {1.0, 5.0, 10.0, 20.0, 40.0}) {
        const std::complex<double> h = modelGain(p, f);
        const std::vector<double> all = times(1000, 6 / f);
        const std::vector<double> t(
            all.begin(), all.begin() + static_cast<std::ptrdiff_t>(wholePeriods(all, f)));
        std::vector<double> u, y;
        for (double ti : t) {
            u.push_back(0.02 * std::cos(kTwoPi * f * ti) + 0.01);
            y.push_back(std::abs(h) * 0.02 * std::cos(kTwoPi * f * ti + std::arg(h)) + 0.025);
        }
        const FrequencyPoint point = frequencyPoint(t, u, y, f);
        QVERIFY(std::abs(point.magnitude / std::abs(h) - 1) < 1e-3);
        QVERIFY(std::abs(point.phase - std::arg(h)) < 1e-3);
        QVERIFY(std::abs(point.inputAmplitude - 0.02) < 2e-4);
    }
    // Static gain 1/K, and phase −π/2 at ω_n.
    QVERIFY(std::abs(modelGain(p, 0) - std::complex<double>(2.5, 0)) < 1e-12);
    const double fn = std::sqrt(0.4 / 1e-4) / kTwoPi;
    QVERIFY(std::abs(std::arg(modelGain(p, fn)) + std::numbers::pi / 2) < 1e-12);
}

void TestFrequencyResponse::modelBandwidthIsMinus3dB_data()
{
    QTest::addColumn<double>("M");
    QTest::newRow("default 0.01") << 1e-2;
    QTest::newRow("light 0.002") << 2e-3;
    QTest::newRow("heavy 0.05") << 5e-2;
}

void TestFrequencyResponse::modelBandwidthIsMinus3dB()
{
    QFETCH(double, M);
    const DeviceParams p = knob(1e-4, M, 0.4);
    const double fb = modelBandwidth(p);
    QVERIFY(std::abs(std::abs(modelGain(p, fb)) * 0.4 * std::numbers::sqrt2 - 1) < 1e-9);
    // Above it the gain stays below: it is the last crossing (the only one).
    QVERIFY(std::abs(modelGain(p, fb * 1.01)) * 0.4 * std::numbers::sqrt2 < 1);
    // ζ = 1/√2 puts it exactly at ω_n.
    const DeviceParams butterworth = knob(1e-4, std::numbers::sqrt2 * std::sqrt(0.4 * 1e-4), 0.4);
    QVERIFY(std::abs(modelBandwidth(butterworth) - std::sqrt(0.4 / 1e-4) / kTwoPi) < 1e-9);
    QVERIFY(std::isnan(modelBandwidth(knob(1e-4, M, 0))));
}

void TestFrequencyResponse::measuredBandwidthInterpolates()
{
    const DeviceParams p = knob(1e-4, 1e-2, 0.4);
    std::vector<FrequencyPoint> points;
    for (double f = 0.5; f < 40; f *= 1.15) {
        FrequencyPoint point;
        point.frequency = f;
        point.gain = modelGain(p, f);
        point.magnitude = std::abs(point.gain);
        points.push_back(point);
    }
    const double fb = measuredBandwidth(points);
    QVERIFY2(std::abs(fb / modelBandwidth(p) - 1) < 0.01, qPrintable(QString::number(fb)));
    points.resize(3); // never falls 3 dB
    QVERIFY(std::isnan(measuredBandwidth(points)));
    QVERIFY(std::isnan(measuredBandwidth({})));
}

void TestFrequencyResponse::unwrapKeepsPhaseContinuous()
{
    std::vector<FrequencyPoint> points(4);
    const double phases[] = {-2.8, -3.1, 3.0, 2.9}; // −2.8, −3.1, then past −π
    for (int i = 0; i < 4; ++i)
        points[static_cast<std::size_t>(i)].phase = phases[i];
    unwrapPhase(points);
    QCOMPARE(points[2].phase, 3.0 - kTwoPi);
    QCOMPARE(points[3].phase, 2.9 - kTwoPi);
}

QTEST_APPLESS_MAIN(TestFrequencyResponse)
#include "tst_frequencyresponse.moc"
