// The bridge's DDS side: one Cyclone DDS participant with the writers and readers of ros.md,
// on the wire exactly as rmw_cyclonedds puts ROS 2 topics (rt/<name>, <pkg>::msg::dds_::<T>_,
// XCDR1). Only copies values between ReferenceMessages and the IDL-generated C types.
#pragma once

#include "profile/bridgesettings.h"
#include "referencemessages.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

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
    //! Called on a Cyclone DDS thread, once per wrench received (stamped or not).
    using WrenchHandler = std::function<void(const Wrench &)>;

    //! Creates the participant in settings.domainId (CYCLONEDDS_URI applies as usual), the
    //! writers of every named outgoing topic and the readers of the wrench topics. Null with
    //! `*error` set to one sentence when Cyclone DDS refuses.
    static std::unique_ptr<RosEndpoints> open(const BridgeSettings &settings,
                                              WrenchHandler onWrench, std::string *error);
    ~RosEndpoints(); //!< deletes the participant; no handler call runs after it returns
    RosEndpoints(const RosEndpoints &) = delete;
    RosEndpoints &operator=(const RosEndpoints &) = delete;

    //! Writes `m` on every outgoing topic that has a name.
    void publish(const ReferenceMessages &m);

    std::uint64_t written(OutTopic topic) const { return m_written[int(topic)]; }
    std::uint64_t writeErrors() const { return m_writeErrors; }

private:
    struct Handles;
    friend struct Handles;
    explicit RosEndpoints(const BridgeSettings &settings, WrenchHandler onWrench);
    std::string create();
    void takeWrenches(std::int32_t reader);

    BridgeSettings m_settings;
    WrenchHandler m_onWrench;
    std::unique_ptr<Handles> m_h;
    std::array<std::uint64_t, kOutTopicCount> m_written{};
    std::uint64_t m_writeErrors = 0;
};

} // namespace hatpic::bridge
