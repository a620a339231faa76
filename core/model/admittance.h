// Admittance filter D_adm·ω̇ + M_adm·ω = −τ + τ_total (paper eq. 1, model.md § 3).
#pragma once

#include "params.h"

namespace hatpic {

struct AdmittanceState
{
    double theta = 0.0; //!< knob angle [rad]
    double omega = 0.0; //!< knob rate [rad/s]
};

//! One exact zero-order-hold step of the filter.
//! @param u  −τ + τ_total, held constant over the step [N·m]
//! @param h  step length [s], h > 0
//! Stable for every h > 0 and every valid parameter set.
AdmittanceState admittanceStep(const DeviceParams &params, AdmittanceState state, double u,
                               double h);

} // namespace hatpic
