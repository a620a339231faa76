// Where the whole teleoperation loop comes to rest (robot.md § What the loop must do): the knob
// held by a constant hand torque, its v_ref driving the robot into the wall, the wall's force
// fed back as τ_ext. Plain C++ over the haptic model; the tests and docs/teleop.md's table
// read the figures from here.
#pragma once

#include "model/params.h"
#include "robot/robotmodel.h"

#include <optional>

namespace hatpic::robot {

struct LoopEquilibrium
{
    double theta = 0;         //!< the knob's rest angle [rad]
    double vRef = 0;          //!< the reference there [m/s]
    double wallForce = 0;     //!< F_e, the robot pressing on the wall [N]
    double tauExt = 0;        //!< the fed-back torque, clamp(gain·(−F_e), ±limit) [N·m]
    double robotPosition = 0; //!< x = x_w + F_e/k_w (x_w for a rigid wall) [m]
};

//! The first angle from θ0 towards the hand's push where τ_rec(θ) + τ_h + τ_ext(θ) = 0, with
//! the robot at rest against the wall: F_e = min(K_v·v_ref(θ), F_max) and τ_ext = clamp(gain·
//! (−F_e), ±limit). v_ref is the host's reference (model.md § 4, dead zone included) on the
//! axis that the wrench component fed back names. nullopt when the hand pushes away from the
//! wall (v_ref ≤ 0 there: the robot never touches it) or no rest exists within ±π.
//! @param tauHand the hand's torque on the knob [N·m]
//! @param gain τ_ext per newton of the fed-back component [N·m/N]
//! @param limit |τ_ext| at most [N·m]
std::optional<LoopEquilibrium> loopEquilibrium(const DeviceParams &device, const HostParams &host,
                                               double tauHand, double gain, double limit,
                                               const RobotParams &robot);

} // namespace hatpic::robot
