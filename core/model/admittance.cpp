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

AdmittanceCoefficients AdmittanceCoefficients::compute(const DeviceParams &p, double h)
{
    const double alpha = p.M_adm / p.D_adm; // [1/s]
    const double x = alpha * h;
    const double f1 = phi1(x);
    AdmittanceCoefficients c;
    c.decay = std::exp(-x);
    c.omegaToTheta = h * f1;
    c.uToOmega = h * f1 / p.D_adm;
    c.uToTheta = h * h * phi2(x) / p.D_adm;
    return c;
}

AdmittanceState admittanceStep(const DeviceParams &p, AdmittanceState s, double u, double h)
{
    return AdmittanceStepper<double>(AdmittanceCoefficients::compute(p, h)).step(s, u);
}

} // namespace hatpic
