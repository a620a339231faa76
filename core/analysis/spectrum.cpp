#include "spectrum.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <numeric>

namespace hatpic::analysis {

namespace {

constexpr double kCoherentGain = 0.5; //!< mean of the Hann window

//! FFTW's planner is not thread-safe (only fftw_execute is): plans are made and destroyed
//! under this lock.
std::mutex &plannerMutex()
{
    static std::mutex mutex;
    return mutex;
}

} // namespace

Spectrum amplitudeSpectrum(std::span<const double> x, double rate)
{
    Spectrum s;
    const std::size_t n = x.size();
    if (n < 2 || !(rate > 0) || !std::isfinite(rate))
        return s;
    const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(n);
    const std::size_t bins = n / 2 + 1;
    double *in = fftw_alloc_real(n);
    fftw_complex *out = fftw_alloc_complex(bins);
    fftw_plan plan = nullptr;
    {
        std::lock_guard lock(plannerMutex());
        plan = fftw_plan_dft_r2c_1d(static_cast<int>(n), in, out, FFTW_ESTIMATE);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const double w =
            0.5 * (1 - std::cos(2 * std::numbers::pi * static_cast<double>(i) / double(n)));
        in[i] = (x[i] - mean) * w;
    }
    fftw_execute(plan);
    s.resolution = rate / static_cast<double>(n);
    s.frequency.resize(bins);
    s.amplitude.resize(bins);
    s.magnitudeDb.resize(bins);
    for (std::size_t k = 0; k < bins; ++k) {
        // One-sided: every bin but DC (and Nyquist for even n) carries its mirror's half too.
        const bool single = k == 0 || (n % 2 == 0 && k == n / 2);
        const double scale = (single ? 1.0 : 2.0) / (static_cast<double>(n) * kCoherentGain);
        const double a = std::hypot(out[k][0], out[k][1]) * scale;
        s.frequency[k] = static_cast<double>(k) * s.resolution;
        s.amplitude[k] = a;
        s.magnitudeDb[k] =
            a > 0 ? std::max(Spectrum::kFloorDb, 20 * std::log10(a)) : Spectrum::kFloorDb;
    }
    {
        std::lock_guard lock(plannerMutex());
        fftw_destroy_plan(plan);
    }
    fftw_free(in);
    fftw_free(out);
    return s;
}

double sampleRate(std::span<const double> t)
{
    if (t.size() < 2)
        return 0;
    std::vector<double> dt(t.size() - 1);
    for (std::size_t i = 1; i < t.size(); ++i)
        dt[i - 1] = t[i] - t[i - 1];
    const auto mid = dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2);
    std::nth_element(dt.begin(), mid, dt.end());
    return *mid > 0 ? 1 / *mid : 0;
}

SpectrumPeak dominantPeak(const Spectrum &spectrum, double minFrequency)
{
    SpectrumPeak peak{std::numeric_limits<double>::quiet_NaN(), 0, Spectrum::kFloorDb};
    for (std::size_t k = 0; k < spectrum.frequency.size(); ++k) {
        if (spectrum.frequency[k] < minFrequency || spectrum.amplitude[k] <= peak.amplitude)
            continue;
        peak = {spectrum.frequency[k], spectrum.amplitude[k], spectrum.magnitudeDb[k]};
    }
    return peak;
}

} // namespace hatpic::analysis
