#include "admittance.h"

#include <cmath>

namespace hatpic {

AdmittanceState admittanceStep(const DeviceParams &p, AdmittanceState s, double u, double h)
{
    const double alpha = p.M_adm / p.D_adm; // [1/s]
    // 1 − e^{−αh} computed with expm1 so that tiny αh keeps full precision.
    const double decay = -std::expm1(-alpha * h);
    const double omegaInf = u / p.M_adm; // steady-state rate under u [rad/s]
    AdmittanceState next;
    next.omega = s.omega * std::exp(-alpha * h) + omegaInf * decay;
    next.theta = s.theta + omegaInf * h + (s.omega - omegaInf) * decay / alpha;
    return next;
}

} // namespace hatpic
