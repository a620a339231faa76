// A ROS 2 node's view of the bridge, for tests: a Cyclone DDS participant built the way
// rmw_cyclonedds builds one — its own IDL-generated types (rostestmessages.idl) without type
// information, so that it matches by type name as a real node does, and rmw's QoS — that reads
// the bridge's topics and publishes wrenches as the published driver does (best effort,
// transient local, keep last 1). By default in a test domain on loopback (lo, no multicast,
// unicast peer 127.0.0.1), or in a domain configured as a test says (as rmw configures it from
// ROS's discovery variables).
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
//! Call it before any other thread starts: setenv beside another thread's getenv is undefined
//! behaviour (a DeviceClient's session thread reads HATPIC_REALTIME as it starts).
HATPIC_ROSPEER_API void confineDdsToLoopback();

//! confineDdsToLoopback() as a test's first member, declared before the members that start
//! threads (a DeviceClient, a Bridge), so that it runs first.
struct LoopbackDds
{
    LoopbackDds() { confineDdsToLoopback(); }
};

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

struct VectorsGot //!< (Twist|Wrench)[Stamped]: (linear, angular) or (force, torque)
{
    TimeGot stamp; //!< zero for the unstamped types
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

struct JogGot //!< control_msgs/JointJog
{
    TimeGot stamp;
    std::vector<std::string> names;
    std::vector<double> displacements, velocities;
    double duration = 0;
};

struct ImuGot //!< sensor_msgs/Imu
{
    TimeGot stamp;
    std::string frame;
    std::array<double, 4> orientation{};
    std::array<double, 9> orientationCovariance{}, angularVelocityCovariance{},
        linearAccelerationCovariance{};
};

//! A remote reader or writer as DDS's built-in topics announce it.
struct EndpointSeen
{
    std::string topic;    //!< "rt/hatpic/twist"
    std::string type;     //!< "geometry_msgs::msg::dds_::TwistStamped_"
    std::string userData; //!< USER_DATA as text ("typehash=RIHS01_…;")
    bool reliable = false;
    friend bool operator==(const EndpointSeen &, const EndpointSeen &) = default;
};

class HATPIC_ROSPEER_API RosTestPeer
{
public:
    //! Where the peer publishes geometry_msgs/Wrench (ROS name "/robot/wrench").
    static constexpr const char *kUnstampedTopic = "rt/robot/wrench";
    //! Where it reads geometry_msgs/Twist (ROS name "/haptic_twist", the published driver's).
    static constexpr const char *kTwistUnstampedTopic = "rt/haptic_twist";
    //! Where it publishes std_msgs/Bool, a dead man (ROS name "/teleop/enable").
    static constexpr const char *kEnableTopic = "rt/teleop/enable";
    //! Where it publishes std_msgs/String and std_msgs/UInt8, an operator's choice of axis (ROS
    //! names "/teleop/axis" and "/teleop/axis_index").
    static constexpr const char *kAxisTopic = "rt/teleop/axis";
    static constexpr const char *kAxisIndexTopic = "rt/teleop/axis_index";
    //! Where it reads control_msgs/JointJog (ROS name "/servo_node/delta_joint_cmds", MoveIt
    //! Servo's).
    static constexpr const char *kJointJogTopic = "rt/servo_node/delta_joint_cmds";

    //! A peer in `domain`. With `domainConfig` the peer creates that domain itself with this
    //! Cyclone DDS configuration (dds_create_domain, as rmw_cyclonedds does), and the process
    //! must have no other participant in it. With `ns` ("/knob1") the bridge's default topics
    //! are read and written under it (the enable and jog topics stay as they are).
    explicit RosTestPeer(int domain, const std::string &domainConfig = {},
                         const std::string &ns = {});
    ~RosTestPeer();
    RosTestPeer(const RosTestPeer &) = delete;
    RosTestPeer &operator=(const RosTestPeer &) = delete;

    bool isValid() const;
    //! The bridge's wrench reader (of the stamped or the unstamped topic) matched ours.
    bool wrenchMatched(bool unstamped = false) const;
    //! A writer of the bridge's matched our reliable twist reader.
    bool twistMatched() const;
    //! A WrenchStamped; its stamp is `stampSeconds` [s since the Unix epoch], 0 by default (as
    //! a sender that does not fill it); its frame_id `frame`.
    void publishWrench(double forceZ, double torqueZ = 0, double stampSeconds = 0,
                       const std::string &frame = "robot");
    //! A WrenchStamped with every component (unstamped, frame "robot"): force [N], torque [N·m].
    void publishWrench(const std::array<double, 3> &force, const std::array<double, 3> &torque);
    //! A TwistStamped on /hatpic/twist (under the namespace) as the bridge sends it (reliable,
    //! keep last 1), for a robot's subscription; its frame_id `frame`. The writer is made on
    //! the first call, so until then the peer's own twist readers hear only the bridge.
    void publishTwist(double linearX, const std::string &frame = "hatpic");
    void publishUnstampedWrench(double forceZ);
    void publishEnable(bool enabled);
    //! An axis by name (std_msgs/String) or by number (std_msgs/UInt8), reliable, keep last 1.
    void publishAxis(const std::string &name);
    void publishAxisIndex(std::uint8_t index);
    //! The bridge's reader of the axis topic (by number: `index`) matched ours.
    bool axisMatched(bool index = false) const;

    //! Takes everything that arrived into joints, twists, … (reliable readers, as ROS 2's
    //! default subscription) and bestEffortTwists (a sensor-data subscription).
    void take();
    void clear();
    //! Every remote writer (reader) discovered so far, in the order announced.
    std::vector<EndpointSeen> publications();
    std::vector<EndpointSeen> subscriptions();

    std::vector<JointGot> joints;
    std::vector<VectorsGot> twists;
    std::vector<VectorsGot> bestEffortTwists;
    std::vector<VectorsGot> unstampedTwists;
    std::vector<PoseGot> poses;
    std::vector<VectorsGot> feedbacks;
    std::vector<JogGot> jogs;
    std::vector<ImuGot> imus; //!< on /hatpic/imu (under the namespace)

private:
    struct Entities;
    std::unique_ptr<Entities> m_e;
    std::vector<EndpointSeen> m_publications, m_subscriptions;
};

} // namespace hatpic::test
