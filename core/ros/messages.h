// The ROS messages HATPIC speaks, as plain values: the same structs whichever middleware
// carries them (ROS 2 over Cyclone DDS, ROS 1 over roscpp). Field names and order follow the
// .msg files of builtin_interfaces, std_msgs, geometry_msgs and sensor_msgs; SI units as ROS
// defines them. No middleware, no Qt.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace hatpic::ros {

//! builtin_interfaces/Time (ROS 1: the header's time): seconds since the Unix epoch.
struct Time
{
    std::int32_t sec = 0;
    std::uint32_t nanosec = 0; //!< always below 10⁹

    friend bool operator==(const Time &, const Time &) = default;
};
//! Seconds since the epoch → Time (nanosec below 10⁹; non-finite or negative → 0; clamped to
//! int32 seconds).
Time timeFromSeconds(double seconds);
double seconds(const Time &time);

//! std_msgs/Header. ROS 1's `seq` is the middleware's business (roscpp fills it).
struct Header
{
    Time stamp;
    std::string frameId;

    friend bool operator==(const Header &, const Header &) = default;
};

struct Vector3
{
    double x = 0, y = 0, z = 0;
    friend bool operator==(const Vector3 &, const Vector3 &) = default;
};
struct Point
{
    double x = 0, y = 0, z = 0;
    friend bool operator==(const Point &, const Point &) = default;
};
struct Quaternion
{
    double x = 0, y = 0, z = 0, w = 1;
    friend bool operator==(const Quaternion &, const Quaternion &) = default;
};

struct Twist
{
    Vector3 linear;  //!< [m/s]
    Vector3 angular; //!< [rad/s]
    friend bool operator==(const Twist &, const Twist &) = default;
};
struct TwistStamped
{
    Header header;
    Twist twist;
    friend bool operator==(const TwistStamped &, const TwistStamped &) = default;
};

struct Wrench
{
    Vector3 force;  //!< [N]
    Vector3 torque; //!< [N·m]
    friend bool operator==(const Wrench &, const Wrench &) = default;
};
struct WrenchStamped
{
    Header header;
    Wrench wrench;
    friend bool operator==(const WrenchStamped &, const WrenchStamped &) = default;
};

struct Pose
{
    Point position; //!< [m]
    Quaternion orientation;
    friend bool operator==(const Pose &, const Pose &) = default;
};
struct PoseStamped
{
    Header header;
    Pose pose;
    friend bool operator==(const PoseStamped &, const PoseStamped &) = default;
};

//! sensor_msgs/JointState.
struct JointState
{
    Header header;
    std::vector<std::string> name;
    std::vector<double> position; //!< [rad] or [m]
    std::vector<double> velocity; //!< [rad/s] or [m/s]
    std::vector<double> effort;   //!< [N·m] or [N]
    friend bool operator==(const JointState &, const JointState &) = default;
};

//! std_msgs/Bool: the enable switch's (ros.md § Enable switch).
struct Bool
{
    bool data = false;
    friend bool operator==(const Bool &, const Bool &) = default;
};

//! std_msgs/String and std_msgs/UInt8: the operator's axis selection (ros.md § Choosing the
//! knob's axis).
struct String
{
    std::string data;
    friend bool operator==(const String &, const String &) = default;
};
struct UInt8
{
    std::uint8_t data = 0;
    friend bool operator==(const UInt8 &, const UInt8 &) = default;
};

//! control_msgs/JointJog (MoveIt Servo's joint command). ROS 2 only: Debian has no ROS 1
//! control_msgs.
struct JointJog
{
    Header header;
    std::vector<std::string> jointNames;
    std::vector<double> displacements; //!< [rad] or [m]
    std::vector<double> velocities;    //!< [rad/s] or [m/s]
    double duration = 0;               //!< [s]
    friend bool operator==(const JointJog &, const JointJog &) = default;
};

//! sensor_msgs/Imu. A covariance whose element 0 is −1 says that quantity is not given; one of
//! all zeros, that its covariance is not known (the .msg file's rules).
struct Imu
{
    Header header;
    Quaternion orientation;
    std::array<double, 9> orientationCovariance{}; //!< row major about x, y, z [rad²]
    Vector3 angularVelocity;                       //!< [rad/s]
    std::array<double, 9> angularVelocityCovariance{};
    Vector3 linearAcceleration; //!< [m/s²]
    std::array<double, 9> linearAccelerationCovariance{};
    friend bool operator==(const Imu &, const Imu &) = default;
};

//! Every message type a topic can carry; the index of each alternative is its MessageType.
using Message = std::variant<JointState, TwistStamped, Twist, PoseStamped, WrenchStamped, Wrench,
                             Bool, JointJog, Imu, String, UInt8>;
enum class MessageType {
    JointState,
    TwistStamped,
    Twist,
    PoseStamped,
    WrenchStamped,
    Wrench,
    Bool,
    JointJog,
    Imu,
    String,
    UInt8
};
constexpr int kMessageTypeCount = 11;

inline MessageType typeOf(const Message &message)
{
    return MessageType(message.index());
}
//! The ROS 2 name of a type: "geometry_msgs/msg/TwistStamped" (ROS 1 drops the "msg/").
const char *rosTypeName(MessageType type);

} // namespace hatpic::ros
