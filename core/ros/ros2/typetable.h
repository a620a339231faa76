// The ROS 2 message types HATPIC speaks, each described once (ros.md § Type hashes): its ROS
// name and its fields in the order of the .msg files of builtin_interfaces, std_msgs,
// geometry_msgs, sensor_msgs and control_msgs, with the field types of type_description_interfaces'
// FieldType. From this one table come the IDL that idlc compiles into the DDS types (the
// build-time generator idlgen.cpp) and the REP 2011 type hash that every reader and writer
// announces (typehash.h). Plain C++, no Qt, no DDS.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace hatpic::ros::ros2 {

//! A field's value type, numbered as type_description_interfaces/msg/FieldType.
enum class FieldKind : int {
    Nested = 1,  //!< FIELD_TYPE_NESTED_TYPE: another message
    Uint8 = 3,   //!< FIELD_TYPE_UINT8
    Int32 = 6,   //!< FIELD_TYPE_INT32
    Uint32 = 7,  //!< FIELD_TYPE_UINT32
    Double = 11, //!< FIELD_TYPE_DOUBLE (float64)
    Bool = 15,   //!< FIELD_TYPE_BOOLEAN
    String = 17, //!< FIELD_TYPE_STRING (unbounded)
};
//! FieldType numbers an unbounded sequence of a value type this much above the value type
//! (FIELD_TYPE_DOUBLE_UNBOUNDED_SEQUENCE = 155 = 11 + 144).
constexpr int kUnboundedSequenceOffset = 144;
//! … and an array of fixed size this much (FIELD_TYPE_DOUBLE_ARRAY = 59 = 11 + 48).
constexpr int kArrayOffset = 48;

struct FieldDef
{
    const char *name;
    FieldKind kind;
    bool sequence = false;       //!< an unbounded sequence (`float64[]`, `string[]`)
    const char *nestedType = ""; //!< kind Nested: the type's ROS name
    int capacity = 0;            //!< a fixed-size array's size (`float64[9]`), else 0

    //! The FieldType id of the field: its kind, the array of it or the unbounded sequence.
    constexpr int typeId() const
    {
        return int(kind) + (sequence ? kUnboundedSequenceOffset : capacity > 0 ? kArrayOffset : 0);
    }
};

struct TypeDef
{
    const char *name; //!< "geometry_msgs/msg/Vector3"
    std::span<const FieldDef> fields;
};

//! Every type, each after the types its fields use.
std::span<const TypeDef> typeTable();
//! The type of that ROS name; null when the table has none.
const TypeDef *findType(std::string_view rosName);

//! What is wrong with the table, one sentence, or empty: a name that is not
//! "package/msg/Name" of [A-Za-z0-9_], a type listed twice, a field whose nested type is not
//! listed before it, a nested type on a field that is not of kind Nested.
std::string checkTypeTable();

//! The DDS type rmw_cyclonedds registers for a ROS type: "geometry_msgs/msg/Twist" →
//! "geometry_msgs::msg::dds_::Twist_".
std::string ddsTypeName(std::string_view rosName);
//! The DDS topic rmw names after a ROS topic: "rt" + the absolute name ("/a/b" and "a/b" both
//! give "rt/a/b": a relative name resolves in the root namespace, where our nodes live).
std::string ddsTopicName(std::string_view rosTopic);

} // namespace hatpic::ros::ros2
