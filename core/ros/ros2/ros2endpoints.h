// A ROS 2 node's readers and writers on Cyclone DDS: the QoS of rmw_cyclonedds'
// create_readwrite_qos, the type hash in USER_DATA, and the copy between our messages and the
// generated C types (ros2convert.h).
#pragma once

#include "ros/node.h"

#include <dds/dds.h>

#include <memory>
#include <string>

namespace hatpic::ros::ros2 {

//! The DDS QoS of an endpoint with `qos` and USER_DATA `userData`, as rmw_cyclonedds makes it:
//! keep last `depth`; reliable or best effort; volatile, or transient local with a durability
//! service of the same history; automatic liveliness of infinite lease; no autodispose; and,
//! as rmw's types only allow it, XCDR1. One difference: a reliable writer's max_blocking_time
//! is 0, not infinite, so that publish() never waits (it is not matched against readers).
//! The caller deletes it.
dds_qos_t *endpointQos(const Qos &qos, const std::string &userData);

//! A writer of `type` on the ROS topic `topic` in `participant`; null with `*error`.
std::unique_ptr<Publisher> makePublisher(dds_entity_t participant, const std::string &topic,
                                         MessageType type, const Qos &qos, std::string *error);
//! A reader of `type` on `topic` whose listener hands every valid sample to `handler`; null
//! with `*error`.
std::unique_ptr<Subscription> makeSubscription(dds_entity_t participant, const std::string &topic,
                                               MessageType type, const Qos &qos,
                                               MessageHandler handler, std::string *error);

} // namespace hatpic::ros::ros2
