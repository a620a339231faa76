// hatpic-robot-sim's node (robot.md): the robot model stepped every millisecond on the host's
// monotonic clock on a thread of its own, its reference read from the knob's twist, its
// estimated wrench and its pose published — through the same ROS layer as hatpic-bridge
// (core/ros), so every topic, type, QoS and discovery rule is the bridge's. The network
// between knob and robot can be made worse in both directions (robot/linkfaults.h).
#pragma once

#include "profile/bridgesettings.h"
#include "robot/linkfaults.h"
#include "robot/robotmodel.h"
#include "ros/node.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
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
    double rateHz = 200;                            //!< outputs per second (≤ 1000) [Hz]
    double staleAfter = 0.5; //!< v_ref = 0 once the last twist is this old [s]
    ros::NodeOptions node{ros::RosVersion::Ros2, "hatpic_robot_sim", -1};
};

constexpr double kMaxRobotRateHz = 1000; //!< one output per step
constexpr double kMaxRobotStale = 10;    //!< [s]

//! Every broken rule, fields named as the options: the robot's and the faults' rules, the
//! rate (0 < rate ≤ 1000), stale (0 < stale ≤ 10), topic names (an output may be empty:
//! off). Empty means valid.
std::vector<Violation> validate(const RobotSimSettings &settings);

class RobotSimulator
{
public:
    struct Status
    {
        double x = 0;                  //!< [m]
        double v = 0;                  //!< [m/s]
        double vRef = 0;               //!< [m/s]
        double wallForce = 0;          //!< F_e [N]
        std::uint64_t twistsIn = 0;    //!< twists that reached the robot (after the faults)
        std::uint64_t wrenchesOut = 0; //!< wrenches published (after the faults)
        std::uint64_t posesOut = 0;
        std::uint64_t dropped = 0;  //!< lost or overflowed on purpose, both directions
        std::uint64_t overruns = 0; //!< steps the host was too late for (caught up, or skipped)
        bool stale = true;          //!< no fresh twist: v_ref held at 0

        //! The status line hatpic-robot-sim prints each second (docs/teleop.md): "x 0.05625 m,
        //! v -1.38e-05 m/s, v_ref …". A value below kNegligible prints as 0 (issue 27: a
        //! velocity decaying at rest printed as "v -1.745e-257").
        std::string line() const;
    };
    //! Below this, x [m], v [m/s], v_ref [m/s] and F_e [N] are nothing: a picometre, a
    //! piconewton, far under any robot's resolution.
    static constexpr double kNegligible = 1e-12;

    //! Opens the node, the subscription and the publishers, and starts stepping. Null with
    //! `*error` one sentence when settings are invalid or the middleware refuses.
    static std::unique_ptr<RobotSimulator> start(const RobotSimSettings &settings,
                                                 std::string *error);
    ~RobotSimulator(); //!< stops stepping, then closes the endpoints and the node
    RobotSimulator(const RobotSimulator &) = delete;
    RobotSimulator &operator=(const RobotSimulator &) = delete;

    Status status() const;
    std::string where() const { return m_node->where(); }

private:
    explicit RobotSimulator(const RobotSimSettings &settings);
    void onTwist(const ros::Message &message); //!< a middleware thread
    void run();                                //!< the stepping thread

    RobotSimSettings m_settings;
    std::unique_ptr<ros::Node> m_node;
    std::unique_ptr<ros::Publisher> m_wrenchOut;
    std::unique_ptr<ros::Publisher> m_poseOut;
    std::unique_ptr<ros::Subscription> m_twistIn;

    mutable std::mutex m_mutex; //!< guards everything below
    RobotModel m_model;
    FaultyChannel<double> m_inbound;              //!< the twist's component, knob → robot
    FaultyChannel<ros::WrenchStamped> m_outbound; //!< robot → knob
    double m_vRef = 0;
    double m_lastTwistAt = -1; //!< when the last twist reached the robot [s, monotonic]
    Status m_status;

    std::atomic<bool> m_stop{false};
    std::thread m_thread;
};

} // namespace hatpic::robot
