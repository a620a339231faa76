#include "model/staticcurve.h"

#include "model/stiffness.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace hatpic {

namespace {

constexpr double kPi = std::numbers::pi;

//! How many detent periods fit in R, robust to R being a multiple of s up to rounding.
double periodsInRange(const EffectParams &fx)
{
    return std::floor(fx.detent_range / fx.detent_spacing * (1 + 1e-12));
}

} // namespace

double staticTorque(const DeviceParams &params, const EffectParams &effects, double theta)
{
    const EffectShape<double> fx = EffectShape<double>::from(effects);
    const double e = theta - params.theta0;
    return recenteringTorque(params, theta) + detentTorque(fx, e) + wallTorque(fx, e, 0.0);
}

bool detentsActive(const EffectParams &fx)
{
    return fx.detent_strength > 0 && fx.detent_range > 0 && std::isfinite(fx.detent_range) &&
           fx.detent_spacing > 0 && std::isfinite(fx.detent_spacing);
}

bool wallsActive(const EffectParams &fx)
{
    return fx.wall_stiffness > 0;
}

bool shapesStaticTorque(const EffectParams &effects)
{
    return detentsActive(effects) || wallsActive(effects);
}

std::vector<double> detentRestPositions(const EffectParams &fx, double theta0, double lo, double hi)
{
    std::vector<double> out;
    if (!detentsActive(fx) || !std::isfinite(theta0))
        return out;
    const double s = fx.detent_spacing;
    // Only the i whose θ0 + i·s lies in [lo, hi]: bounded by the view, not by R/s.
    const double n = periodsInRange(fx);
    const double first = std::max(-n, std::ceil((lo - theta0) / s));
    const double last = std::min(n, std::floor((hi - theta0) / s));
    for (double i = first; i <= last && out.size() < std::size_t(kMaxDetentSamples); ++i) {
        const double theta = theta0 + i * s;
        if (theta >= lo && theta <= hi)
            out.push_back(theta);
    }
    return out;
}

WallAngles wallAngles(const EffectParams &fx, double theta0, double lo, double hi)
{
    WallAngles out;
    if (!wallsActive(fx))
        return out;
    auto inside = [&](double theta) -> std::optional<double> {
        if (std::isfinite(theta) && theta >= lo && theta <= hi)
            return theta;
        return std::nullopt;
    };
    out.low = inside(theta0 + fx.wall_min);
    out.high = inside(theta0 + fx.wall_max);
    return out;
}

double effectsHalfRange(const EffectParams &fx)
{
    double half = 0;
    if (detentsActive(fx))
        half = std::max(half, fx.detent_range + fx.detent_spacing / 2);
    if (wallsActive(fx)) {
        for (double wall : {fx.wall_min, fx.wall_max}) {
            const double w = std::abs(wall);
            if (std::isfinite(w) && w < kPi)
                half = std::max(half, 1.25 * w);
        }
    }
    return std::isfinite(half) ? std::min(half, kPi) : kPi;
}

std::vector<double> effectSampleAngles(const EffectParams &fx, double theta0, double lo, double hi)
{
    std::vector<double> out;
    if (!std::isfinite(theta0) || !(lo <= hi))
        return out;
    auto add = [&](double theta) {
        if (std::isfinite(theta) && theta >= lo && theta <= hi)
            out.push_back(theta);
    };
    if (detentsActive(fx)) {
        const double s = fx.detent_spacing;
        const double r = fx.detent_range;
        // The detent range seen in [lo, hi], as phase steps of s / kSamplesPerDetent from θ0.
        const double from = std::max(theta0 - r, lo);
        const double to = std::min(theta0 + r, hi);
        if (from <= to) {
            double step = s / kSamplesPerDetent;
            const double first = std::ceil((from - theta0) / step);
            const double last = std::floor((to - theta0) / step);
            double stride = 1;
            if (last - first + 1 > kMaxDetentSamples)
                stride = std::ceil((last - first + 1) / kMaxDetentSamples);
            for (double j = first; j <= last; j += stride)
                add(theta0 + j * step);
        }
        for (double sign : {-1.0, 1.0}) {
            const double edge = theta0 + sign * r;
            add(edge);
            // The first angle beyond the edge where τ_det is 0, then the last one inside.
            const double outward = sign * std::numeric_limits<double>::infinity();
            double beyond = std::nextafter(edge, outward);
            for (int i = 0; i < 8 && std::abs(beyond - theta0) <= r; ++i)
                beyond = std::nextafter(beyond, outward);
            double inside = std::nextafter(beyond, theta0);
            for (int i = 0; i < 8 && std::abs(inside - theta0) > r; ++i)
                inside = std::nextafter(inside, theta0);
            add(beyond);
            add(inside);
        }
    }
    if (wallsActive(fx)) {
        add(theta0 + fx.wall_min);
        add(theta0 + fx.wall_max);
    }
    return out;
}

EffectTorques splitEffectTorque(const EffectParams &effects, double theta0, double theta,
                                double omega, double tauFx)
{
    if (std::isnan(tauFx)) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {nan, nan, nan};
    }
    const EffectShape<double> fx = EffectShape<double>::from(effects);
    const double e = theta - theta0;
    EffectTorques out;
    out.det = detentTorque(fx, e);
    out.wall = wallTorque(fx, e, omega);
    out.vib = tauFx - out.det - out.wall;
    return out;
}

} // namespace hatpic
