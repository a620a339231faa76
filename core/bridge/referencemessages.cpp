#include "referencemessages.h"

#include <cmath>

namespace hatpic::bridge {

ReferenceMessages referenceMessages(const Sample &sample, double wallSeconds,
                                    const BridgeSettings &settings, Component axis)
{
    ReferenceMessages m;
    m.stamp = ros::timeFromSeconds(wallSeconds);
    m.position = sample.theta;
    m.velocity = sample.omega;
    m.effort = sample.tau;
    m.twist[(axis.angular ? 3 : 0) + axis.index] = sample.v_ref;
    for (int i = 0; i < 3; ++i)
        m.posePosition[i] = settings.poseOrigin[i];
    if (axis.angular) {
        // p_ref is an angle about that axis: the rotation as a unit quaternion.
        m.poseOrientation[axis.index] = std::sin(sample.p_ref / 2);
        m.poseOrientation[3] = std::cos(sample.p_ref / 2);
    } else {
        m.posePosition[axis.index] += sample.p_ref;
    }
    m.feedbackTorque = sample.tau_ext;
    m.jointJogVelocity = sample.v_ref;
    return m;
}

} // namespace hatpic::bridge
