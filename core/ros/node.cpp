#include "ros/node.h"

// Each ROS that this build has gives one function, `openNode(options, error)`, in its own
// subfolder: ros2/ (Cyclone DDS, HATPIC_HAVE_ROS2) and ros1/ (roscpp, HATPIC_HAVE_ROS1).
#ifdef HATPIC_HAVE_ROS2
#include "ros/ros2/ros2node.h"
#endif
#ifdef HATPIC_HAVE_ROS1
#include "ros/ros1/ros1node.h"
#endif

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <limits>

namespace hatpic::ros {

const char *rosVersionName(RosVersion version)
{
    return version == RosVersion::Ros1 ? "ROS 1" : "ROS 2";
}

std::optional<int> domainFromEnvironment(int maxId, std::string *error)
{
    const char *text = std::getenv("ROS_DOMAIN_ID");
    if (!text || !*text)
        return 0;
    char *end = nullptr;
    errno = 0;
    const long id = std::strtol(text, &end, 10);
    while (*end == ' ' || *end == '\t' || *end == '\n')
        ++end;
    if (end == text || *end != '\0' || errno != 0 || id < 0 || id > maxId) {
        if (error)
            *error = "ROS_DOMAIN_ID must be a whole number from 0 to " + std::to_string(maxId) +
                     ", got '" + std::string(text).substr(0, 40) + "'.";
        return std::nullopt;
    }
    return int(id);
}

std::string effectiveNamespace(RosVersion version, const std::string &given)
{
    if (!given.empty() || version != RosVersion::Ros1)
        return given;
    const char *text = std::getenv("ROS_NAMESPACE");
    return text ? std::string(text) : std::string();
}

namespace {
std::atomic<bool> g_exitWhenShutDown{false};
} // namespace

void setExitWhenShutDownByMaster(bool exit)
{
    g_exitWhenShutDown = exit;
}

bool exitsWhenShutDownByMaster()
{
    return g_exitWhenShutDown;
}

bool Node::isAvailable(RosVersion version)
{
    switch (version) {
    case RosVersion::Ros1:
#ifdef HATPIC_HAVE_ROS1
        return true;
#else
        return false;
#endif
    case RosVersion::Ros2:
#ifdef HATPIC_HAVE_ROS2
        return true;
#else
        return false;
#endif
    }
    return false;
}

std::unique_ptr<Node> Node::open(const NodeOptions &options, std::string *error)
{
    switch (options.version) {
    case RosVersion::Ros1:
#ifdef HATPIC_HAVE_ROS1
        return ros1::openNode(options, error);
#else
        break;
#endif
    case RosVersion::Ros2:
#ifdef HATPIC_HAVE_ROS2
        return ros2::openNode(options, error);
#else
        break;
#endif
    }
    if (error)
        *error = std::string(rosVersionName(options.version)) +
                 " is not built into this program (docs/ros.md says what it needs).";
    return nullptr;
}

} // namespace hatpic::ros
