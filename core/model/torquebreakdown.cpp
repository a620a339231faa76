#include "torquebreakdown.h"

#include <cmath>
#include <limits>

namespace hatpic {

TorqueTerms torqueTerms(const DeviceParams &params, const TorqueBalanceInput &in)
{
    TorqueTerms t;
    t.inertial = params.D_adm * in.omegaDot;
    t.damping = params.M_adm * in.omega;
    t.tauOp = -in.tau;
    t.tauRec = in.tauRec;
    t.tauExt = in.tauExt;
    t.tauFx = in.tauFx;
    t.clipped = in.saturated ? (in.tauRec + in.tauFx + in.tauExt) - in.tauTotal : 0.0;
    t.residual = t.inertial + t.damping - (t.tauOp + in.tauTotal);
    return t;
}

double rateOfChange(double t0, double v0, double t1, double v1)
{
    if (!(t1 > t0) || !std::isfinite(v0) || !std::isfinite(v1))
        return std::numeric_limits<double>::quiet_NaN();
    return (v1 - v0) / (t1 - t0);
}

} // namespace hatpic
