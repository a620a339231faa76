// ROS 2 over Cyclone DDS, on the wire as rmw_cyclonedds puts it (ros.md § ROS 2): one
// participant per node (USER_DATA "enclave=/;") in a domain configured as rmw configures it
// from ROS's discovery variables (discovery.h); topics rt/<name> of the types of typetable.h,
// XCDR1, without type information; QoS mapped as rmw's create_readwrite_qos; every reader and
// writer announcing "typehash=RIHS01_…;" (typehash.h).
#pragma once

#include "ros/node.h"

#include <cstdint>
#include <memory>
#include <string>

namespace hatpic::ros::ros2 {

//! The largest sample a node takes or sends, serialised (CDR) [bytes]: Cyclone DDS's
//! Domain/Internal/MaxSampleSize in the configuration every domain of ours is created with, so
//! a larger one is dropped as it arrives — at its first fragment, before any is reassembled —
//! and Cyclone says so on stderr (ros.md § Discovery: how much one sample may cost). The
//! largest legitimate one is a WrenchStamped or TwistStamped with its frame_id (≈ 70 bytes and
//! the name; the bridge's own frame ids and joint names are at most 256 characters). The same
//! limit applies to discovery's samples (a participant's or an endpoint's announcement, under
//! 1 KiB from any ROS 2 node), which is why it is not smaller. A CYCLONEDDS_URI may raise it.
constexpr std::uint32_t kMaxSampleBytes = 16 * 1024;

//! A ROS 2 node (options.version is not looked at). Null with `*error` one sentence when a
//! discovery variable or ROS_DOMAIN_ID is invalid, or Cyclone DDS refuses the domain or the
//! participant.
std::unique_ptr<Node> openNode(const NodeOptions &options, std::string *error);

} // namespace hatpic::ros::ros2
