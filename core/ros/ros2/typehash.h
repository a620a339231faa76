// The ROS 2 type hash (REP 2011, RIHS version 01), computed from the one table of our types
// (typetable.h) the way rosidl_generator_type_description computes it, and the USER_DATA
// rmw_cyclonedds (Iron and later) puts it in on every reader and writer.
#pragma once

#include "ros/ros2/typetable.h"

#include <string>

namespace hatpic::ros::ros2 {

//! The text REP 2011 hashes: the TypeDescription of `type` (type_description, then
//! referenced_type_descriptions: every type it uses, however deep, sorted by name) with the
//! default values left out, as Python's json.dumps writes it with separators ", " and ": " and
//! the keys in the message's field order.
std::string hashedTypeDescription(const TypeDef &type);
//! "RIHS01_" + the SHA-256 of hashedTypeDescription() in lowercase hex.
std::string typeHash(const TypeDef &type);
//! The endpoint USER_DATA of rmw_dds_common::encode_type_hash_for_user_data_qos:
//! "typehash=RIHS01_…;" (no terminating NUL).
std::string typeHashUserData(const TypeDef &type);

} // namespace hatpic::ros::ros2
