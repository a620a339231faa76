#include "ros/messages.h"

#include <cmath>
#include <limits>

namespace hatpic::ros {

Time timeFromSeconds(double seconds)
{
    if (!std::isfinite(seconds) || seconds < 0)
        return {};
    constexpr double kMaxSec = std::numeric_limits<std::int32_t>::max();
    if (seconds >= kMaxSec)
        return {std::numeric_limits<std::int32_t>::max(), 0};
    const double whole = std::floor(seconds);
    auto nanos = static_cast<std::int64_t>(std::llround((seconds - whole) * 1e9));
    auto sec = static_cast<std::int64_t>(whole);
    if (nanos >= 1000000000) {
        nanos -= 1000000000;
        ++sec;
    }
    return {static_cast<std::int32_t>(sec), static_cast<std::uint32_t>(nanos)};
}

double seconds(const Time &time)
{
    return double(time.sec) + double(time.nanosec) * 1e-9;
}

const char *rosTypeName(MessageType type)
{
    switch (type) {
    case MessageType::JointState:
        return "sensor_msgs/msg/JointState";
    case MessageType::TwistStamped:
        return "geometry_msgs/msg/TwistStamped";
    case MessageType::Twist:
        return "geometry_msgs/msg/Twist";
    case MessageType::PoseStamped:
        return "geometry_msgs/msg/PoseStamped";
    case MessageType::WrenchStamped:
        return "geometry_msgs/msg/WrenchStamped";
    case MessageType::Wrench:
        return "geometry_msgs/msg/Wrench";
    case MessageType::Bool:
        return "std_msgs/msg/Bool";
    case MessageType::JointJog:
        return "control_msgs/msg/JointJog";
    case MessageType::Imu:
        return "sensor_msgs/msg/Imu";
    case MessageType::String:
        return "std_msgs/msg/String";
    case MessageType::UInt8:
        return "std_msgs/msg/UInt8";
    }
    return "";
}

} // namespace hatpic::ros
