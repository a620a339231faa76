// Re-centering stiffness and torque (paper eqs. 3–4, model.md § 2).
#pragma once

#include "params.h"

namespace hatpic {

//! Where an angle lies relative to the center.
enum class StiffnessZone {
    DeadZone, //!< |θ−θ0| < Q_dz: no re-centering torque
    Notch,    //!< Q_dz ≤ |θ−θ0| ≤ N: K_max
    Outer,    //!< |θ−θ0| > N: falls linearly to K_min at 2N, K_min beyond
};

StiffnessZone stiffnessZone(const DeviceParams &params, double theta);

//! K_rec(θ) [N·m/rad]. K_t is clamped to [K_min, K_max] (model.md § 2).
double recenteringStiffness(const DeviceParams &params, double theta);

//! τ_rec = −K_rec(θ)·(θ−θ0) [N·m].
double recenteringTorque(const DeviceParams &params, double theta);

} // namespace hatpic
