#include "stiffness.h"

#include <algorithm>
#include <cmath>

namespace hatpic {

StiffnessZone stiffnessZone(const DeviceParams &p, double theta)
{
    const double a = std::abs(theta - p.theta0);
    if (a < p.Q_dz)
        return StiffnessZone::DeadZone;
    if (a <= p.N)
        return StiffnessZone::Notch;
    return StiffnessZone::Outer;
}

double recenteringStiffness(const DeviceParams &p, double theta)
{
    switch (stiffnessZone(p, theta)) {
    case StiffnessZone::DeadZone:
        return 0.0;
    case StiffnessZone::Notch:
        return p.K_max;
    case StiffnessZone::Outer:
        break;
    }
    const double a = std::abs(theta - p.theta0);
    const double kT = p.K_min + (p.K_max - p.K_min) * (1.0 - (a - p.N) / p.N);
    // Literal K_t turns negative far from center; the spec clamps it (model.md § 2).
    return std::clamp(kT, std::min(p.K_min, p.K_max), std::max(p.K_min, p.K_max));
}

double recenteringTorque(const DeviceParams &p, double theta)
{
    return -recenteringStiffness(p, theta) * (theta - p.theta0);
}

} // namespace hatpic
