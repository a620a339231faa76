// Our plain messages (ros/messages.h) ⇄ the C types idlc generates from the type table: the
// only code that knows the generated layouts. Values are copied, never reinterpreted.
#pragma once

#include "ros/messages.h"

#include <dds/dds.h>

namespace hatpic::ros::ros2 {

//! The descriptor idlc generated for `type` (its DDS type name, layout and XCDR1 ops).
const dds_topic_descriptor_t *descriptorOf(MessageType type);

//! dds_write() of `message` on `writer`; the C sample points into `message` for the call only.
dds_return_t writeMessage(dds_entity_t writer, const Message &message);

//! The message of `type` that the C sample `sample` (from dds_take on a reader of that type)
//! holds.
Message messageOf(MessageType type, const void *sample);

} // namespace hatpic::ros::ros2
