#include "referencemessages.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hatpic::bridge {

namespace {

using Quaternion = std::array<double, 4>; // x y z w

//! a ⊗ b: b's rotation, then a's.
Quaternion product(const Quaternion &a, const Quaternion &b)
{
    return {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
            a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
            a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
            a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}

//! Moves the pose of `m` by `value` along (linear) or about (angular) `c`, about the frame's own
//! axis after the rotations it already has.
void addToPose(ReferenceMessages &m, Component c, double value)
{
    if (c.angular) {
        Quaternion q{0, 0, 0, std::cos(value / 2)};
        q[std::size_t(c.index)] = std::sin(value / 2);
        m.poseOrientation = product(q, m.poseOrientation);
    } else {
        m.posePosition[std::size_t(c.index)] += value;
    }
}

} // namespace

KnobComponents knobComponents(const BridgeSettings &settings, Component axis)
{
    const auto others = parseKnobAxes(settings.knobAxes);
    if (!others) // validate() refuses such settings before they get here
        throw std::logic_error("knob axes '" + settings.knobAxes + "'");
    KnobComponents axes{axis};
    std::copy(others->begin(), others->end(), axes.begin() + 1);
    return axes;
}

ReferenceMessages referenceMessages(const Knobs &knobs, int count, double wallSeconds,
                                    const BridgeSettings &settings, const KnobComponents &axes,
                                    double roll, double pitch, const SlotPose *knob1Pose)
{
    ReferenceMessages m;
    m.stamp = ros::timeFromSeconds(wallSeconds);
    m.joints = std::clamp(count, 1, kMaxAxes);
    for (int i = 0; i < 3; ++i)
        m.posePosition[i] = settings.poseOrigin[i];
    for (int k = 0; k < m.joints; ++k) {
        const AxisSample &knob = knobs[std::size_t(k)];
        m.position[k] = knob.theta;
        m.velocity[k] = knob.omega;
        m.effort[k] = knob.tau;
        m.jointJogVelocity[k] = knob.v_ref;
        const Component c = axes[std::size_t(k)];
        if (std::find(axes.begin(), axes.begin() + k, c) != axes.begin() + k)
            continue; // the axis is an earlier knob's
        m.twist[c.slot()] = knob.v_ref;
        // p_ref about an angular axis is an angle: the rotation as a unit quaternion, after the
        // earlier knobs' (each about the frame's own axis).
        if (k == 0 && knob1Pose) {
            for (int slot = 0; slot < 6; ++slot) {
                const double value = (*knob1Pose)[std::size_t(slot)];
                if (value != 0 || slot == c.slot())
                    addToPose(m, *Component::fromSlot(slot), value);
            }
        } else {
            addToPose(m, c, knob.p_ref);
        }
    }
    m.feedbackTorque = knobs[0].tau_ext;
    if (std::isfinite(roll) && std::isfinite(pitch)) {
        const Quaternion aboutX{std::sin(roll / 2), 0, 0, std::cos(roll / 2)};
        const Quaternion aboutY{0, std::sin(pitch / 2), 0, std::cos(pitch / 2)};
        m.tilt = product(aboutY, aboutX);
    }
    return m;
}

ReferenceMessages referenceMessages(const Sample &sample, double wallSeconds,
                                    const BridgeSettings &settings, Component axis)
{
    Knobs knobs{};
    for (int n = 1; n <= sample.axes(); ++n)
        knobs[std::size_t(n - 1)] = sample.knob(n);
    return referenceMessages(knobs, sample.axes(), wallSeconds, settings,
                             knobComponents(settings, axis), sample.roll(), sample.pitch());
}

} // namespace hatpic::bridge
