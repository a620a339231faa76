// The message values of ros/messages.h as roscpp's generated types (Debian's std_msgs,
// geometry_msgs and sensor_msgs headers) and back, field for field; and which ROS 1 type each
// MessageType is. Only the files of core/ros/ros1 include this (it pulls in roscpp).
#pragma once

#include "ros/messages.h"

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/TwistStamped.h>
#include <geometry_msgs/Wrench.h>
#include <geometry_msgs/WrenchStamped.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Bool.h>
#include <std_msgs/String.h>
#include <std_msgs/UInt8.h>

#include <cstdlib>

#include <memory>
#include <string>

namespace hatpic::ros::ros1 {

//! roscpp's messages (and their serializers) are templates on an allocator, std::allocator
//! by default, whose `rebind` member they use; C++20 removed it. So they are instantiated here
//! with std::allocator plus that member: the same wire format and traits; only the strings
//! and vectors of a message have this allocator type.
template<typename T> struct Allocator : std::allocator<T>
{
    template<typename U> struct rebind
    {
        using other = Allocator<U>;
    };
    Allocator() = default;
    template<typename U> Allocator(const Allocator<U> &) noexcept {}
};
using JointStateMsg = sensor_msgs::JointState_<Allocator<void>>;
using TwistStampedMsg = geometry_msgs::TwistStamped_<Allocator<void>>;
using TwistMsg = geometry_msgs::Twist_<Allocator<void>>;
using PoseStampedMsg = geometry_msgs::PoseStamped_<Allocator<void>>;
using WrenchStampedMsg = geometry_msgs::WrenchStamped_<Allocator<void>>;
using WrenchMsg = geometry_msgs::Wrench_<Allocator<void>>;
using BoolMsg = std_msgs::Bool_<Allocator<void>>;
using ImuMsg = sensor_msgs::Imu_<Allocator<void>>;
using StringMsg = std_msgs::String_<Allocator<void>>;
using UInt8Msg = std_msgs::UInt8_<Allocator<void>>;
using HeaderMsg = std_msgs::Header_<Allocator<void>>;
using Vector3Msg = geometry_msgs::Vector3_<Allocator<void>>;

//! Stands for the roscpp message type T in visitType().
template<typename T> struct RosType
{
    using Type = T;
};

//! Whether ROS 1 has `type`: all but control_msgs/JointJog (Debian packages no ROS 1
//! control_msgs).
constexpr bool hasRos1Type(MessageType type)
{
    return type != MessageType::JointJog;
}

//! Calls `f(RosType<T>{})` with T the roscpp type of `type` (TwistStampedMsg, …); `type` must
//! be one hasRos1Type() accepts.
template<typename F> decltype(auto) visitType(MessageType type, F &&f)
{
    switch (type) {
    case MessageType::JointState:
        return f(RosType<JointStateMsg>{});
    case MessageType::TwistStamped:
        return f(RosType<TwistStampedMsg>{});
    case MessageType::Twist:
        return f(RosType<TwistMsg>{});
    case MessageType::PoseStamped:
        return f(RosType<PoseStampedMsg>{});
    case MessageType::WrenchStamped:
        return f(RosType<WrenchStampedMsg>{});
    case MessageType::Wrench:
        return f(RosType<WrenchMsg>{});
    case MessageType::Bool:
        return f(RosType<BoolMsg>{});
    case MessageType::Imu:
        return f(RosType<ImuMsg>{});
    case MessageType::String:
        return f(RosType<StringMsg>{});
    case MessageType::UInt8:
        return f(RosType<UInt8Msg>{});
    case MessageType::JointJog:
        break;
    }
    std::abort(); // refused before: Ros1Node's prepare()
}

//! "geometry_msgs/TwistStamped": the type as ROS 1 names it (roscpp's own traits).
std::string rosTypeName1(MessageType type);

JointStateMsg toRos(const JointState &m);
TwistStampedMsg toRos(const TwistStamped &m);
TwistMsg toRos(const Twist &m);
PoseStampedMsg toRos(const PoseStamped &m);
WrenchStampedMsg toRos(const WrenchStamped &m);
WrenchMsg toRos(const Wrench &m);
BoolMsg toRos(const Bool &m);
ImuMsg toRos(const Imu &m);
StringMsg toRos(const String &m);
UInt8Msg toRos(const UInt8 &m);

//! ROS 1 header stamps are unsigned: a stamp beyond int32 seconds is clamped to its largest.
JointState fromRos(const JointStateMsg &m);
TwistStamped fromRos(const TwistStampedMsg &m);
Twist fromRos(const TwistMsg &m);
PoseStamped fromRos(const PoseStampedMsg &m);
WrenchStamped fromRos(const WrenchStampedMsg &m);
Imu fromRos(const ImuMsg &m);
Wrench fromRos(const WrenchMsg &m);
Bool fromRos(const BoolMsg &m);
String fromRos(const StringMsg &m);
UInt8 fromRos(const UInt8Msg &m);

} // namespace hatpic::ros::ros1
