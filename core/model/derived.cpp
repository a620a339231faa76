#include "derived.h"

#include "stiffness.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace hatpic {

DerivedFigures deriveFigures(const DeviceParams &p, const HostParams &host)
{
    DerivedFigures f;
    const double k = p.K_max;
    f.omega_n = std::sqrt(k / p.D_adm);
    f.zeta = k > 0.0 ? p.M_adm / (2.0 * std::sqrt(k * p.D_adm))
                     : std::numeric_limits<double>::infinity();
    f.timeConstant = p.D_adm / p.M_adm;
    f.tauLimit = host.tau_limit;

    // |τ_rec|(a) is piecewise: linear in the notch band, a concave parabola between N and 2N,
    // linear beyond. Its maximum over [0, π/2] is therefore at one of these points.
    constexpr double aMax = std::numbers::pi / 2;
    const double dK = p.K_max - p.K_min;
    double candidates[] = {std::min(p.N, aMax), std::min(2.0 * p.N, aMax), aMax, 0.0};
    if (dK > 0.0)
        candidates[3] = std::clamp(p.N * (p.K_min + 2.0 * dK) / (2.0 * dK), 0.0, aMax);
    for (double a : candidates) {
        const double tau = std::abs(recenteringTorque(p, p.theta0 + a));
        if (tau > f.peakTauRec) {
            f.peakTauRec = tau;
            f.peakAngle = a;
        }
    }
    return f;
}

} // namespace hatpic
