// Figures a tuning UI shows for a parameter set (model.md § 3, last paragraph).
#pragma once

#include "params.h"

namespace hatpic {

struct DerivedFigures
{
    double omega_n = 0.0;      //!< natural frequency sqrt(K_max/D_adm) [rad/s]
    double zeta = 0.0;         //!< damping ratio M_adm/(2·sqrt(K_max·D_adm)); +inf when K_max = 0
    double timeConstant = 0.0; //!< D_adm/M_adm [s]
    double peakTauRec = 0.0;   //!< largest |τ_rec| over |θ−θ0| ≤ π/2 [N·m]
    double peakAngle = 0.0;    //!< |θ−θ0| where that peak occurs [rad]
    double tauLimit = 0.0;     //!< actuator limit it is compared with [N·m]

    bool saturates() const { return peakTauRec > tauLimit; }
    //! Under-damped enough to ring visibly (ζ < 0.3).
    bool rings() const { return zeta < kRingingZeta; }

    static constexpr double kRingingZeta = 0.3;
};

DerivedFigures deriveFigures(const DeviceParams &device, const HostParams &host);

} // namespace hatpic
