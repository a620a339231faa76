// Tests for the Hann-windowed amplitude spectrum against known sines.
#include "analysis/spectrum.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <vector>

using namespace hatpic::analysis;

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

std::vector<double> sines(std::size_t n, double rate,
                          std::initializer_list<std::pair<double, double>> parts, double dc = 0)
{
    std::vector<double> x(n, dc);
    for (std::size_t i = 0; i < n; ++i) {
        for (const auto &[f, a] : parts)
            x[i] += a * std::sin(kTwoPi * f * static_cast<double>(i) / rate);
    }
    return x;
}

double at(const Spectrum &s, double f)
{
    return s.magnitudeDb[static_cast<std::size_t>(std::lround(f / s.resolution))];
}

} // namespace

class TestSpectrum : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void binCentredSinesReadTheirAmplitude();
    void offBinSineLosesAtMostTheHannScallop();
    void bins();
    void oddLength();
    void tooShortOrBadRate();
    void sampleRateIsTheMedianSpacing();
};

void TestSpectrum::binCentredSinesReadTheirAmplitude()
{
    const double rate = 1000;
    const auto x = sines(1000, rate, {{50, 0.5}, {120, 0.01}}, 3.0);
    const Spectrum s = amplitudeSpectrum(x, rate);
    QCOMPARE(s.resolution, 1.0);
    QVERIFY(std::abs(at(s, 50) - 20 * std::log10(0.5)) < 1e-9);
    QVERIFY(std::abs(at(s, 120) - 20 * std::log10(0.01)) < 1e-6);
    // The mean is taken out: DC reads nothing like the offset 3.
    QVERIFY(s.amplitude[0] < 1e-9);
    const SpectrumPeak peak = dominantPeak(s);
    QCOMPARE(peak.frequency, 50.0);
    QCOMPARE(dominantPeak(s, 60).frequency, 120.0);
    // Far from both lines the Hann sidelobes are deep.
    QVERIFY(at(s, 300) < -200);
}

void TestSpectrum::offBinSineLosesAtMostTheHannScallop()
{
    const double rate = 1000;
    const auto x = sines(1000, rate, {{50.5, 0.5}});
    const Spectrum s = amplitudeSpectrum(x, rate);
    const SpectrumPeak peak = dominantPeak(s);
    QVERIFY(std::abs(peak.frequency - 50.5) <= 0.5);
    // Hann's worst-case scalloping loss is 1.42 dB.
    QVERIFY(peak.magnitudeDb <= 20 * std::log10(0.5) + 1e-9);
    QVERIFY(peak.magnitudeDb > 20 * std::log10(0.5) - 1.43);
}

void TestSpectrum::bins()
{
    const Spectrum s = amplitudeSpectrum(sines(256, 512, {{64, 1}}), 512);
    QCOMPARE(s.frequency.size(), std::size_t(129));
    QCOMPARE(s.frequency.back(), 256.0);
    QCOMPARE(s.resolution, 2.0);
}

void TestSpectrum::oddLength()
{
    const Spectrum s = amplitudeSpectrum(sines(999, 999, {{111, 0.25}}), 999);
    QCOMPARE(s.frequency.size(), std::size_t(500));
    QVERIFY(std::abs(at(s, 111) - 20 * std::log10(0.25)) < 1e-6);
}

void TestSpectrum::tooShortOrBadRate()
{
    QVERIFY(amplitudeSpectrum(std::vector<double>{1.0}, 1000).frequency.empty());
    QVERIFY(amplitudeSpectrum(std::vector<double>{1.0, 2.0}, 0).frequency.empty());
    QVERIFY(amplitudeSpectrum(std::vector<double>{1.0, 2.0}, std::nan("")).frequency.empty());
    // A constant is all mean: every bin reads the floor.
    const Spectrum flat = amplitudeSpectrum(std::vector<double>(64, 2.0), 64);
    for (double db : flat.magnitudeDb)
        QVERIFY(db < -250);
}

void TestSpectrum::sampleRateIsTheMedianSpacing()
{
    std::vector<double> t;
    for (int i = 0; i < 100; ++i)
        t.push_back(i * 1e-3);
    t.erase(t.begin() + 50); // a dropped sample does not move the median
    QVERIFY(std::abs(sampleRate(t) - 1000) < 1e-6);
    QCOMPARE(sampleRate(std::vector<double>{0.0}), 0.0);
}

QTEST_APPLESS_MAIN(TestSpectrum)
#include "tst_spectrum.moc"
