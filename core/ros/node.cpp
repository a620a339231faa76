#include "ros/node.h"

// Each ROS that this build has gives one function, `openNode(options, error)`, in its own
// subfolder: ros2/ (Cyclone DDS, HATPIC_HAVE_ROS2) and ros1/ (roscpp, HATPIC_HAVE_ROS1).
#ifdef HATPIC_HAVE_ROS2
#include "ros/ros2/ros2node.h"
#endif
#ifdef HATPIC_HAVE_ROS1
#include "ros/ros1/ros1node.h"
#endif

namespace hatpic::ros {

const char *rosVersionName(RosVersion version)
{
    return version == RosVersion::Ros1 ? "ROS 1" : "ROS 2";
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
