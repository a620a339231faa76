#include "stepresponse.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

namespace hatpic::analysis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRiseLow = 0.1;     //!< rise time starts at 10 % of the change
constexpr double kRiseHigh = 0.9;    //!< and ends at 90 %
constexpr double kSettleBand = 0.02; //!< settling: within 2 % of the change
constexpr double kCritical = 1e-6;   //!< |ζ − 1| below this: the critically damped formula
constexpr int kMinFitSamples = 8;

//! Time at which y first crosses `level` going from `initial` toward it (linear interpolation
//! between samples); NaN when it never does.
double firstCrossing(std::span<const double> t, std::span<const double> y, double initial,
                     double level)
{
    const double sign = level >= initial ? 1.0 : -1.0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] < 0 || sign * (y[i] - level) < 0)
            continue;
        if (i == 0 || t[i - 1] < 0)
            return t[i];
        const double y0 = y[i - 1];
        const double y1 = y[i];
        const double f = y1 == y0 ? 1.0 : (level - y0) / (y1 - y0);
        return t[i - 1] + f * (t[i] - t[i - 1]);
    }
    return kNaN;
}

struct LinearSolution
{
    double offset = 0;
    double gain = 0;
    double sse = std::numeric_limits<double>::infinity();
};

//! The offset and gain minimising Σ(y − offset − gain·s)² for the shape s of (ω_n, ζ).
LinearSolution solveLinear(std::span<const double> t, std::span<const double> y, double omegaN,
                           double zeta)
{
    double n = 0, ss = 0, s1 = 0, sy = 0, y1 = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const double s = secondOrderStep(t[i], omegaN, zeta);
        n += 1;
        s1 += s;
        ss += s * s;
        sy += s * y[i];
        y1 += y[i];
    }
    const double det = n * ss - s1 * s1;
    LinearSolution out;
    if (!(std::abs(det) > 1e-12 * n * n))
        return out;
    out.gain = (n * sy - s1 * y1) / det;
    out.offset = (y1 - out.gain * s1) / n;
    double sse = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const double r = y[i] - out.offset - out.gain * secondOrderStep(t[i], omegaN, zeta);
        sse += r * r;
    }
    out.sse = sse;
    return out;
}

struct Simplex
{
    std::array<std::array<double, 2>, 3> x{};
    std::array<double, 3> f{};
};

//! Nelder–Mead (reflection 1, expansion 2, contraction ½, shrink ½) on a 2-D function.
template<typename F>
std::array<double, 2> nelderMead(F &&objective, std::array<double, 2> start, double step,
                                 int maxEvaluations, int &evaluations)
{
    Simplex s;
    s.x = {start, {start[0] + step, start[1]}, {start[0], start[1] + step}};
    for (int i = 0; i < 3; ++i)
        s.f[i] = objective(s.x[i]);
    int used = 3;
    auto point = [](const std::array<double, 2> &a, const std::array<double, 2> &b, double k) {
        return std::array<double, 2>{a[0] + k * (b[0] - a[0]), a[1] + k * (b[1] - a[1])};
    };
    while (used < maxEvaluations) {
        std::array<int, 3> order{0, 1, 2};
        std::sort(order.begin(), order.end(), [&](int a, int b) { return s.f[a] < s.f[b]; });
        const int best = order[0], mid = order[1], worst = order[2];
        const double spread = std::max(std::abs(s.x[worst][0] - s.x[best][0]),
                                       std::abs(s.x[worst][1] - s.x[best][1]));
        if (spread < 1e-9)
            break;
        const std::array<double, 2> centroid{(s.x[best][0] + s.x[mid][0]) / 2,
                                             (s.x[best][1] + s.x[mid][1]) / 2};
        const auto reflected = point(centroid, s.x[worst], -1.0);
        const double fr = objective(reflected);
        ++used;
        if (fr < s.f[best]) {
            const auto expanded = point(centroid, s.x[worst], -2.0);
            const double fe = objective(expanded);
            ++used;
            if (fe < fr) {
                s.x[worst] = expanded;
                s.f[worst] = fe;
            } else {
                s.x[worst] = reflected;
                s.f[worst] = fr;
            }
        } else if (fr < s.f[mid]) {
            s.x[worst] = reflected;
            s.f[worst] = fr;
        } else {
            const auto contracted = point(centroid, s.x[worst], 0.5);
            const double fc = objective(contracted);
            ++used;
            if (fc < s.f[worst]) {
                s.x[worst] = contracted;
                s.f[worst] = fc;
            } else {
                for (int i : {mid, worst}) {
                    s.x[i] = point(s.x[best], s.x[i], 0.5);
                    s.f[i] = objective(s.x[i]);
                    ++used;
                }
            }
        }
    }
    evaluations += used;
    const auto bestIt = std::min_element(s.f.begin(), s.f.end());
    return s.x[static_cast<std::size_t>(bestIt - s.f.begin())];
}

} // namespace

double secondOrderStep(double t, double omegaN, double zeta)
{
    if (t <= 0)
        return 0;
    const double w = omegaN;
    if (std::abs(zeta - 1) < kCritical)
        return 1 - std::exp(-w * t) * (1 + w * t);
    if (zeta < 1) {
        const double root = std::sqrt(1 - zeta * zeta);
        const double wd = w * root;
        return 1 - std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta / root * std::sin(wd * t));
    }
    const double root = std::sqrt(zeta * zeta - 1);
    const double p1 = w * (zeta - root); // the slow pole
    const double p2 = w * (zeta + root);
    return 1 - (p2 * std::exp(-p1 * t) - p1 * std::exp(-p2 * t)) / (p2 - p1);
}

