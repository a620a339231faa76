// What the Bridge panel's form is made of (bridgepanel.h): the Topics section's rows in their
// order, each a label, an object name and the member of bridge::Topics it edits; what the
// bridge needs, the list the ROS section opens with; and its number boxes, all made alike and
// read without losing a digit of what a profile gave them.
#pragma once

#include "model/axes.h"
#include "profile/bridgesettings.h"

#include <QString>
#include <QtGlobal>

#include <array>
#include <iterator>
#include <string>

class QDoubleSpinBox;
class QWidget;

namespace hatpic::bridgeform {

// The topic fields, in the order of the form.
struct TopicField
{
    const char *label; //!< translated
    const char16_t *name;
    std::string bridge::Topics::*topic;
};
inline constexpr TopicField kTopicFields[] = {
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "Joint states (out)"), u"bridge_topic_joint_states",
     &bridge::Topics::jointStates},
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "Twist (out)"), u"bridge_topic_twist",
     &bridge::Topics::twist},
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "Twist, unstamped (out)"),
     u"bridge_topic_twist_unstamped", &bridge::Topics::twistUnstamped},
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "Pose (out)"), u"bridge_topic_pose",
     &bridge::Topics::pose},
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "Feedback (out)"), u"bridge_topic_feedback",
     &bridge::Topics::feedback},
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "Wrench (in)"), u"bridge_topic_wrench",
     &bridge::Topics::wrench},
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "Wrench, unstamped (in)"),
     u"bridge_topic_wrench_unstamped", &bridge::Topics::wrenchUnstamped},
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "Enable, dead man (in)"), u"bridge_topic_enable",
     &bridge::Topics::enable},
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "Joint jog, MoveIt Servo (out)"),
     u"bridge_topic_joint_jog", &bridge::Topics::jointJog},
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "IMU, a board's tilt (out)"), u"bridge_topic_imu",
     &bridge::Topics::imu},
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "Axis by name (in)"), u"bridge_topic_axis",
     &bridge::Topics::axis},
    {QT_TRANSLATE_NOOP("hatpic::BridgePanel", "Axis by number (in)"), u"bridge_topic_axis_index",
     &bridge::Topics::axisIndex},
};
static_assert(std::size(kTopicFields) == 12);

// What the bridge needs to do its work, a line each (issue 21: the panel once said nothing of
// it). A new way to get a robot's wrench (a simulated robot) is one more line.
inline constexpr const char *kNeeds[] = {
    QT_TRANSLATE_NOOP("hatpic::BridgePanel",
                      "ROS 2 on the robot's network, in the domain below (the bridge speaks DDS "
                      "itself: no ROS installation needed here), or a ROS 1 master "
                      "(ROS_MASTER_URI)."),
    QT_TRANSLATE_NOOP("hatpic::BridgePanel",
                      "A robot, or any ROS node, publishing its wrench on the Wrench topic: "
                      "the knob's force."),
    QT_TRANSLATE_NOOP("hatpic::BridgePanel",
                      "No robot? hatpic-robot-sim is a simulated one, a wall to push against; "
                      "scripts/teleop-demo starts it and this tuner with the bridge running "
                      "(docs/teleop.md)."),
};

//! A box for a number from `low` to `high` with `decimals` and `suffix`, named `name`, that
//! reports a value once it is entered (no keyboard tracking).
QDoubleSpinBox *spin(QWidget *parent, const QString &name, double low, double high, int decimals,
                     const QString &suffix);

// The box's value, or `original` when the box still shows it (rounded to its decimals): an
// edit elsewhere in the panel keeps every digit the profile had.
double taken(const QDoubleSpinBox *box, double original);

//! A figure as the panel shows it: 4 significant digits, "–" when not finite (none yet).
QString number(double value);
//! The whole wrench, force then torque: "force 0 0 0.5 N, torque 0 0 0 N·m".
QString wrenchText(const std::array<double, 6> &wrench);
//! The robot sends on another component than `felt`: which, and how much (its largest).
QString otherComponentWarning(const std::array<double, 6> &wrench, bridge::Component felt);
//! τ_ext asked of the knob ("0.077 N·m"); of each knob on a board of `knobs` ("0.077 N·m;
//! knobs 2–4: 0, 0.077, -0.077 N·m").
QString torquesText(const AxisTorques &torques, int knobs);

} // namespace hatpic::bridgeform
