// The joystick's state as the content of the bridge's outgoing ROS messages (ros.md § Topics),
// and the rate at which they go out. Plain C++: what goes on the wire is decided here, the
// DDS side only copies it. The rate they go out at is teleop/ratelimiter.h's.
#pragma once

#include "profile/bridgesettings.h"

#include "ros/messages.h"
#include "telemetry/sample.h"

#include <array>
#include <cstdint>

namespace hatpic::bridge {

//! One sample's content for every outgoing topic.
struct ReferenceMessages
{
    ros::Time stamp;                      //!< the sample's time on the host's wall clock
    double position = 0;                  //!< JointState: θ [rad]
    double velocity = 0;                  //!< JointState: ω [rad/s]
    double effort = 0;                    //!< JointState: τ [N·m]
    std::array<double, 6> twist{};        //!< linear x y z, angular x y z: v_ref on the axis
    std::array<double, 3> posePosition{}; //!< origin, plus p_ref on a linear axis [m]
    std::array<double, 4> poseOrientation{0, 0, 0, 1}; //!< x y z w: p_ref about an angular axis
    double feedbackTorque = 0;   //!< WrenchStamped torque.z: the τ_ext the device applies
    double jointJogVelocity = 0; //!< JointJog velocities[0]: v_ref [m/s or rad/s]
};

//! The messages for `sample`, stamped `wallSeconds` (Unix time of the sample), with the
//! references on `axis`.
ReferenceMessages referenceMessages(const Sample &sample, double wallSeconds,
                                    const BridgeSettings &settings, Component axis);

//! The wall-clock time of a sample that is `ageSeconds` older than the newest sample of its
//! batch, which arrived at `arrivalWallSeconds`.
inline double sampleWallSeconds(double arrivalWallSeconds, double newestT, double sampleT)
{
    return arrivalWallSeconds - (newestT - sampleT);
}

} // namespace hatpic::bridge
