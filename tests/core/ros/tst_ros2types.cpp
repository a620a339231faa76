// ROS 2's one table of our message types (ros/ros2/typetable.h): consistent, the type hashes
// computed from it equal to those ROS 2 publishes for the same types, the text REP 2011 hashes,
// the USER_DATA rmw_cyclonedds writes, and the idlc-generated types (from the same table) under
// the names rmw registers, without type information.
#include "ros/ros2/ros2convert.h"
#include "ros/ros2/typehash.h"
#include "ros/ros2/typetable.h"

#include <QTest>

#include <algorithm>

using namespace hatpic::ros;
using namespace hatpic::ros::ros2;

class TestRos2Types : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void tableIsConsistent() { QCOMPARE(checkTypeTable(), std::string()); }

    // The hashes ROS 2 (Iron and later) gives these types, as `ros2 topic info -v` shows them
    // and as other ROS 2 implementations list them.
    void hashesAreThePublishedOnes_data()
    {
        QTest::addColumn<QString>("type");
        QTest::addColumn<QString>("hash");
        const auto row = [](const char *type, const char *hex) {
            QTest::newRow(type) << QString::fromLatin1(type)
                                << QStringLiteral("RIHS01_") + QString::fromLatin1(hex);
        };
        row("builtin_interfaces/msg/Time",
            "b106235e25a4c5ed35098aa0a61a3ee9c9b18d197f398b0e4206cea9acf9c197");
        row("std_msgs/msg/Header",
            "f49fb3ae2cf070f793645ff749683ac6b06203e41c891e17701b1cb597ce6a01");
        row("geometry_msgs/msg/Vector3",
            "cc12fe83e4c02719f1ce8070bfd14aecd40f75a96696a67a2a1f37f7dbb0765d");
        row("geometry_msgs/msg/Point",
            "6963084842a9b04494d6b2941d11444708d892da2f4b09843b9c43f42a7f6881");
        row("geometry_msgs/msg/Quaternion",
            "8a765f66778c8ff7c8ab94afcc590a2ed5325a1d9a076ffff38fbce36f458684");
        row("geometry_msgs/msg/Pose",
            "d501954e9476cea2996984e812054b68026ae0bfae789d9a10b23daf35cc90fa");
        row("geometry_msgs/msg/PoseStamped",
            "10f3786d7d40fd2b54367835614bff85d4ad3b5dab62bf8bca0cc232d73b4cd8");
        row("geometry_msgs/msg/Twist",
            "9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a");
        row("geometry_msgs/msg/TwistStamped",
            "5f0fcd4f81d5d06ad9b4c4c63e3ea51b82d6ae4d0558f1d475229b1121db6f64");
        row("geometry_msgs/msg/Wrench",
            "018e8519d57c16adbe97c9fe1460ef21fec7e31bc541de3d653a35895677ce52");
        row("geometry_msgs/msg/WrenchStamped",
            "8dc3deaf06b2ab281f9f9a742a8961c328ca7cec16e3fd6586d3a5c83fa78f77");
        row("sensor_msgs/msg/JointState",
            "a13ee3a330e346c9d87b5aa18d24e11690752bd33a0350f11c5882bc9179260e");
        // As rosidl_generator_c writes them into the generated bool__description.c and
        // joint_jog__description.c (the latter with Time's and Header's hashes above).
        row("std_msgs/msg/Bool",
            "feb91e995ff9ebd09c0cb3d2aed18b11077585839fb5db80193b62d74528f6c9");
        row("control_msgs/msg/JointJog",
            "ba249455a20f70168a1acb7bf43b776b72ff1f7eb5fc4cfea443f749e963c6e7");
        // As rosidl_generator_c writes it into imu__description.c, beside Time's, Quaternion's,
        // Vector3's and Header's hashes above (a fixed-size array: float64[9]).
        row("sensor_msgs/msg/Imu",
            "7d9a00ff131080897a5ec7e26e315954b8eae3353c3f995c55faf71574000b5b");
        // As a ROS 2 node announces them (String's is the one rmw_zenoh's keys and rosbag2's
        // metadata show for /chatter; a micro-ROS struct.h lists other figures for both).
        row("std_msgs/msg/String",
            "df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18");
        row("std_msgs/msg/UInt8",
            "6138bd83d8c3569cb80a667db03cfc1629f529fee79d944c39c34e352e72f010");
    }
    void hashesAreThePublishedOnes()
    {
        QFETCH(QString, type);
        QFETCH(QString, hash);
        const TypeDef *def = findType(type.toStdString());
        QVERIFY(def);
        QCOMPARE(QString::fromStdString(typeHash(*def)), hash);
        QCOMPARE(QString::fromStdString(typeHashUserData(*def)), u"typehash=" + hash + u';');
    }

    // What is hashed, in the layout of rosidl_generator_type_description (Python's json.dumps
    // with ", " and ": ", keys in field order, no default values, referenced types by name).
    void hashedTextOfTwist()
    {
        const std::string vector3 = R"({"type_name": "geometry_msgs/msg/Vector3", "fields": [)"
                                    R"({"name": "x", "type": {"type_id": 11, "capacity": 0, )"
                                    R"("string_capacity": 0, "nested_type_name": ""}}, )"
                                    R"({"name": "y", "type": {"type_id": 11, "capacity": 0, )"
                                    R"("string_capacity": 0, "nested_type_name": ""}}, )"
                                    R"({"name": "z", "type": {"type_id": 11, "capacity": 0, )"
                                    R"("string_capacity": 0, "nested_type_name": ""}}]})";
        const std::string twist =
            R"({"type_description": {"type_name": "geometry_msgs/msg/Twist", "fields": [)"
            R"({"name": "linear", "type": {"type_id": 1, "capacity": 0, "string_capacity": 0, )"
            R"("nested_type_name": "geometry_msgs/msg/Vector3"}}, )"
            R"({"name": "angular", "type": {"type_id": 1, "capacity": 0, "string_capacity": 0, )"
            R"("nested_type_name": "geometry_msgs/msg/Vector3"}}]}, )"
            R"("referenced_type_descriptions": [)" +
            vector3 + "]}";
        QCOMPARE(hashedTypeDescription(*findType("geometry_msgs/msg/Twist")), twist);
    }

    // Referenced types once each, sorted by name, however deep.
    void referencedTypesOfPoseStamped()
    {
        const std::string text = hashedTypeDescription(*findType("geometry_msgs/msg/PoseStamped"));
        std::vector<std::size_t> at;
        for (const char *name :
             {"\"builtin_interfaces/msg/Time\", \"fields\"",
              "\"geometry_msgs/msg/Point\", \"fields\"", "\"geometry_msgs/msg/Pose\", \"fields\"",
              "\"geometry_msgs/msg/Quaternion\", \"fields\"",
              "\"std_msgs/msg/Header\", \"fields\""}) {
            at.push_back(text.find(name));
            QVERIFY2(at.back() != std::string::npos, name);
            QCOMPARE(text.find(name, at.back() + 1), std::string::npos);
        }
        QVERIFY(std::is_sorted(at.begin(), at.end()));
    }

    // type_description_interfaces/msg/FieldType's numbers.
    void fieldTypeIdsOfJointState()
    {
        const TypeDef *joint = findType("sensor_msgs/msg/JointState");
        QVERIFY(joint);
        std::vector<int> ids;
        for (const FieldDef &f : joint->fields)
            ids.push_back(f.typeId());
        // NESTED_TYPE, STRING_UNBOUNDED_SEQUENCE, then DOUBLE_UNBOUNDED_SEQUENCE three times.
        QCOMPARE(ids, (std::vector<int>{1, 161, 155, 155, 155}));
        QCOMPARE(findType("builtin_interfaces/msg/Time")->fields[1].typeId(), 7); // UINT32
        QCOMPARE(findType("std_msgs/msg/Header")->fields[1].typeId(), 17);        // STRING
    }

    void ddsNames()
    {
        QCOMPARE(ddsTypeName("geometry_msgs/msg/TwistStamped"),
                 std::string("geometry_msgs::msg::dds_::TwistStamped_"));
        QCOMPARE(ddsTopicName("/hatpic/twist"), std::string("rt/hatpic/twist"));
        QCOMPARE(ddsTopicName("wrench_estimation"), std::string("rt/wrench_estimation"));
    }

    // The types on the wire come from the table: each message type has its entry, and idlc's
    // descriptor (from the generated IDL) carries rmw's DDS name and no XTypes information.
    void everyMessageTypeOnTheWire()
    {
        for (int i = 0; i < kMessageTypeCount; ++i) {
            const auto type = MessageType(i);
            QVERIFY2(findType(rosTypeName(type)), rosTypeName(type));
            const dds_topic_descriptor_t *desc = descriptorOf(type);
            QVERIFY(desc);
            QCOMPARE(std::string(desc->m_typename), ddsTypeName(rosTypeName(type)));
            QCOMPARE(desc->m_flagset & DDS_TOPIC_XTYPES_METADATA, 0u);
            QCOMPARE(desc->m_nkeys, 0u);
        }
    }
};

QTEST_GUILESS_MAIN(TestRos2Types)
#include "tst_ros2types.moc"
