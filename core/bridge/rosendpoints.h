// The bridge's ROS side. ROS 2: one Cyclone DDS participant with the writers and readers of
// ros.md, on the wire exactly as rmw_cyclonedds puts ROS 2 topics (rt/<name>,
// <pkg>::msg::dds_::<T>_, XCDR1); it only copies values between ReferenceMessages and the
// IDL-generated C types. ROS 1 (settings.rosVersion 1): a hatpic::ros node "hatpic_bridge"
// with the same topics and types.
#pragma once

#include "profile/bridgesettings.h"
#include "referencemessages.h"

#include "ros/node.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hatpic::bridge {

//! The outgoing topics, in the order of every per-topic array.
enum class OutTopic { JointStates, Twist, Pose, Feedback };
constexpr int kOutTopicCount = 4;
const char *outTopicKey(OutTopic topic); //!< "joint_states", "twist", "pose", "feedback"

class RosEndpoints
{
public:
    //! force x y z, torque x y z of a wrench that arrived.
    using Wrench = std::array<double, 6>;
    //! Called on a middleware thread, once per wrench received (stamped or not).
    using WrenchHandler = std::function<void(const Wrench &)>;

    //! ROS 2: creates the participant in settings.domainId (CYCLONEDDS_URI applies as usual),
    //! the writers of every named outgoing topic and the readers of the wrench topics. ROS 1:
    //! the node's publishers and subscriptions (ROS_MASTER_URI applies). Null with `*error`
    //! set to one sentence when the middleware refuses.
    static std::unique_ptr<RosEndpoints> open(const BridgeSettings &settings,
                                              WrenchHandler onWrench, std::string *error);
    ~RosEndpoints(); //!< deletes the participant; no handler call runs after it returns
    RosEndpoints(const RosEndpoints &) = delete;
    RosEndpoints &operator=(const RosEndpoints &) = delete;

    //! Writes `m` on every outgoing topic that has a name.
    void publish(const ReferenceMessages &m);

    std::uint64_t written(OutTopic topic) const;
    std::uint64_t writeErrors() const;
    //! Where the endpoints are, for people ("ROS 2, domain 0", "ROS 1, master http://…").
    std::string where() const;

private:
    struct Handles;
    friend struct Handles;
    explicit RosEndpoints(const BridgeSettings &settings, WrenchHandler onWrench);
    std::string create();
    std::string createOnNode(); //!< ROS 1, through hatpic::ros
    void publishOnNode(const ReferenceMessages &m);
    void takeWrenches(std::int32_t reader);

    BridgeSettings m_settings;
    WrenchHandler m_onWrench;
    std::unique_ptr<Handles> m_h;
    std::array<std::uint64_t, kOutTopicCount> m_written{};
    std::uint64_t m_writeErrors = 0;

    // ROS 1: the node and its endpoints (per OutTopic).
    std::unique_ptr<ros::Node> m_node;
    std::array<std::unique_ptr<ros::Publisher>, kOutTopicCount> m_publishers;
    std::vector<std::unique_ptr<ros::Subscription>> m_subscriptions;
};

} // namespace hatpic::bridge
