// The joystick's state as the content of the bridge's outgoing ROS messages (ros.md § Topics),
// and the rate at which they go out. Plain C++: what goes on the wire is decided here, the
// DDS side only copies it. The rate they go out at is teleop/ratelimiter.h's.
#pragma once

#include "axisselector.h"
#include "profile/bridgesettings.h"

#include "ros/messages.h"
#include "telemetry/sample.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

namespace hatpic::bridge {

//! Each knob's quantities, knob 1 first, with the references the robot is to see (the enable
//! switch's gating applied): Sample::knob(1 … axes()).
using Knobs = std::array<AxisSample, kMaxAxes>;

//! One sample's content for every outgoing topic.
struct ReferenceMessages
{
    ros::Time stamp; //!< the sample's time on the host's wall clock
    int joints = 1;  //!< knobs in the JointState and JointJog: the device's axes
    std::array<double, kMaxAxes> position{}; //!< JointState: θ of each knob [rad]
    std::array<double, kMaxAxes> velocity{}; //!< JointState: ω [rad/s]
    std::array<double, kMaxAxes> effort{};   //!< JointState: τ [N·m]
    std::array<double, 6> twist{};           //!< linear x y z, angular x y z: v_ref on each axis
    std::array<double, 3> posePosition{};    //!< origin, plus p_ref on each linear axis [m]
    //! x y z w: the rotations by p_ref about each angular axis, knob 1's first
    std::array<double, 4> poseOrientation{0, 0, 0, 1};
    double feedbackTorque = 0; //!< WrenchStamped torque.z: the τ_ext the device applies knob 1
    std::array<double, kMaxAxes> jointJogVelocity{}; //!< JointJog velocities: v_ref [m/s, rad/s]
    //! Imu orientation, x y z w: the board's roll about x, then its pitch about y (yaw 0);
    //! none without a tilt sensor.
    std::optional<std::array<double, 4>> tilt;
};

//! Each knob's twist and pose axis, knob 1 first: `axis` for knob 1, then the settings'
//! knobAxes (parseKnobAxes(); settings validate() accepts).
using KnobComponents = std::array<Component, kMaxAxes>;
KnobComponents knobComponents(const BridgeSettings &settings, Component axis);

//! The messages for `count` knobs, stamped `wallSeconds` (Unix time of the sample), each
//! knob's references on its `axes`; a knob whose axis an earlier knob has goes in the joints
//! only (ros.md § A board's knobs). `roll` and `pitch` [rad] are the board's tilt (NaN: none).
//! `knob1Pose`: knob 1's pose on every place, its rotations composed x, y, z; null: its p_ref
//! on its axis alone.
ReferenceMessages referenceMessages(const Knobs &knobs, int count, double wallSeconds,
                                    const BridgeSettings &settings, const KnobComponents &axes,
                                    double roll = NAN, double pitch = NAN,
                                    const SlotPose *knob1Pose = nullptr);
//! The messages for every knob of `sample` as it is, knob 1's references on `axis`.
ReferenceMessages referenceMessages(const Sample &sample, double wallSeconds,
                                    const BridgeSettings &settings, Component axis);

//! The wall-clock time of a sample that is `ageSeconds` older than the newest sample of its
//! batch, which arrived at `arrivalWallSeconds`.
inline double sampleWallSeconds(double arrivalWallSeconds, double newestT, double sampleT)
{
    return arrivalWallSeconds - (newestT - sampleT);
}

} // namespace hatpic::bridge
