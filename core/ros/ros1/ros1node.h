// ROS 1's Node (node.h) over Debian's roscpp: Node::open's ROS 1 branch. No roscpp here, so
// the factory includes it freely.
//
// What a ROS 1 user can count on (docs/ros.md § ROS 1):
// - the node is /<options.name>, in ROS_NAMESPACE when set; ROS_MASTER_URI, ROS_IP and
//   ROS_HOSTNAME apply as for every roscpp node; relative topics resolve in the namespace;
// - open() never waits for the master: without one it says so once (rosconsole, stderr) and
//   tries every second; publishers and subscriptions exist from the start and reach the graph
//   once the master answers; until then publish() refuses (counted);
// - a master that restarts is noticed within about a second and everything is registered
//   with it again (roscpp alone would not);
// - TCP_NODELAY on every topic connection: subscriptions ask their publishers for it, and the
//   connections of our publishers get it from the listening socket;
// - QoS: ROS 1 has none (TCPROS is reliable and volatile); depth is the queue size;
// - one node per process: every open() in a process shares one roscpp node, so all must ask
//   for the same name; closing the last Node keeps that node (without topics) until the
//   process ends, because roscpp cannot start again once shut down.
#pragma once

#include "ros/node.h"

#include <memory>
#include <string>

namespace hatpic::ros::ros1 {

//! A Node on the process's ROS 1 node; null with `*error` (one sentence) when roscpp refuses
//! the name or the environment, or when the process's node has another name or was shut down.
std::unique_ptr<Node> openNode(const NodeOptions &options, std::string *error);

} // namespace hatpic::ros::ros1
