#include "ros/node.h"

// Each ROS's implementation, when built. ROS 1: core/ros/ros1 (HATPIC_BUILD_ROS1).
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
        return false; // core/ros/ros2 follows
    }
    return false;
}

std::unique_ptr<Node> Node::open(const NodeOptions &options, std::string *error)
{
    // ROS 1 ------------------------------------------------------------------------------
#ifdef HATPIC_HAVE_ROS1
    if (options.version == RosVersion::Ros1)
        return ros1::openNode(options, error);
#endif
    // -------------------------------------------------------------------------------------
    if (error) {
        *error = std::string(rosVersionName(options.version)) +
                 (options.version == RosVersion::Ros1
                      ? " is not built into this program (it needs Debian's libroscpp-dev; "
                        "see docs/ros.md)."
                      : " is not built into this program.");
    }
    return nullptr;
}

} // namespace hatpic::ros
