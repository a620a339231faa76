// The simulated knob and its STS3032 smart servo (private to the simulator).
//
// A rigid knob on the servo's output shaft, driven by the servo's own position loop. The
// numbers are a published identification of the STS3032 at 6 V (see docs/simulator.md).
#pragma once

#include "model/servo.h"

namespace hatpic {

class ServoPlant
{
public:
    static constexpr double kTorqueConstant = 0.60; //!< output-shaft torque constant [N·m/A]
    static constexpr double kResistance = 3.34;     //!< armature resistance [Ω]
    static constexpr double kSupplyVoltage = 6.0;   //!< [V]
    static constexpr double kInertia = 5.4e-5;      //!< armature + knob inertia [kg·m²]
    static constexpr double kViscousFriction = servo::kViscousFriction; //!< [N·m·s/rad]
    static constexpr double kNoLoadSpeed = 10.0;                        //!< [rad/s]
    static constexpr double kBandwidthHz = servo::kPositionLoopHz;      //!< position loop [Hz]
    static constexpr double kDampingRatio = 0.7;     //!< position-loop damping ratio [-]
    static constexpr double kMinSubStepRate = 10000; //!< servo loop sub-steps per second [Hz]

    //! @param torqueLimit the servo's torque limit [N·m]; @param theta start angle [rad]
    explicit ServoPlant(double torqueLimit, double theta = 0.0);

    //! Position the servo tracks from now on [rad].
    void setCommand(double theta) { m_command = theta; }
    double command() const { return m_command; }

    //! Torque enable (the servo's register 40): off, the motor produces no torque (from now
    //! on, so motorTorque() reads 0) and the knob turns freely against the shaft's own
    //! friction. On by default.
    void setTorqueEnabled(bool enabled);
    bool torqueEnabled() const { return m_torqueEnabled; }

    //! One sub-step of length dt [s] with the operator's torque tauOp [N·m] on the knob.
    void step(double dt, double tauOp);

    double theta() const { return m_theta; }             //!< shaft angle [rad]
    double omega() const { return m_omega; }             //!< shaft rate [rad/s]
    double motorTorque() const { return m_motorTorque; } //!< torque of the last sub-step [N·m]

    double stallTorque() const;      //!< K_t·V/R [N·m]
    double proportionalGain() const; //!< position loop P gain [N·m/rad]
    double derivativeGain() const;   //!< position loop D gain [N·m·s/rad]

private:
    double torqueFor(double theta, double omega) const;

    double m_torqueLimit;
    double m_theta;
    double m_omega = 0.0;
    double m_command;
    double m_motorTorque = 0.0;
    bool m_torqueEnabled = true;
};

} // namespace hatpic
