// A ROS 2 node's view of the bridge, for tests: a Cyclone DDS participant with its own
// IDL-generated types (rostestmessages.idl) that reads the bridge's topics and publishes
// wrenches, confined to loopback (lo, no multicast, unicast peer 127.0.0.1) in a test domain.
//
// Built as a shared library whose generated symbols stay hidden: the types it uses are its
// own, never the bridge's of the same C names.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#define HATPIC_ROSPEER_API __attribute__((visibility("default")))

namespace hatpic::test {

//! Cyclone DDS on loopback only, for every participant of this process and its children.
HATPIC_ROSPEER_API void confineDdsToLoopback();

struct TimeGot
{
    std::int32_t sec = 0;
    std::uint32_t nanosec = 0;
    double seconds() const { return double(sec) + double(nanosec) * 1e-9; }
    friend bool operator==(const TimeGot &, const TimeGot &) = default;
};

struct JointGot
{
    TimeGot stamp;
    std::string frame;
    std::vector<std::string> names;
    std::vector<double> position, velocity, effort;
};

struct VectorsGot //!< TwistStamped (linear, angular) or WrenchStamped (force, torque)
{
    TimeGot stamp;
    std::string frame;
    std::array<double, 3> a{}, b{};
};

struct PoseGot
{
    TimeGot stamp;
    std::string frame;
    std::array<double, 3> position{};
    std::array<double, 4> orientation{};
};

class HATPIC_ROSPEER_API RosTestPeer
{
public:
    //! Where the peer publishes geometry_msgs/Wrench (ROS name "/robot/wrench").
    static constexpr const char *kUnstampedTopic = "rt/robot/wrench";

    explicit RosTestPeer(int domain);
    ~RosTestPeer();
    RosTestPeer(const RosTestPeer &) = delete;
    RosTestPeer &operator=(const RosTestPeer &) = delete;

    bool isValid() const;
    //! The bridge's wrench reader (of the stamped or the unstamped topic) matched ours.
    bool wrenchMatched(bool unstamped = false) const;
    void publishWrench(double forceZ, double torqueZ = 0);
    void publishUnstampedWrench(double forceZ);

    //! Takes everything that arrived into joints, twists, poses, feedbacks.
    void take();
    void clear();
    //! (DDS topic name, type name) of every remote writer discovered so far.
    std::vector<std::pair<std::string, std::string>> publications();

    std::vector<JointGot> joints;
    std::vector<VectorsGot> twists;
    std::vector<PoseGot> poses;
    std::vector<VectorsGot> feedbacks;

private:
    struct Entities;
    std::unique_ptr<Entities> m_e;
    std::vector<std::pair<std::string, std::string>> m_seen;
};

} // namespace hatpic::test
