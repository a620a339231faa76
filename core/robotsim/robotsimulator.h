// hatpic-robot-sim's node (robot.md): the robot model stepped every millisecond on the host's
// monotonic clock on a thread of its own, its reference read from the knob's twist, its
// estimated wrench and its pose published — through the same ROS layer as hatpic-bridge
// (core/ros), so every topic, type, QoS and discovery rule is the bridge's. The network
// between knob and robot can be made worse in both directions (robot/linkfaults.h).
#pragma once

#include "robot/robotend.h"
#include "robotsim/robotsimsettings.h"
#include "ros/node.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace hatpic::robot {

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

    mutable std::mutex m_mutex;         //!< guards everything below
    RobotEnd<ros::WrenchStamped> m_end; //!< the model between its two fault channels
    Status m_status;

    std::atomic<bool> m_stop{false};
    std::thread m_thread;
};

} // namespace hatpic::robot