double tailMean(std::span<const double> y, double fraction)
{
    if (y.empty())
        return kNaN;
    const auto count = std::clamp<std::size_t>(
        static_cast<std::size_t>(std::ceil(static_cast<double>(y.size()) * fraction)), 1, y.size());
    const auto tail = y.last(count);
    return std::accumulate(tail.begin(), tail.end(), 0.0) / static_cast<double>(count);
}

StepMetrics stepMetrics(std::span<const double> t, std::span<const double> y, double initial,
                        double final)
{
    StepMetrics m;
    m.initial = initial;
    m.final = final;
    const double change = final - initial;
    const double sign = change >= 0 ? 1.0 : -1.0;
    const double start = firstCrossing(t, y, initial, initial + kRiseLow * change);
    const double end = firstCrossing(t, y, initial, initial + kRiseHigh * change);
    m.riseTime = std::isnan(start) || std::isnan(end) ? kNaN : end - start;

    double peak = -std::numeric_limits<double>::infinity();
    double lastOutside = kNaN;
    bool any = false;
    std::size_t lastOutsideIndex = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] < 0)
            continue;
        any = true;
        const double excursion = sign * (y[i] - final);
        if (excursion > peak) {
            peak = excursion;
            m.peakTime = t[i];
        }
        if (std::abs(y[i] - final) > kSettleBand * std::abs(change)) {
            lastOutside = t[i];
            lastOutsideIndex = i;
        }
    }
    m.overshoot = any ? std::max(0.0, peak / std::abs(change)) : kNaN;
    if (!any)
        m.settlingTime = kNaN;
    else if (std::isnan(lastOutside))
        m.settlingTime = 0;
    else if (lastOutsideIndex + 1 < t.size())
        m.settlingTime = t[lastOutsideIndex + 1];
    else
        m.settlingTime = kNaN; // still outside at the last sample
    return m;
}

SecondOrderFit fitSecondOrderStep(std::span<const double> tAll, std::span<const double> yAll)
{
    SecondOrderFit fit;
    std::vector<double> t, y;
    for (std::size_t i = 0; i < std::min(tAll.size(), yAll.size()); ++i) {
        if (tAll[i] >= 0 && std::isfinite(tAll[i]) && std::isfinite(yAll[i])) {
            t.push_back(tAll[i]);
            y.push_back(yAll[i]);
        }
    }
    if (t.size() < static_cast<std::size_t>(kMinFitSamples)) {
        fit.problem = "The response has fewer than " + std::to_string(kMinFitSamples) +
                      " samples after the step.";
        return fit;
    }
    const double duration = t.back() - t.front();
    const auto [lo, hi] = std::minmax_element(y.begin(), y.end());
    if (!(duration > 0) || !(*hi > *lo)) {
        fit.problem = "The response does not change after the step.";
        return fit;
    }

    // Start values from the figures: ζ from the overshoot (under-damped), ω_n from the rise
    // time (t_r·ω_n ≈ 1 − 0.4167ζ + 2.917ζ², a standard fit for 0 < ζ < 1); the search is then
    // restarted from several damping ratios so an over-damped or poorly started case still
    // finds the global minimum.
    const double initial = y.front();
    const double final = tailMean(y);
    const StepMetrics m = stepMetrics(t, y, initial, final);
    const double riseTime = std::isnan(m.riseTime) || m.riseTime <= 0 ? duration / 4 : m.riseTime;
    auto omegaGuess = [&](double zeta) {
        return (1 - 0.4167 * zeta + 2.917 * zeta * zeta) / riseTime;
    };
    std::vector<double> zetas{0.1, 0.3, 0.7, 1.5, 4.0};
    if (m.overshoot > 1e-3 && m.overshoot < 1) {
        const double l = std::log(m.overshoot);
        zetas.insert(zetas.begin(), -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l));
    }

    auto objective = [&](const std::array<double, 2> &x) {
        const double omegaN = std::exp(x[0]);
        const double zeta = std::exp(x[1]);
        if (!std::isfinite(omegaN) || !std::isfinite(zeta) || zeta > 1e3 || zeta < 1e-4)
            return std::numeric_limits<double>::infinity();
        return solveLinear(t, y, omegaN, zeta).sse;
    };
    double bestSse = std::numeric_limits<double>::infinity();
    std::array<double, 2> best{};
    constexpr int kEvaluationsPerStart = 400;
    for (double zeta : zetas) {
        const std::array<double, 2> start{std::log(omegaGuess(std::min(zeta, 1.0))),
                                          std::log(zeta)};
        const auto x = nelderMead(objective, start, 0.3, kEvaluationsPerStart, fit.evaluations);
        const double sse = objective(x);
        if (sse < bestSse) {
            bestSse = sse;
            best = x;
        }
    }
    if (!std::isfinite(bestSse)) {
        fit.problem = "No second-order response fits the samples.";
        return fit;
    }
    fit.omegaN = std::exp(best[0]);
    fit.zeta = std::exp(best[1]);
    const LinearSolution linear = solveLinear(t, y, fit.omegaN, fit.zeta);
    fit.gain = linear.gain;
    fit.offset = linear.offset;
    fit.rmsResidual = std::sqrt(linear.sse / static_cast<double>(t.size()));
    fit.ok = true;
    return fit;
}

} // namespace hatpic::analysis
