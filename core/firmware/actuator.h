// The knob's actuator as the control cycle sees it: measure, command, enable, disable.
//
// StsActuator (stsactuator.h) implements it over the servo bus of servo.md; the simulator's ideal
// mode implements it with the model alone. Plain C++20; used from the control context only.
#pragma once

namespace hatpic::fw {

//! One cycle's measurement, SI, with the sign conventions of model.md § 3.
template<typename T> struct Measurement
{
    T theta{}; //!< knob angle relative to the servo's center tick [rad]
    T omega{}; //!< knob rate [rad/s]
    T tau{};   //!< interaction torque of eq. (1); operator torque is −tau [N·m]
};

template<typename T> class Actuator
{
public:
    virtual ~Actuator() = default;
    //! Brings the actuator up (servo.md § 4: ping, position mode, present position, torque
    //! on) and writes the present angle to `theta`. False when it does not answer.
    virtual bool start(T &theta) = 0;
    //! This cycle's measurement. False on a bus error; `m` is then left untouched.
    virtual bool measure(Measurement<T> &m) = 0;
    //! Commands the knob to `theta` [rad]. `omega` [rad/s] is the admittance filter's rate at
    //! that position: a servo ignores it, the simulator's ideal actuator uses it.
    virtual bool command(T theta, T omega) = 0;
    //! Torque off (shutdown, fatal bus error). Safe to call more than once.
    virtual void disable() = 0;
};

} // namespace hatpic::fw
