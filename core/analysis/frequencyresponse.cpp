#include "frequencyresponse.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace hatpic::analysis {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

} // namespace

std::complex<double> lockInAmplitude(std::span<const double> t, std::span<const double> x,
                                     double frequency)
{
    const std::size_t n = std::min(t.size(), x.size());
    if (n < 2 || !(t[n - 1] > t[0]))
        return {};
    const double span = t[n - 1] - t[0];
    // The mean by the same rule, so the offset leaves no trace in the correlation.
    double mean = 0;
    for (std::size_t i = 1; i < n; ++i)
        mean += (x[i] + x[i - 1]) / 2 * (t[i] - t[i - 1]);
    mean /= span;
    const double w = kTwoPi * frequency;
    std::complex<double> sum;
    auto term = [&](std::size_t i) { return (x[i] - mean) * std::polar(1.0, -w * (t[i] - t[0])); };
    std::complex<double> previous = term(0);
    for (std::size_t i = 1; i < n; ++i) {
        const std::complex<double> current = term(i);
        sum += (previous + current) / 2.0 * (t[i] - t[i - 1]);
        previous = current;
    }
    return 2.0 / span * sum;
}

FrequencyPoint frequencyPoint(std::span<const double> t, std::span<const double> input,
                              std::span<const double> output, double frequency)
{
    FrequencyPoint p;
    p.frequency = frequency;
    const std::complex<double> u = lockInAmplitude(t, input, frequency);
    const std::complex<double> y = lockInAmplitude(t, output, frequency);
    p.inputAmplitude = std::abs(u);
    p.gain = std::abs(u) > 0 ? y / u : std::complex<double>(kNaN, kNaN);
    p.magnitude = std::abs(p.gain);
    p.phase = std::arg(p.gain);
    return p;
}

std::size_t wholePeriods(std::span<const double> t, double frequency)
{
    if (t.size() < 2 || !(frequency > 0))
        return 0;
    const double period = 1 / frequency;
    const double periods = std::floor((t.back() - t.front()) / period);
    if (periods < 1)
        return 0;
    const double end = t.front() + periods * period;
    // The sample nearest the end of the last whole period.
    std::size_t best = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (std::abs(t[i] - end) < std::abs(t[best] - end))
            best = i;
    }
    return best + 1;
}

void unwrapPhase(std::vector<FrequencyPoint> &points)
{
    for (std::size_t i = 1; i < points.size(); ++i) {
        double phase = points[i].phase;
        while (phase - points[i - 1].phase > std::numbers::pi)
            phase -= kTwoPi;
        while (phase - points[i - 1].phase < -std::numbers::pi)
            phase += kTwoPi;
        points[i].phase = phase;
    }
}

std::complex<double> modelGain(const DeviceParams &params, double frequency)
{
    const double w = kTwoPi * frequency;
    return 1.0 / std::complex<double>(params.K_max - params.D_adm * w * w, params.M_adm * w);
}

double modelBandwidth(const DeviceParams &params)
{
    const double K = params.K_max, D = params.D_adm, M = params.M_adm;
    if (!(K > 0))
        return kNaN;
    // |H|² = 1/((K − Dω²)² + M²ω²) = 1/(2K²)  ⇔  D²x² + (M² − 2KD)·x − K² = 0, x = ω².
    const double b = M * M - 2 * K * D;
    const double x = (-b + std::sqrt(b * b + 4 * D * D * K * K)) / (2 * D * D);
    return std::sqrt(x) / kTwoPi;
}

double measuredBandwidth(std::span<const FrequencyPoint> points)
{
    if (points.empty())
        return kNaN;
    const double reference = points.front().magnitude;
    const double limitDb = 20 * std::log10(reference / std::numbers::sqrt2);
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (points[i].magnitude >= reference / std::numbers::sqrt2)
            continue;
        const double d0 = 20 * std::log10(points[i - 1].magnitude);
        const double d1 = 20 * std::log10(points[i].magnitude);
        const double l0 = std::log10(points[i - 1].frequency);
        const double l1 = std::log10(points[i].frequency);
        const double f = d1 == d0 ? 1.0 : (limitDb - d0) / (d1 - d0);
        return std::pow(10.0, l0 + f * (l1 - l0));
    }
    return kNaN;
}

} // namespace hatpic::analysis
