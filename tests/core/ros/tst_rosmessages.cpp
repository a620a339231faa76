// The plain ROS messages (ros/messages.h): time stamps, type names, the variant's order, and
// the node factory's answer for a ROS this build does not have.
#include "ros/messages.h"
#include "ros/node.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace hatpic::ros;

class TestRosMessages : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void timeFromSecondsKeepsNanosecBelowASecond_data()
    {
        QTest::addColumn<double>("seconds");
        QTest::addColumn<int>("sec");
        QTest::addColumn<uint>("nanosec");
        QTest::newRow("zero") << 0.0 << 0 << 0u;
        QTest::newRow("quarter") << 1700000000.25 << 1700000000 << 250000000u;
        QTest::newRow("rounds up to the next second") << 1.9999999999 << 2 << 0u;
        QTest::newRow("negative") << -1.0 << 0 << 0u;
        QTest::newRow("NaN") << std::numeric_limits<double>::quiet_NaN() << 0 << 0u;
        QTest::newRow("infinite") << std::numeric_limits<double>::infinity() << 0 << 0u;
        QTest::newRow("beyond int32") << 1e12 << std::numeric_limits<std::int32_t>::max() << 0u;
    }
    void timeFromSecondsKeepsNanosecBelowASecond()
    {
        QFETCH(double, seconds);
        QFETCH(int, sec);
        QFETCH(uint, nanosec);
        QCOMPARE(timeFromSeconds(seconds), (Time{sec, nanosec}));
    }

    void secondsOfATime()
    {
        QCOMPARE(seconds(Time{3, 500000000}), 3.5);
        QCOMPARE(seconds(timeFromSeconds(1234.5)), 1234.5);
    }

    void typeOfFollowsTheVariant_data()
    {
        QTest::addColumn<int>("index");
        QTest::addColumn<QString>("rosName");
        QTest::newRow("JointState") << 0 << QStringLiteral("sensor_msgs/msg/JointState");
        QTest::newRow("TwistStamped") << 1 << QStringLiteral("geometry_msgs/msg/TwistStamped");
        QTest::newRow("Twist") << 2 << QStringLiteral("geometry_msgs/msg/Twist");
        QTest::newRow("PoseStamped") << 3 << QStringLiteral("geometry_msgs/msg/PoseStamped");
        QTest::newRow("WrenchStamped") << 4 << QStringLiteral("geometry_msgs/msg/WrenchStamped");
        QTest::newRow("Wrench") << 5 << QStringLiteral("geometry_msgs/msg/Wrench");
        QTest::newRow("Bool") << 6 << QStringLiteral("std_msgs/msg/Bool");
        QTest::newRow("JointJog") << 7 << QStringLiteral("control_msgs/msg/JointJog");
        QTest::newRow("Imu") << 8 << QStringLiteral("sensor_msgs/msg/Imu");
        QTest::newRow("String") << 9 << QStringLiteral("std_msgs/msg/String");
        QTest::newRow("UInt8") << 10 << QStringLiteral("std_msgs/msg/UInt8");
    }
    void typeOfFollowsTheVariant()
    {
        QFETCH(int, index);
        QFETCH(QString, rosName);
        const Message messages[] = {JointState{},    TwistStamped{}, Twist{}, PoseStamped{},
                                    WrenchStamped{}, Wrench{},       Bool{},  JointJog{},
                                    Imu{},           String{},       UInt8{}};
        static_assert(std::size(messages) == kMessageTypeCount);
        QCOMPARE(int(typeOf(messages[index])), index);
        QCOMPARE(QString::fromLatin1(rosTypeName(MessageType(index))), rosName);
    }

    void qosProfiles()
    {
        QCOMPARE(Qos::defaults(), (Qos{Qos::Reliability::Reliable, Qos::Durability::Volatile, 10}));
        QCOMPARE(Qos::matchAny(),
                 (Qos{Qos::Reliability::BestEffort, Qos::Durability::Volatile, 1}));
    }

    void aRosThatIsNotBuiltIsOneSentence()
    {
        for (const RosVersion version : {RosVersion::Ros1, RosVersion::Ros2}) {
            if (Node::isAvailable(version))
                continue;
            NodeOptions options;
            options.version = version;
            options.name = "test";
            std::string error;
            QVERIFY(!Node::open(options, &error));
            QCOMPARE(error, std::string(rosVersionName(version)) +
                                " is not built into this program (docs/ros.md says what it "
                                "needs).");
        }
    }
};

QTEST_GUILESS_MAIN(TestRosMessages)
#include "tst_rosmessages.moc"
