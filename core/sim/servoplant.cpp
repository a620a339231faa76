#include "servoplant.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hatpic {

ServoPlant::ServoPlant(double torqueLimit, double theta)
    : m_torqueLimit(torqueLimit), m_theta(theta), m_command(theta)
{}

double ServoPlant::stallTorque() const
{
    return kTorqueConstant * kSupplyVoltage / kResistance;
}

double ServoPlant::proportionalGain() const
{
    const double wn = 2.0 * std::numbers::pi * kBandwidthHz;
    return kInertia * wn * wn;
}

double ServoPlant::derivativeGain() const
{
    // The shaft's own viscous friction already damps; the loop adds the rest.
    const double wn = 2.0 * std::numbers::pi * kBandwidthHz;
    return std::max(0.0, 2.0 * kDampingRatio * kInertia * wn - kViscousFriction);
}

double ServoPlant::torqueFor(double theta, double omega) const
{
    const double demand = proportionalGain() * (m_command - theta) - derivativeGain() * omega;
    const double limited = std::clamp(demand, -m_torqueLimit, m_torqueLimit);
    // DC motor torque–speed line at full supply voltage: the torque available falls
    // linearly from the stall torque at rest to zero at the no-load speed.
    const double stall = stallTorque();
    const double high = stall * (1.0 - omega / kNoLoadSpeed);
    const double low = -stall * (1.0 + omega / kNoLoadSpeed);
    return std::clamp(limited, low, high);
}

void ServoPlant::setTorqueEnabled(bool enabled)
{
    m_torqueEnabled = enabled;
    if (!enabled)
        m_motorTorque = 0.0;
}

void ServoPlant::step(double dt, double tauOp)
{
    // Semi-implicit Euler; stable for dt ≤ 1e-4 s with these gains (poles near 160 rad/s).
    m_motorTorque = m_torqueEnabled ? torqueFor(m_theta, m_omega) : 0.0;
    const double accel = (m_motorTorque + tauOp - kViscousFriction * m_omega) / kInertia;
    m_omega += accel * dt;
    m_theta += m_omega * dt;
}

} // namespace hatpic
