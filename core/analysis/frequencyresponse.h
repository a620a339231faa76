// Frequency response of θ/τ_ext from stepped sines, by correlation (a digital lock-in), and
// the model's own θ/τ_ext (docs/experiments.md § Frequency response).
//
// Plain C++20: no Qt.
#pragma once

#include "model/params.h"

#include <complex>
#include <span>
#include <vector>

namespace hatpic::analysis {

//! The complex amplitude of the component of x at `frequency` over the samples (t[i], x[i]):
//! (2/T)·∫(x − x̄)·e^{−i2πft} dt by the trapezoidal rule over T = t.back() − t.front(), so
//! uneven spacing and a missing sample cost only their share. Exact for a sine when T spans a
//! whole number of periods; the mean x̄ (an offset) is taken out first. A sine A·cos(2πft + φ)
//! gives A·e^{iφ}.
std::complex<double> lockInAmplitude(std::span<const double> t, std::span<const double> x,
                                     double frequency);

struct FrequencyPoint
{
    double frequency = 0;      //!< [Hz]
    std::complex<double> gain; //!< θ/τ_ext [rad/(N·m)]
    double magnitude = 0;      //!< |gain| [rad/(N·m)]
    double phase = 0;          //!< arg(gain), unwrapped along the points [rad]
    double inputAmplitude = 0; //!< |τ_ext| component at the frequency [N·m]
};

//! One point from a stretch of samples excited at `frequency`: the output's lock-in amplitude
//! over the input's. The stretch should span whole periods (see wholePeriods()).
FrequencyPoint frequencyPoint(std::span<const double> t, std::span<const double> input,
                              std::span<const double> output, double frequency);

//! How many samples from the start of t span the largest whole number of periods of
//! `frequency` (at least one period; 0 when t is shorter than one period).
std::size_t wholePeriods(std::span<const double> t, double frequency);

//! Unwraps the phases of points sorted by frequency, so steps between neighbours stay below π.
void unwrapPhase(std::vector<FrequencyPoint> &points);

//! The model's θ/τ_ext at `frequency`: 1/(K − D·ω² + i·M·ω) with K = K_max, D = D_adm,
//! M = M_adm (model.md § 3, linear in the notch band; the 1 ms zero-order hold is left out).
std::complex<double> modelGain(const DeviceParams &params, double frequency);

//! The model's −3 dB bandwidth: where |θ/τ_ext| falls to 1/√2 of its static value 1/K [Hz];
//! NaN when K_max = 0 (no static value).
double modelBandwidth(const DeviceParams &params);

//! The measured −3 dB bandwidth: the first frequency at which the magnitude falls below 1/√2
//! of the lowest frequency's, interpolated between points in log frequency and dB [Hz]; NaN
//! when no point falls that far.
double measuredBandwidth(std::span<const FrequencyPoint> points);

} // namespace hatpic::analysis
