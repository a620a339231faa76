#include "ros/ros2/typetable.h"

#include <algorithm>
#include <array>

namespace hatpic::ros::ros2 {

namespace {

using K = FieldKind;

// The fields of each type, as its .msg file lists them (ROS 2 Jazzy's common_interfaces and
// control_msgs).
constexpr FieldDef kTime[] = {{"sec", K::Int32}, {"nanosec", K::Uint32}};
constexpr FieldDef kHeader[] = {{"stamp", K::Nested, false, "builtin_interfaces/msg/Time"},
                                {"frame_id", K::String}};
constexpr FieldDef kVector3[] = {{"x", K::Double}, {"y", K::Double}, {"z", K::Double}};
constexpr FieldDef kPoint[] = {{"x", K::Double}, {"y", K::Double}, {"z", K::Double}};
constexpr FieldDef kQuaternion[] = {
    {"x", K::Double}, {"y", K::Double}, {"z", K::Double}, {"w", K::Double}};
constexpr FieldDef kPose[] = {{"position", K::Nested, false, "geometry_msgs/msg/Point"},
                              {"orientation", K::Nested, false, "geometry_msgs/msg/Quaternion"}};
constexpr FieldDef kPoseStamped[] = {{"header", K::Nested, false, "std_msgs/msg/Header"},
                                     {"pose", K::Nested, false, "geometry_msgs/msg/Pose"}};
constexpr FieldDef kTwist[] = {{"linear", K::Nested, false, "geometry_msgs/msg/Vector3"},
                               {"angular", K::Nested, false, "geometry_msgs/msg/Vector3"}};
constexpr FieldDef kTwistStamped[] = {{"header", K::Nested, false, "std_msgs/msg/Header"},
                                      {"twist", K::Nested, false, "geometry_msgs/msg/Twist"}};
constexpr FieldDef kWrench[] = {{"force", K::Nested, false, "geometry_msgs/msg/Vector3"},
                                {"torque", K::Nested, false, "geometry_msgs/msg/Vector3"}};
constexpr FieldDef kWrenchStamped[] = {{"header", K::Nested, false, "std_msgs/msg/Header"},
                                       {"wrench", K::Nested, false, "geometry_msgs/msg/Wrench"}};
constexpr FieldDef kJointState[] = {{"header", K::Nested, false, "std_msgs/msg/Header"},
                                    {"name", K::String, true},
                                    {"position", K::Double, true},
                                    {"velocity", K::Double, true},
                                    {"effort", K::Double, true}};
constexpr FieldDef kBool[] = {{"data", K::Bool}};
constexpr FieldDef kString[] = {{"data", K::String}};
constexpr FieldDef kUInt8[] = {{"data", K::Uint8}};
constexpr FieldDef kJointJog[] = {{"header", K::Nested, false, "std_msgs/msg/Header"},
                                  {"joint_names", K::String, true},
                                  {"displacements", K::Double, true},
                                  {"velocities", K::Double, true},
                                  {"duration", K::Double}};
constexpr FieldDef kImu[] = {{"header", K::Nested, false, "std_msgs/msg/Header"},
                             {"orientation", K::Nested, false, "geometry_msgs/msg/Quaternion"},
                             {"orientation_covariance", K::Double, false, "", 9},
                             {"angular_velocity", K::Nested, false, "geometry_msgs/msg/Vector3"},
                             {"angular_velocity_covariance", K::Double, false, "", 9},
                             {"linear_acceleration", K::Nested, false, "geometry_msgs/msg/Vector3"},
                             {"linear_acceleration_covariance", K::Double, false, "", 9}};

constexpr TypeDef kTypes[] = {
    {"builtin_interfaces/msg/Time", kTime},
    {"std_msgs/msg/Header", kHeader},
    {"geometry_msgs/msg/Vector3", kVector3},
    {"geometry_msgs/msg/Point", kPoint},
    {"geometry_msgs/msg/Quaternion", kQuaternion},
    {"geometry_msgs/msg/Pose", kPose},
    {"geometry_msgs/msg/PoseStamped", kPoseStamped},
    {"geometry_msgs/msg/Twist", kTwist},
    {"geometry_msgs/msg/TwistStamped", kTwistStamped},
    {"geometry_msgs/msg/Wrench", kWrench},
    {"geometry_msgs/msg/WrenchStamped", kWrenchStamped},
    {"sensor_msgs/msg/JointState", kJointState},
    {"std_msgs/msg/Bool", kBool},
    {"control_msgs/msg/JointJog", kJointJog},
    {"sensor_msgs/msg/Imu", kImu},
    {"std_msgs/msg/String", kString},
    {"std_msgs/msg/UInt8", kUInt8},
};

bool isIdentifier(std::string_view s)
{
    return !s.empty() && !(s[0] >= '0' && s[0] <= '9') &&
           std::all_of(s.begin(), s.end(), [](char c) {
               return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '_';
           });
}

// "package/msg/Name" split in its three parts; empty parts when it is not of that form.
std::array<std::string_view, 3> parts(std::string_view rosName)
{
    const auto first = rosName.find('/');
    const auto second = first == std::string_view::npos ? first : rosName.find('/', first + 1);
    if (second == std::string_view::npos)
        return {};
    return {rosName.substr(0, first), rosName.substr(first + 1, second - first - 1),
            rosName.substr(second + 1)};
}

} // namespace

std::span<const TypeDef> typeTable()
{
    return kTypes;
}

const TypeDef *findType(std::string_view rosName)
{
    for (const TypeDef &type : kTypes) {
        if (rosName == type.name)
            return &type;
    }
    return nullptr;
}

std::string checkTypeTable()
{
    for (std::size_t i = 0; i < std::size(kTypes); ++i) {
        const TypeDef &type = kTypes[i];
        const std::string name = type.name;
        const auto [package, msg, message] = parts(name);
        if (!isIdentifier(package) || msg != "msg" || !isIdentifier(message))
            return "type '" + name + "': not a ROS message name package/msg/Name";
        const auto earlier = std::span(kTypes, i);
        const auto listed = [&](std::string_view n) {
            return std::any_of(earlier.begin(), earlier.end(),
                               [&](const TypeDef &t) { return n == t.name; });
        };
        if (listed(name))
            return "type '" + name + "': listed twice";
        if (type.fields.empty())
            return "type '" + name + "': has no fields";
        for (const FieldDef &field : type.fields) {
            const std::string where = "type '" + name + "', field '" + field.name + "'";
            if (!isIdentifier(field.name))
                return where + ": not an identifier";
            const std::string_view nested = field.nestedType;
            if ((field.kind == FieldKind::Nested) == nested.empty())
                return where + ": a nested type goes with kind Nested, and only with it";
            if (field.capacity < 0 || (field.capacity > 0 && field.sequence))
                return where + ": an array has a size above 0 and is not a sequence";
            if (field.kind == FieldKind::Nested && !listed(nested))
                return where + ": its type '" + std::string(nested) + "' is not listed before it";
        }
    }
    return {};
}

std::string ddsTypeName(std::string_view rosName)
{
    const auto [package, msg, message] = parts(rosName);
    return std::string(package) + "::" + std::string(msg) + "::dds_::" + std::string(message) + "_";
}

std::string ddsTopicName(std::string_view rosTopic)
{
    return std::string(rosTopic.starts_with('/') ? "rt" : "rt/") + std::string(rosTopic);
}

} // namespace hatpic::ros::ros2
