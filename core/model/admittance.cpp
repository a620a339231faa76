#include "admittance.h"

#include <cmath>

namespace hatpic {

namespace {

// φ1(x) = (1 − e^{−x})/x, with φ1(0) = 1. expm1 keeps full precision for tiny x.
double phi1(double x)
{
    if (x == 0.0)
        return 1.0;
    return -std::expm1(-x) / x;
}

// φ2(x) = (x − 1 + e^{−x})/x², with φ2(0) = 1/2. The closed form cancels catastrophically
// for small x (relative error ≈ 2ε/x), so below 1/2 the alternating series
// Σ (−x)ⁿ/(n+2)! is summed instead; it converges in at most about 16 terms there.
double phi2(double x)
{
    if (x >= 0.5)
        return (x + std::expm1(-x)) / (x * x);
    double term = 0.5;
    double sum = term;
    for (int n = 1; n < 30; ++n) {
        term *= -x / (n + 2);
        const double next = sum + term;
        if (next == sum)
            break;
        sum = next;
    }
    return sum;
}

} // namespace

AdmittanceState admittanceStep(const DeviceParams &p, AdmittanceState s, double u, double h)
{
    // Exact zero-order-hold solution of D ω̇ + M ω = u over h (model.md § 3), rewritten as
    //   ω' = ω·e^{−x} + (u/D)·h·φ1(x)
    //   θ' = θ + ω·h·φ1(x) + (u/D)·h²·φ2(x),      x = α·h, α = M/D.
    // This is algebraically the spec's formula, but it divides by D (≥ 1e-6) instead of M
    // (which may be arbitrarily close to 0) and has no cancellation when x is tiny.
    const double alpha = p.M_adm / p.D_adm; // [1/s]
    const double x = alpha * h;
    const double accel = u / p.D_adm; // [rad/s²]
    const double f1 = phi1(x);
    AdmittanceState next;
    next.omega = s.omega * std::exp(-x) + accel * h * f1;
    next.theta = s.theta + s.omega * h * f1 + accel * h * h * phi2(x);
    return next;
}

} // namespace hatpic
