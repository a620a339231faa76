// The admittance filter's torque balance term by term (paper eq. 1, model.md § 3), for a
// breakdown plot of recorded or live samples:
//
//     D_adm·ω̇  +  M_adm·ω  =  −τ  +  τ_total
//     inertial    damping     τ_op   rendered: τ_rec + τ_fx + τ_ext, clamped to ±tau_limit
//
// The paper's letters are kept: D_adm is the virtual *inertia* (so D_adm·ω̇ is the inertial
// term) and M_adm the virtual *damping* (M_adm·ω the damping term). τ_op = −τ is the operator's
// torque; τ_fx the effects' torque (effects.md § 1), 0 without effects. What tau_limit took
// away is (τ_rec + τ_fx + τ_ext) − τ_total on a sample the device flagged saturated (it
// clamps, model.md § 2), from the rendered τ_total the sample carries; 0 on any other.
//
// Plain C++20, no Qt.
#pragma once

#include "params.h"

namespace hatpic {

//! One sample's quantities the balance reads (SI). ω̇ is not measured: see rateOfChange().
struct TorqueBalanceInput
{
    double omega = 0;       //!< ω [rad/s]
    double omegaDot = 0;    //!< ω̇ [rad/s²]
    double tau = 0;         //!< measured interaction torque τ [N·m]
    double tauRec = 0;      //!< τ_rec [N·m]
    double tauExt = 0;      //!< τ_ext [N·m]
    double tauTotal = 0;    //!< τ_total as rendered (clamped) [N·m]
    double tauFx = 0;       //!< τ_fx, the effects' torque (effects.md) [N·m]
    bool saturated = false; //!< the device's `saturated` flag: the clamp acted
};

//! The terms, all in N·m.
struct TorqueTerms
{
    double inertial = 0; //!< D_adm·ω̇
    double damping = 0;  //!< M_adm·ω
    double tauOp = 0;    //!< −τ, the operator's torque
    double tauRec = 0;   //!< τ_rec
    double tauExt = 0;   //!< τ_ext
    double tauFx = 0;    //!< τ_fx, the effects' torque
    double clipped = 0;  //!< (τ_rec + τ_fx + τ_ext) − τ_total when saturated, else 0
    //! D_adm·ω̇ + M_adm·ω − (τ_op + τ_total): what eq. (1) leaves unexplained (ω̇ is estimated
    //! from samples, so it is not exactly 0).
    double residual = 0;
};

TorqueTerms torqueTerms(const DeviceParams &params, const TorqueBalanceInput &in);

//! The slope (v1 − v0)/(t1 − t0); NaN when t1 ≤ t0 or a value is not finite. From a sample to
//! the next it is the estimate of ω̇ the breakdown uses: a sample's torques are held over the
//! step that follows it (model.md § 3, zero-order hold), so the forward difference of ω is the
//! mean ω̇ they drive; exact at the control rate, an average over the skipped cycles when the
//! telemetry is thinned.
double rateOfChange(double t0, double v0, double t1, double v1);

} // namespace hatpic
