// Admittance filter D_adm·ω̇ + M_adm·ω = −τ + τ_total (paper eq. 1, model.md § 3).
//
// The exact zero-order-hold step depends on the parameters and the step length only through
// four coefficients. AdmittanceStepper computes them once (in double, where e^{−αh} is cheap
// to get right) and then steps in any scalar type: double on the host, float on the ESP32,
// whose FPU is single precision.
#pragma once

#include "params.h"

#include <cmath>

namespace hatpic {

template<typename T> struct BasicAdmittanceState
{
    T theta{}; //!< knob angle [rad]
    T omega{}; //!< knob rate [rad/s]
};
using AdmittanceState = BasicAdmittanceState<double>;

//! The step's coefficients for one parameter set and step length h, with x = α·h,
//! α = M_adm/D_adm, φ1(x) = (1 − e^{−x})/x, φ2(x) = (x − 1 + e^{−x})/x²:
//!   ω' = ω·e^{−x} + u·h·φ1(x)/D
//!   θ' = θ + ω·h·φ1(x) + u·h²·φ2(x)/D
//! This is algebraically model.md's formula, but it divides by D (≥ 1e-6) instead of M (which
//! may be arbitrarily close to 0) and has no cancellation when x is tiny.
namespace detail {

// φ1(x) = (1 − e^{−x})/x, with φ1(0) = 1. expm1 keeps full precision for tiny x.
template<typename T> T phi1(T x)
{
    if (x == T(0))
        return T(1);
    return -std::expm1(-x) / x;
}

// φ2(x) = (x − 1 + e^{−x})/x², with φ2(0) = 1/2. The closed form cancels catastrophically
// for small x (relative error ≈ 2ε/x), so below 1/2 the alternating series
// Σ (−x)ⁿ/(n+2)! is summed instead; it converges in at most about 16 terms there.
template<typename T> T phi2(T x)
{
    if (x >= T(0.5))
        return (x + std::expm1(-x)) / (x * x);
    T term = T(0.5);
    T sum = term;
    for (int n = 1; n < 30; ++n) {
        term *= -x / T(n + 2);
        const T next = sum + term;
        if (next == sum)
            break;
        sum = next;
    }
    return sum;
}

} // namespace detail

struct AdmittanceCoefficients
{
    double decay = 1;        //!< e^{−x} [-]
    double omegaToTheta = 0; //!< h·φ1(x) [s]
    double uToOmega = 0;     //!< h·φ1(x)/D [rad/s per N·m]
    double uToTheta = 0;     //!< h²·φ2(x)/D [rad per N·m]

    //! @param h step length [s], h > 0
    static AdmittanceCoefficients compute(const DeviceParams &params, double h);
};

template<typename T> class AdmittanceStepper
{
public:
    AdmittanceStepper() = default;
    explicit AdmittanceStepper(const AdmittanceCoefficients &c)
        : m_decay(T(c.decay)), m_omegaToTheta(T(c.omegaToTheta)), m_uToOmega(T(c.uToOmega)),
          m_uToTheta(T(c.uToTheta))
    {}

    //! The step for inertia `D`, damping `M` and step `h`, computed in T itself: for a damping
    //! that changes from cycle to cycle (the passivity controller's M_adm + β), where the
    //! ESP32 must not fall back to software double arithmetic.
    static AdmittanceStepper computeIn(T D, T M, T h)
    {
        const T x = (M / D) * h;
        const T f1 = detail::phi1(x);
        AdmittanceStepper s;
        s.m_decay = std::exp(-x);
        s.m_omegaToTheta = h * f1;
        s.m_uToOmega = h * f1 / D;
        s.m_uToTheta = h * h * detail::phi2(x) / D;
        return s;
    }

    //! One step with u = −τ + τ_total held constant over it [N·m].
    BasicAdmittanceState<T> step(BasicAdmittanceState<T> s, T u) const
    {
        BasicAdmittanceState<T> next;
        next.omega = s.omega * m_decay + u * m_uToOmega;
        next.theta = s.theta + s.omega * m_omegaToTheta + u * m_uToTheta;
        return next;
    }

private:
    T m_decay = T(1);
    T m_omegaToTheta = T(0);
    T m_uToOmega = T(0);
    T m_uToTheta = T(0);
};

//! One exact zero-order-hold step of the filter.
//! @param u  −τ + τ_total, held constant over the step [N·m]
//! @param h  step length [s], h > 0
//! Stable for every h > 0 and every valid parameter set.
AdmittanceState admittanceStep(const DeviceParams &params, AdmittanceState state, double u,
                               double h);

} // namespace hatpic
