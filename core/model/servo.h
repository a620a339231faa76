// The STS3032 knob's figures that the model's checks, the device core and the simulator share
// (docs/simulator.md § The servo): one home, read by the simulator's plant, the controller's
// default rate and the editor's warnings.
#pragma once

namespace hatpic::servo {

//! b, the knob's own viscous damping (the armature and bearing friction) [N·m·s/rad]
constexpr double kViscousFriction = 0.0049;
//! The natural frequency of the servo's own position loop, which follows the device's
//! references [Hz]
constexpr double kPositionLoopHz = 25.0;
//! The device core's control rate, for a device that has not told its own [Hz]
constexpr double kControlRateHz = 1000;

} // namespace hatpic::servo
