#include "ros/ros1/ros1messages.h"

#include <ros/message_traits.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace hatpic::ros::ros1 {

namespace {

::ros::Time toRos(const Time &t)
{
    // messages.h's Time is never negative when made by timeFromSeconds(); a negative one is 0.
    return t.sec < 0 ? ::ros::Time() : ::ros::Time(std::uint32_t(t.sec), t.nanosec);
}

Time fromRos(const ::ros::Time &t)
{
    constexpr std::uint32_t kMaxSec = std::numeric_limits<std::int32_t>::max();
    return t.sec > kMaxSec ? Time{std::int32_t(kMaxSec), 0} : Time{std::int32_t(t.sec), t.nsec};
}

// A string or vector of one allocator as the same of another.
template<typename To, typename From> To copied(const From &from)
{
    return To(from.begin(), from.end());
}

template<typename From> std::vector<std::string> copiedStrings(const From &from)
{
    std::vector<std::string> to;
    to.reserve(from.size());
    for (const auto &s : from)
        to.emplace_back(s.begin(), s.end());
    return to;
}

HeaderMsg toRos(const Header &h)
{
    HeaderMsg r;
    r.stamp = toRos(h.stamp);
    r.frame_id = copied<decltype(r.frame_id)>(h.frameId);
    return r;
}

Header fromRos(const HeaderMsg &h)
{
    return {fromRos(h.stamp), copied<std::string>(h.frame_id)};
}

Vector3Msg toRos(const Vector3 &v)
{
    Vector3Msg r;
    r.x = v.x;
    r.y = v.y;
    r.z = v.z;
    return r;
}

Vector3 fromRos(const Vector3Msg &v)
{
    return {v.x, v.y, v.z};
}

} // namespace

std::string rosTypeName1(MessageType type)
{
    if (!hasRos1Type(type))
        return "control_msgs/JointJog";
    return visitType(type, [](auto tag) {
        return std::string(::ros::message_traits::datatype<typename decltype(tag)::Type>());
    });
}

JointStateMsg toRos(const JointState &m)
{
    JointStateMsg r;
    r.header = toRos(m.header);
    for (const std::string &name : m.name)
        r.name.push_back(copied<decltype(r.name)::value_type>(name));
    r.position = copied<decltype(r.position)>(m.position);
    r.velocity = copied<decltype(r.velocity)>(m.velocity);
    r.effort = copied<decltype(r.effort)>(m.effort);
    return r;
}

TwistMsg toRos(const Twist &m)
{
    TwistMsg r;
    r.linear = toRos(m.linear);
    r.angular = toRos(m.angular);
    return r;
}

TwistStampedMsg toRos(const TwistStamped &m)
{
    TwistStampedMsg r;
    r.header = toRos(m.header);
    r.twist = toRos(m.twist);
    return r;
}

PoseStampedMsg toRos(const PoseStamped &m)
{
    PoseStampedMsg r;
    r.header = toRos(m.header);
    r.pose.position.x = m.pose.position.x;
    r.pose.position.y = m.pose.position.y;
    r.pose.position.z = m.pose.position.z;
    r.pose.orientation.x = m.pose.orientation.x;
    r.pose.orientation.y = m.pose.orientation.y;
    r.pose.orientation.z = m.pose.orientation.z;
    r.pose.orientation.w = m.pose.orientation.w;
    return r;
}

WrenchMsg toRos(const Wrench &m)
{
    WrenchMsg r;
    r.force = toRos(m.force);
    r.torque = toRos(m.torque);
    return r;
}

WrenchStampedMsg toRos(const WrenchStamped &m)
{
    WrenchStampedMsg r;
    r.header = toRos(m.header);
    r.wrench = toRos(m.wrench);
    return r;
}

JointState fromRos(const JointStateMsg &m)
{
    using Values = std::vector<double>;
    return {fromRos(m.header), copiedStrings(m.name), copied<Values>(m.position),
            copied<Values>(m.velocity), copied<Values>(m.effort)};
}

Twist fromRos(const TwistMsg &m)
{
    return {fromRos(m.linear), fromRos(m.angular)};
}

TwistStamped fromRos(const TwistStampedMsg &m)
{
    return {fromRos(m.header), fromRos(m.twist)};
}

PoseStamped fromRos(const PoseStampedMsg &m)
{
    const auto &p = m.pose.position;
    const auto &q = m.pose.orientation;
    return {fromRos(m.header), Pose{{p.x, p.y, p.z}, {q.x, q.y, q.z, q.w}}};
}

Wrench fromRos(const WrenchMsg &m)
{
    return {fromRos(m.force), fromRos(m.torque)};
}

WrenchStamped fromRos(const WrenchStampedMsg &m)
{
    return {fromRos(m.header), fromRos(m.wrench)};
}

BoolMsg toRos(const Bool &m)
{
    BoolMsg r;
    r.data = m.data;
    return r;
}

Bool fromRos(const BoolMsg &m)
{
    return {m.data != 0};
}

StringMsg toRos(const String &m)
{
    StringMsg r;
    r.data.assign(m.data.begin(), m.data.end());
    return r;
}

String fromRos(const StringMsg &m)
{
    return {std::string(m.data.begin(), m.data.end())};
}

UInt8Msg toRos(const UInt8 &m)
{
    UInt8Msg r;
    r.data = m.data;
    return r;
}

UInt8 fromRos(const UInt8Msg &m)
{
    return {m.data};
}

ImuMsg toRos(const Imu &m)
{
    ImuMsg r;
    r.header = toRos(m.header);
    r.orientation.x = m.orientation.x;
    r.orientation.y = m.orientation.y;
    r.orientation.z = m.orientation.z;
    r.orientation.w = m.orientation.w;
    r.angular_velocity = toRos(m.angularVelocity);
    r.linear_acceleration = toRos(m.linearAcceleration);
    std::copy(m.orientationCovariance.begin(), m.orientationCovariance.end(),
              r.orientation_covariance.begin());
    std::copy(m.angularVelocityCovariance.begin(), m.angularVelocityCovariance.end(),
              r.angular_velocity_covariance.begin());
    std::copy(m.linearAccelerationCovariance.begin(), m.linearAccelerationCovariance.end(),
              r.linear_acceleration_covariance.begin());
    return r;
}

Imu fromRos(const ImuMsg &m)
{
    const auto &q = m.orientation;
    Imu r{fromRos(m.header),
          {q.x, q.y, q.z, q.w},
          {},
          fromRos(m.angular_velocity),
          {},
          fromRos(m.linear_acceleration),
          {}};
    std::copy(m.orientation_covariance.begin(), m.orientation_covariance.end(),
              r.orientationCovariance.begin());
    std::copy(m.angular_velocity_covariance.begin(), m.angular_velocity_covariance.end(),
              r.angularVelocityCovariance.begin());
    std::copy(m.linear_acceleration_covariance.begin(), m.linear_acceleration_covariance.end(),
              r.linearAccelerationCovariance.begin());
    return r;
}

} // namespace hatpic::ros::ros1
