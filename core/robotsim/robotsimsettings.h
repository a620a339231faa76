// hatpic-robot-sim's settings and its options, described once (robot.md, docs/teleop.md): the
// same kind of table as the bridge's settings (profile/bridgesettings.h, kSettings). The
// options both programs have (ROS version, domain) are kSettings' own rows; a number's range
// and a topic name's rule are worded by the same functions (rangeRule(), topicNameProblem()).
#pragma once

#include "profile/bridgesettings.h"
#include "robot/linkfaults.h"
#include "robot/robotmodel.h"
#include "ros/node.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace hatpic::robot {

struct RobotSimSettings
{
    RobotParams robot;
    LinkFaults faults;      //!< both directions: the twist in, the wrench out
    std::uint64_t seed = 1; //!< of the faults' randomness
    bridge::Component axis; //!< the twist component followed, and the wrench's (linear.x)
    std::string twistTopic = "/hatpic/twist";       //!< in: geometry_msgs/TwistStamped
    std::string wrenchTopic = "/wrench_estimation"; //!< out: geometry_msgs/WrenchStamped
    std::string poseTopic = "/robot/pose";          //!< out: geometry_msgs/PoseStamped
    std::string frameId = "robot";                  //!< header.frame_id of what goes out
    double rateHz = 200;                            //!< outputs per second [Hz]
    double staleAfter = 0.5; //!< v_ref = 0 once the last twist is this old [s]
    ros::NodeOptions node{ros::RosVersion::Ros2, "hatpic_robot_sim", -1, {}};
};

constexpr double kMaxRobotRateHz = 1000; //!< one output per step
constexpr double kMaxRobotStale = 10;    //!< [s]
//! At least one output per kMaxStaleAfter (10 s, the longest a reader of the bridge waits).
constexpr double kMinRobotRateHz = 1 / bridge::kMaxStaleAfter;

// Where an option's value goes, and so how it is read.
struct RosPlace
{}; //!< node.version: 1 or 2
struct DomainPlace
{}; //!< node.domainId: 0 … kMaxDomainId
struct AxisPlace
{}; //!< axis: a twist component
struct SeedPlace
{}; //!< seed: a whole number ≥ 0
struct NamespacePlace
{}; //!< node.nameSpace: the node and its default topics under it (as the bridge's)
//! An input topic (may not be empty) or an output topic (empty: off).
struct TopicPlace
{
    std::string RobotSimSettings::*member;
    bool output;
};
using RobotSimPlace =
    std::variant<TopicPlace, double RobotSimSettings::*, double RobotParams::*,
                 double LinkFaults::*, RosPlace, DomainPlace, AxisPlace, SeedPlace, NamespacePlace>;

//! One option of hatpic-robot-sim: its name (without --), value name and --help line, where its
//! value goes, and its range when the table holds it (the robot's and the faults' own rules are
//! validate(RobotParams) and validate(LinkFaults)).
struct RobotSimOption
{
    std::string_view key;
    std::string_view valueName;
    std::string_view help;
    RobotSimPlace place;
    std::optional<bridge::SettingRange> range;
};

//! Every option, in --help's order.
const std::vector<RobotSimOption> &robotSimOptions();

//! Reads `text` into `settings`: empty, or what is wrong with its form ("needs a number").
//! Its range is validate()'s.
std::string applyOption(const RobotSimOption &option, RobotSimSettings &settings,
                        const std::string &text);

//! Every broken rule, one sentence each, named by the option: "rate: must be from 0.1 to 1000
//! Hz, got 1e-12", "twist-topic: 'a b' is not a ROS topic name (…)", the robot's (including its
//! integrator's stability bound, robotmodel.h) and the faults' rules. Empty means valid.
std::vector<std::string> validate(const RobotSimSettings &settings);

} // namespace hatpic::robot
