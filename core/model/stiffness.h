// Re-centering stiffness and torque (paper eqs. 3–4, model.md § 2).
//
// One implementation for every scalar type: the host and the simulator evaluate it in double,
// the ESP32 firmware (single-precision FPU) in float, from a StiffnessShape<T> made once per
// parameter change.
#pragma once

#include "params.h"

#include <algorithm>
#include <cmath>

namespace hatpic {

//! Where an angle lies relative to the center.
enum class StiffnessZone {
    DeadZone, //!< |θ−θ0| < Q_dz: no re-centering torque
    Notch,    //!< Q_dz ≤ |θ−θ0| ≤ N: K_max
    Outer,    //!< |θ−θ0| > N: falls linearly to K_min at 2N, K_min beyond
};

//! The fields of a parameter set that K_rec reads, in the scalar type that evaluates it.
template<typename T> struct StiffnessShape
{
    T K_min{};  //!< [N·m/rad]
    T K_max{};  //!< [N·m/rad]
    T N{};      //!< [rad]
    T Q_dz{};   //!< [rad]
    T theta0{}; //!< [rad]

    static StiffnessShape from(const DeviceParams &p)
    {
        return {T(p.K_min), T(p.K_max), T(p.N), T(p.Q_dz), T(p.theta0)};
    }
};

template<typename T> StiffnessZone stiffnessZone(const StiffnessShape<T> &p, T theta)
{
    const T a = std::abs(theta - p.theta0);
    if (a < p.Q_dz)
        return StiffnessZone::DeadZone;
    if (a <= p.N)
        return StiffnessZone::Notch;
    return StiffnessZone::Outer;
}

//! K_rec(θ) [N·m/rad]. K_t is clamped to [K_min, K_max] (model.md § 2).
template<typename T> T recenteringStiffness(const StiffnessShape<T> &p, T theta)
{
    switch (stiffnessZone(p, theta)) {
    case StiffnessZone::DeadZone:
        return T(0);
    case StiffnessZone::Notch:
        return p.K_max;
    case StiffnessZone::Outer:
        break;
    }
    const T a = std::abs(theta - p.theta0);
    const T kT = p.K_min + (p.K_max - p.K_min) * (T(1) - (a - p.N) / p.N);
    // Literal K_t turns negative far from center; the spec clamps it (model.md § 2).
    return std::clamp(kT, std::min(p.K_min, p.K_max), std::max(p.K_min, p.K_max));
}

//! τ_rec = −K_rec(θ)·(θ−θ0) [N·m].
template<typename T> T recenteringTorque(const StiffnessShape<T> &p, T theta)
{
    return -recenteringStiffness(p, theta) * (theta - p.theta0);
}

inline StiffnessZone stiffnessZone(const DeviceParams &params, double theta)
{
    return stiffnessZone(StiffnessShape<double>::from(params), theta);
}
inline double recenteringStiffness(const DeviceParams &params, double theta)
{
    return recenteringStiffness(StiffnessShape<double>::from(params), theta);
}
inline double recenteringTorque(const DeviceParams &params, double theta)
{
    return recenteringTorque(StiffnessShape<double>::from(params), theta);
}

} // namespace hatpic
