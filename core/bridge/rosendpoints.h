// The bridge's ROS side: one node (hatpic::ros) of the ROS the settings name — ROS 2 on the
// wire as rmw_cyclonedds puts it, or ROS 1 through roscpp — with the publishers and
// subscriptions of ros.md, made from the bridge's settings. It only
// turns ReferenceMessages into ROS messages and a wrench message into a Wrench.
#pragma once

#include "profile/bridgesettings.h"
#include "referencemessages.h"

#include "ros/node.h"

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace hatpic::bridge {

//! The outgoing topics, in the order of every per-topic array.
enum class OutTopic { JointStates, Twist, TwistUnstamped, Pose, Feedback, JointJog, Imu };
constexpr int kOutTopicCount = 7;
//! "joint_states", "twist", "twist_unstamped", "pose", "feedback", "joint_jog", "imu"
const char *outTopicKey(OutTopic topic);

class RosEndpoints
{
public:
    //! A wrench that arrived, as either ROS carries it (the same ros::WrenchStamped).
    struct Wrench
    {
        std::array<double, 6> values{}; //!< force x y z [N], torque x y z [N·m]
        //! The header's stamp: the sender's wall clock [s since the Unix epoch]; NaN for the
        //! unstamped topic, and for a stamp of 0 (a sender that does not fill it).
        double stamp = std::numeric_limits<double>::quiet_NaN();
        //! The bridge's own feedback message come back (a relay from the feedback topic onto
        //! the wrench topic): its header — frame_id and stamp — is one the bridge published on
        //! the feedback topic in the last kEchoMemoryS. Such a wrench is never the robot's.
        bool echo = false;
    };
    //! How long the headers of the feedback published are remembered [s]: the longest a
    //! wrench stays fresh (kMaxStaleAfter).
    static constexpr double kEchoMemoryS = kMaxStaleAfter;
    //! Called on a middleware thread, once per wrench received (stamped or not).
    using WrenchHandler = std::function<void(const Wrench &)>;
    //! Called on a middleware thread, once per std_msgs/Bool on the enable topic.
    using EnableHandler = std::function<void(bool)>;
    //! An axis the operator asked for on an axis topic (ros.md § Choosing the knob's axis).
    struct AxisRequest
    {
        std::optional<Component> axis; //!< none: the message named no axis
        std::string text;              //!< what came, for the refusal (echoedText())
    };
    //! Called on a middleware thread, once per message on either axis topic.
    using AxisHandler = std::function<void(const AxisRequest &)>;
    //! What the subscriptions call; each must be set.
    struct Handlers
    {
        WrenchHandler wrench;
        EnableHandler enable;
        AxisHandler axis;
    };
    //! The request a message on an axis topic makes: a std_msgs/String's text (trimmed) names
    //! a component as Component::parse() reads it; a std_msgs/UInt8 is its place (slot()).
    static AxisRequest axisRequest(const ros::Message &message);

    //! Opens the node "hatpic_bridge" of settings.rosVersion in settings.nodeNamespace (ROS 2:
    //! in settings.domainId, ROS's discovery variables and CYCLONEDDS_URI apply; ROS 1:
    //! ROS_MASTER_URI and ROS_NAMESPACE apply), a publisher of every named outgoing topic with
    //! writerQos() and a subscription of every named input topic (wrench, enable, axis) with
    //! ros::Qos::matchAny(), each under the namespace as topicInNamespace() says. Null with
    //! `*error` set to one sentence when the middleware refuses.
    static std::unique_ptr<RosEndpoints> open(const BridgeSettings &settings, Handlers handlers,
                                              std::string *error);
    ~RosEndpoints(); //!< closes the node; no handler call runs after it returns
    RosEndpoints(const RosEndpoints &) = delete;
    RosEndpoints &operator=(const RosEndpoints &) = delete;

    //! The QoS of the bridge's publishers: settings.qos and settings.depth, volatile.
    static ros::Qos writerQos(const BridgeSettings &settings);

    //! The name `topic` of `settings` has on the network (topicInNamespace() in the node's
    //! effective namespace).
    static std::string resolved(const BridgeSettings &settings, std::string Topics::*topic);

    //! Publishes `m` on every outgoing topic that has a name.
    void publish(const ReferenceMessages &m);

    std::uint64_t written(OutTopic topic) const;
    std::uint64_t writeErrors() const;
    //! Where the endpoints are, for people ("ROS 2, domain 0", "ROS 1, master http://…").
    std::string where() const;

private:
    RosEndpoints(const BridgeSettings &settings, Handlers handlers);
    std::string create();

    //! Notes a feedback message's stamp (publish()); whether `header` is one of them (the
    //! middleware's threads).
    void rememberFeedback(const ros::Time &stamp);
    bool isEcho(const ros::Header &header);

    BridgeSettings m_settings;
    std::vector<std::string> m_jointNames; //!< each knob's, knob 1 first (jointNames())
    Handlers m_handlers;
    std::mutex m_echoMutex;                 //!< guards the two below; nothing is called with it
    std::deque<ros::Time> m_feedbackStamps; //!< published, oldest first
    std::set<std::pair<std::int32_t, std::uint32_t>> m_feedbackStampSet;
    std::unique_ptr<ros::Node> m_node;
    std::array<std::unique_ptr<ros::Publisher>, kOutTopicCount> m_publishers;
    std::vector<std::unique_ptr<ros::Subscription>> m_subscriptions;
};

} // namespace hatpic::bridge
