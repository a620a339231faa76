// Step-response figures of a measured (or simulated) response, and the least-squares fit of a
// second-order step response to it (docs/experiments.md § Step response).
//
// Plain C++20: no Qt. Times are relative to the step [s]; values are in the response's unit.
#pragma once

#include <span>
#include <string>

namespace hatpic::analysis {

//! The unit step response of ω_n²/(s² + 2ζω_n·s + ω_n²) at t ≥ 0 (0 before the step), for
//! every ζ > 0: under-damped, critically damped and over-damped.
//! @param t time since the step [s]  @param omegaN [rad/s], > 0  @param zeta [-], > 0
double secondOrderStep(double t, double omegaN, double zeta);

struct StepMetrics
{
    double initial = 0;      //!< level before the step [unit]
    double final = 0;        //!< level after it [unit]
    double riseTime = 0;     //!< 10 % → 90 % of the change; NaN when 90 % is never reached [s]
    double overshoot = 0;    //!< largest excursion beyond `final`, as a fraction of the change
    double peakTime = 0;     //!< time of that largest excursion [s]
    double settlingTime = 0; //!< from which on it stays within 2 % of the change; NaN if never
};

//! Figures of the response (t[i], y[i]) to a step at t = 0, between `initial` and `final`
//! (e.g. tailMean()). Samples before t = 0 are ignored. `final` ≠ `initial`.
StepMetrics stepMetrics(std::span<const double> t, std::span<const double> y, double initial,
                        double final);

//! Mean of the last `fraction` (0 < fraction ≤ 1) of the values, at least one value.
double tailMean(std::span<const double> y, double fraction = 0.1);

struct SecondOrderFit
{
    bool ok = false;        //!< false: see problem
    std::string problem;    //!< why there is no fit, one sentence
    double omegaN = 0;      //!< natural frequency [rad/s]
    double zeta = 0;        //!< damping ratio [-]
    double gain = 0;        //!< size of the step in the response [unit]
    double offset = 0;      //!< level before the step [unit]
    double rmsResidual = 0; //!< root mean square of data − fit [unit]
    int evaluations = 0;    //!< objective evaluations the search used
};

//! Least-squares fit of y(t) ≈ offset + gain·secondOrderStep(t, ω_n, ζ) to the samples at
//! t ≥ 0 (times relative to the step). Variable projection: for each (ω_n, ζ) the offset and
//! gain that minimise the squared error are solved in closed form, so the search (Nelder–Mead
//! in ln ω_n, ln ζ, restarted from several damping ratios) runs over two nonlinear
//! parameters only. Needs ≥ 8 samples spanning a visible change.
SecondOrderFit fitSecondOrderStep(std::span<const double> t, std::span<const double> y);

} // namespace hatpic::analysis
