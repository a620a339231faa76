// ROS 2 over Cyclone DDS, on the wire as rmw_cyclonedds puts it (ros.md § ROS 2): one
// participant per node (USER_DATA "enclave=/;") in a domain configured as rmw configures it
// from ROS's discovery variables (discovery.h); topics rt/<name> of the types of typetable.h,
// XCDR1, without type information; QoS mapped as rmw's create_readwrite_qos; every reader and
// writer announcing "typehash=RIHS01_…;" (typehash.h).
#pragma once

#include "ros/node.h"

#include <memory>
#include <string>

namespace hatpic::ros::ros2 {

//! A ROS 2 node (options.version is not looked at). Null with `*error` one sentence when a
//! discovery variable or ROS_DOMAIN_ID is invalid, or Cyclone DDS refuses the domain or the
//! participant.
std::unique_ptr<Node> openNode(const NodeOptions &options, std::string *error);

} // namespace hatpic::ros::ros2
