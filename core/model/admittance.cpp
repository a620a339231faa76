#include "admittance.h"

#include <cmath>

namespace hatpic {

AdmittanceCoefficients AdmittanceCoefficients::compute(const DeviceParams &p, double h)
{
    const double alpha = p.M_adm / p.D_adm; // [1/s]
    const double x = alpha * h;
    const double f1 = detail::phi1(x);
    AdmittanceCoefficients c;
    c.decay = std::exp(-x);
    c.omegaToTheta = h * f1;
    c.uToOmega = h * f1 / p.D_adm;
    c.uToTheta = h * h * detail::phi2(x) / p.D_adm;
    return c;
}

AdmittanceState admittanceStep(const DeviceParams &p, AdmittanceState s, double u, double h)
{
    return AdmittanceStepper<double>(AdmittanceCoefficients::compute(p, h)).step(s, u);
}

} // namespace hatpic
