// ROS 1's Node against real middleware: a roscore of its own on loopback and a rospy node that
// is not ours. The process's ROS 1 node is opened before the master runs (it must say so and
// keep trying), then carries every message type both ways with exact values, asks for and
// gets TCP_NODELAY, survives a master restart, and is shared by a second open() in the
// process. The order of the functions is the order of that story.
#include "roscore.h"

#include "ros/node.h"

#include <ros/connection_manager.h>
#include <ros/console.h>

#include <QDeadlineTimer>
#include <QJsonArray>
#include <QTest>
#include <QThread>
#include <QTimer>

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <sys/stat.h>

#include <condition_variable>
#include <cstring>
#include <filesystem>
#include <mutex>

using namespace hatpic;
using namespace hatpic::ros;
using hatpic::test::field;
using hatpic::test::Ros1Peer;
using hatpic::test::RosCore;
using namespace Qt::StringLiterals;

Q_DECLARE_METATYPE(hatpic::ros::Message)

namespace {

// What rosconsole says, kept for the checks (ROS 1's nodes speak through it).
class LogCapture : public ::ros::console::LogAppender
{
public:
    void log(::ros::console::Level, const char *text, const char *, const char *, int) override
    {
        const std::lock_guard lock(mutex);
        lines.append(QString::fromUtf8(text));
    }
    int count(const QString &part) const
    {
        const std::lock_guard lock(mutex);
        int n = 0;
        for (const QString &line : lines)
            n += line.contains(part) ? 1 : 0;
        return n;
    }
    mutable std::mutex mutex;
    QStringList lines;
};

// Messages a handler got, from the middleware's thread.
struct Inbox
{
    std::mutex mutex;
    std::condition_variable arrived;
    std::vector<Message> messages;
    Qt::HANDLE thread = nullptr;

    MessageHandler handler()
    {
        return [this](const Message &m) {
            const std::lock_guard lock(mutex);
            messages.push_back(m);
            thread = QThread::currentThreadId();
            arrived.notify_all();
        };
    }
    std::size_t size()
    {
        const std::lock_guard lock(mutex);
        return messages.size();
    }
    Message last()
    {
        const std::lock_guard lock(mutex);
        return messages.back();
    }
};

Header header(int sec, std::uint32_t nanosec)
{
    return {{sec, nanosec}, "hatpic_frame"};
}

// Every established TCP socket of this process whose local port is `port`, with its
// TCP_NODELAY.
QList<int> noDelayOfConnectionsOn(int port)
{
    QList<int> values;
    std::error_code error;
    for (const auto &entry : std::filesystem::directory_iterator("/proc/self/fd", error)) {
        const int fd = std::atoi(entry.path().filename().c_str());
        struct stat status;
        int listening = 1;
        socklen_t length = sizeof listening;
        if (::fstat(fd, &status) != 0 || !S_ISSOCK(status.st_mode) ||
            ::getsockopt(fd, SOL_SOCKET, SO_ACCEPTCONN, &listening, &length) != 0 || listening)
            continue;
        sockaddr_in address{};
        socklen_t addressLength = sizeof address;
        if (::getsockname(fd, reinterpret_cast<sockaddr *>(&address), &addressLength) != 0 ||
            address.sin_family != AF_INET || ntohs(address.sin_port) != port)
            continue;
        int noDelay = -1;
        length = sizeof noDelay;
        ::getsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &noDelay, &length);
        values.append(noDelay);
    }
    return values;
}

} // namespace

class TestRos1Node : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(Node::isAvailable(RosVersion::Ros1));
        ROSCONSOLE_AUTOINIT;
        ::ros::console::register_appender(&m_log);
    }
    void cleanupTestCase()
    {
        ::ros::console::deregister_appender(&m_log);
        m_peer.stop();
        m_publishers.clear();
        m_node.reset();
        m_core.stop();
    }

    void noMasterAtStartIsSaidOnceThenConnects()
    {
        std::string error;
        QElapsedTimer opening;
        opening.start();
        m_node = Node::open({RosVersion::Ros1, "hatpic_bridge"}, &error);
        QVERIFY2(m_node, error.c_str());
        auto publisher =
            m_node->advertise("/early/twist", MessageType::TwistStamped, Qos::defaults(), &error);
        QVERIFY2(publisher, error.c_str());
        QVERIFY2(opening.elapsed() < 200, qPrintable(QString::number(opening.elapsed())));
        QCOMPARE(m_node->where(),
                 "ROS 1, master " + m_core.uri().toStdString() + " (node /hatpic_bridge)");

        const QString said = u"No ROS 1 master at "_s + m_core.uri() + u" (ROS_MASTER_URI)"_s;
        QTRY_COMPARE_WITH_TIMEOUT(m_log.count(said), 1, 5000);
        QVERIFY(!publisher->publish(TwistStamped{}));
        QCOMPARE(publisher->writeErrors(), 1u);
        QTest::qWait(2500); // two more tries, said once
        QCOMPARE(m_log.count(said), 1);

        QCOMPARE(m_core.start(), QString());
        QTRY_COMPARE_WITH_TIMEOUT(m_log.count(u"/hatpic_bridge is registered with the ROS 1 "
                                              "master at "_s +
                                              m_core.uri()),
                                  1, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(publisher->publish(TwistStamped{}), 5000);
        QVERIFY(publisher->written() >= 1);
    }

    // Each type out, with values a float would not keep, as rospy decodes it.
    void messagesReachRospy_data()
    {
        QTest::addColumn<QString>("topic");
        QTest::addColumn<Message>("message");
        QTest::addColumn<QVariantMap>("expected"); // path → number or text

        JointState joint{header(1700000000, 123456789), {"hatpic_knob"}, {0.1}, {-0.2}, {0.3}};
        QTest::newRow("JointState") << u"/hatpic/joint_states"_s << Message(joint)
                                    << QVariantMap{{u"header.stamp.secs"_s, 1700000000},
                                                   {u"header.stamp.nsecs"_s, 123456789},
                                                   {u"header.frame_id"_s, u"hatpic_frame"_s},
                                                   {u"name.0"_s, u"hatpic_knob"_s},
                                                   {u"position.0"_s, 0.1},
                                                   {u"velocity.0"_s, -0.2},
                                                   {u"effort.0"_s, 0.3}};
        QTest::newRow("TwistStamped")
            << u"/hatpic/twist"_s
            << Message(TwistStamped{header(5, 6), {{0.1, 0.2, 0.3}, {0.4, 0.5, 0.6}}})
            << QVariantMap{{u"header.stamp.secs"_s, 5},
                           {u"twist.linear.x"_s, 0.1},
                           {u"twist.linear.z"_s, 0.3},
                           {u"twist.angular.y"_s, 0.5}};
        QTest::newRow("Twist") << u"/hatpic/twist_unstamped"_s
                               << Message(Twist{{0, 0, 0}, {0, 0, 0.7}})
                               << QVariantMap{{u"angular.z"_s, 0.7}, {u"linear.x"_s, 0.0}};
        QTest::newRow("PoseStamped")
            << u"/mavros/setpoint_position/local"_s
            << Message(PoseStamped{header(7, 8), {{1.1, 2.2, 0.5}, {0.1, 0.2, 0.3, 0.9}}})
            << QVariantMap{{u"pose.position.x"_s, 1.1},
                           {u"pose.position.z"_s, 0.5},
                           {u"pose.orientation.w"_s, 0.9},
                           {u"pose.orientation.x"_s, 0.1}};
        QTest::newRow("WrenchStamped")
            << u"/hatpic/feedback"_s
            << Message(WrenchStamped{header(9, 10), {{0, 0, 0}, {0, 0, 0.077}}})
            << QVariantMap{{u"wrench.torque.z"_s, 0.077}, {u"header.stamp.nsecs"_s, 10}};
        QTest::newRow("Wrench") << u"/robot/wrench_out"_s
                                << Message(Wrench{{-1.5, 2.5, -3.5}, {0, 0, 0}})
                                << QVariantMap{{u"force.x"_s, -1.5}, {u"force.z"_s, -3.5}};
    }
    void messagesReachRospy()
    {
        QFETCH(QString, topic);
        QFETCH(Message, message);
        QFETCH(QVariantMap, expected);
        QVERIFY(startPeer());
        std::string error;
        auto publisher =
            m_node->advertise(topic.toStdString(), typeOf(message), Qos::defaults(), &error);
        QVERIFY2(publisher, error.c_str());
        QTimer timer;
        connect(&timer, &QTimer::timeout, this, [&] { publisher->publish(message); });
        timer.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(!m_peer.received(topic).isEmpty(), 10000);
        const QJsonObject got = m_peer.received(topic).last();
        QCOMPARE(got.value(u"callerid"_s).toString(), u"/hatpic_bridge"_s);
        for (auto it = expected.cbegin(); it != expected.cend(); ++it) {
            if (it.value().typeId() == QMetaType::QString) {
                QJsonValue value = got.value(u"msg"_s);
                for (const QString &part : it.key().split(u'.')) {
                    bool index = false;
                    const int i = part.toInt(&index);
                    value = index ? value.toArray().at(i) : value.toObject().value(part);
                }
                QCOMPARE(value.toString(), it.value().toString());
            } else {
                QCOMPARE(field(got, it.key()), it.value().toDouble());
            }
        }
        m_publishers.push_back(std::move(publisher)); // kept for the restart below
    }

    // Types out are ROS 1's names; the node is registered at ROS_IP's address.
    void theMasterKnowsTheNodeAndItsTypes()
    {
        QVERIFY(startPeer());
        m_peer.send(u"lookup /hatpic_bridge"_s);
        QTRY_VERIFY_WITH_TIMEOUT(!m_peer.lastEvent(u"lookup"_s).isEmpty(), 5000);
        QVERIFY2(m_peer.lastEvent(u"lookup"_s)
                     .value(u"uri"_s)
                     .toString()
                     .startsWith(u"http://127.0.0.1:"_s),
                 qPrintable(m_peer.lastEvent(u"lookup"_s).value(u"uri"_s).toString()));
        m_peer.send(u"topics"_s);
        QTRY_VERIFY_WITH_TIMEOUT(!m_peer.lastEvent(u"topics"_s).isEmpty(), 5000);
        const QJsonArray topics = m_peer.lastEvent(u"topics"_s).value(u"list"_s).toArray();
        QVERIFY(topics.contains(QJsonArray{u"/hatpic/twist"_s, u"geometry_msgs/TwistStamped"_s}));
        QVERIFY(
            topics.contains(QJsonArray{u"/hatpic/joint_states"_s, u"sensor_msgs/JointState"_s}));
    }

    // rospy's messages reach the handler on a middleware thread: the test's thread waits
    // without running its event loop.
    void rospyReachesTheHandler_data()
    {
        QTest::addColumn<QString>("topic");
        QTest::addColumn<int>("type");
        QTest::addColumn<QString>("json");
        QTest::addColumn<Message>("expected");
        QTest::newRow("WrenchStamped")
            << u"/wrench_estimation"_s << int(MessageType::WrenchStamped)
            << uR"({"header": {"frame_id": "robot"}, "wrench": {"force": {"z": 0.5}}})"_s
            << Message(WrenchStamped{{{0, 0}, "robot"}, {{0, 0, 0.5}, {0, 0, 0}}});
        QTest::newRow("Wrench") << u"/robot/wrench"_s << int(MessageType::Wrench)
                                << uR"({"torque": {"z": -0.25}, "force": {"x": 1e-9}})"_s
                                << Message(Wrench{{1e-9, 0, 0}, {0, 0, -0.25}});
        QTest::newRow("TwistStamped")
            << u"/robot/twist"_s << int(MessageType::TwistStamped)
            << uR"({"header": {"stamp": {"secs": 3, "nsecs": 4}}, "twist": {"angular": {"z": 2}}})"_s
            << Message(TwistStamped{{{3, 4}, ""}, {{0, 0, 0}, {0, 0, 2}}});
        // The operator's axis selection (ros.md § Choosing the knob's axis).
        QTest::newRow("String") << u"/hatpic/axis"_s << int(MessageType::String)
                                << uR"({"data": "angular.z"})"_s << Message(String{"angular.z"});
        QTest::newRow("UInt8") << u"/hatpic/axis_index"_s << int(MessageType::UInt8)
                               << uR"({"data": 4})"_s << Message(UInt8{4});
    }
    void rospyReachesTheHandler()
    {
        QFETCH(QString, topic);
        QFETCH(int, type);
        QFETCH(QString, json);
        QFETCH(Message, expected);
        QVERIFY(startPeer());
        Inbox inbox;
        std::string error;
        auto subscription = m_node->subscribe(topic.toStdString(), MessageType(type),
                                              Qos::matchAny(), inbox.handler(), &error);
        QVERIFY2(subscription, error.c_str());
        QTRY_VERIFY_WITH_TIMEOUT(m_peer.connections(topic) >= 1, 10000);
        m_peer.send(u"set "_s + topic + u' ' + json);
        {
            std::unique_lock lock(inbox.mutex);
            QVERIFY(inbox.arrived.wait_for(lock, std::chrono::seconds(10),
                                           [&] { return !inbox.messages.empty(); }));
            QVERIFY(inbox.thread != QThread::currentThreadId());
        }
        QCOMPARE(inbox.last(), expected);
        m_peer.send(u"stop "_s + topic);
    }

    // A node never hears its own publications (the caller id roscpp gives each message): a
    // bridge whose input is also its output cannot feed itself, while rospy's are heard.
    void aNodeNeverHearsItself()
    {
        QVERIFY(startPeer());
        Inbox inbox;
        std::string error;
        const std::string topic = "/wrench_estimation";
        auto subscription = m_node->subscribe(topic, MessageType::WrenchStamped, Qos::matchAny(),
                                              inbox.handler(), &error);
        QVERIFY2(subscription, error.c_str());
        auto own = m_node->advertise(topic, MessageType::WrenchStamped, Qos::defaults(), &error);
        QVERIFY2(own, error.c_str());
        QTRY_VERIFY_WITH_TIMEOUT(m_peer.connections(u"/wrench_estimation"_s) >= 1, 10000);
        const WrenchStamped mine{header(1, 0), {{1, 0, 0}, {0, 0, 0}}};
        QTest::qWait(1000); // our own subscription connects to our publisher meanwhile
        for (int i = 0; i < 50; ++i) {
            own->publish(mine);
            QTest::qWait(10);
        }
        QTest::qWait(500);
        QCOMPARE(inbox.size(), std::size_t(0));
        m_peer.send(u"set /wrench_estimation {\"wrench\": {\"force\": {\"x\": 2}}}"_s);
        {
            std::unique_lock lock(inbox.mutex);
            QVERIFY(inbox.arrived.wait_for(lock, std::chrono::seconds(10),
                                           [&] { return !inbox.messages.empty(); }));
        }
        const auto *got = std::get_if<WrenchStamped>(&inbox.messages.front());
        QVERIFY(got);
        QCOMPARE(got->wrench.force.x, 2.0);
        m_peer.send(u"stop /wrench_estimation"_s);
    }

    // Our subscriptions ask rospy's publishers for TCP_NODELAY; the connections of our
    // publishers have it although rospy's subscribers do not ask (ros1peer.py without
    // --nodelay).
    void topicConnectionsAreNoDelay()
    {
        QVERIFY(startPeer());
        Inbox inbox;
        std::string error;
        auto subscription = m_node->subscribe("/wrench_estimation", MessageType::WrenchStamped,
                                              Qos::matchAny(), inbox.handler(), &error);
        QTRY_VERIFY_WITH_TIMEOUT(m_peer.connections(u"/wrench_estimation"_s) >= 1, 10000);
        m_peer.send(u"nodelay /wrench_estimation"_s);
        QTRY_VERIFY_WITH_TIMEOUT(!m_peer.lastEvent(u"nodelay"_s).isEmpty(), 5000);
        QCOMPARE(m_peer.lastEvent(u"nodelay"_s).value(u"values"_s).toArray(), QJsonArray{1});

        const QList<int> ours =
            noDelayOfConnectionsOn(int(::ros::ConnectionManager::instance()->getTCPPort()));
        QVERIFY2(ours.size() >= 4, qPrintable(QString::number(ours.size()))); // topics, /rosout
        QVERIFY(!ours.contains(0));
    }

    // The master restarts: the node notices, registers again, and a new rospy node sees its
    // topics and reaches its subscription. The old peer's connections are kept throughout.
    void masterRestartRegistersAgain()
    {
        QVERIFY(startPeer());
        Inbox inbox;
        std::string error;
        auto subscription = m_node->subscribe("/after/wrench", MessageType::WrenchStamped,
                                              Qos::matchAny(), inbox.handler(), &error);
        QVERIFY(subscription);
        auto publisher =
            m_node->advertise("/after/twist", MessageType::TwistStamped, Qos::defaults(), &error);
        QTRY_VERIFY_WITH_TIMEOUT(publisher->publish(TwistStamped{}), 5000);

        m_core.stop();
        QTRY_COMPARE_WITH_TIMEOUT(m_log.count(u"Lost the ROS 1 master at "_s + m_core.uri()), 1,
                                  5000);
        QCOMPARE(m_core.start(), QString());
        QTRY_COMPARE_WITH_TIMEOUT(m_log.count(u"did not know /hatpic_bridge (it restarted)"_s), 1,
                                  5000);

        // The old peer still gets what it subscribed before the restart.
        m_peer.clear();
        QTimer timer;
        connect(&timer, &QTimer::timeout, this, [&] {
            publisher->publish(TwistStamped{{{1, 2}, "after"}, {{0.25, 0, 0}, {0, 0, 0}}});
            m_publishers.front()->publish(
                JointState{header(1, 1), {"hatpic_knob"}, {0.5}, {0}, {0}});
        });
        timer.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(!m_peer.received(u"/hatpic/joint_states"_s).isEmpty(), 5000);

        // A node started after the restart finds both directions through the new master.
        Ros1Peer fresh;
        QCOMPARE(fresh.start(m_core.environment(),
                             {u"--name"_s, u"fresh_peer"_s, u"--sub"_s,
                              u"/after/twist=geometry_msgs/TwistStamped"_s, u"--pub"_s,
                              u"/after/wrench=geometry_msgs/WrenchStamped"_s}),
                 QString());
        QTRY_VERIFY_WITH_TIMEOUT(!fresh.received(u"/after/twist"_s).isEmpty(), 10000);
        QCOMPARE(field(fresh.received(u"/after/twist"_s).last(), u"twist.linear.x"_s), 0.25);
        fresh.send(uR"(set /after/wrench {"wrench": {"force": {"z": 0.75}}})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(inbox.size() > 0, 10000);
        QCOMPARE(std::get<WrenchStamped>(inbox.last()).wrench.force.z, 0.75);
    }

    // One node per process: a second open() with the same name shares it, another name is
    // refused, and the node outlives its last Node (the tuner starts and stops its bridge).
    void oneNodePerProcess()
    {
        std::string error;
        auto second = Node::open({RosVersion::Ros1, "hatpic_bridge"}, &error);
        QVERIFY2(second, error.c_str());
        QCOMPARE(second->where(), m_node->where());
        QVERIFY(!Node::open({RosVersion::Ros1, "other_name"}, &error));
        QCOMPARE(error, std::string("ROS 1 allows one node per process, and this process's node "
                                    "is /hatpic_bridge: it cannot also be 'other_name'."));
        QVERIFY(!second->advertise("/hatpic/twist", MessageType::Wrench, Qos::defaults(), &error));
        QVERIFY2(error.find("one type per topic") != std::string::npos, error.c_str());
        QVERIFY(!second->advertise("/bad topic", MessageType::Wrench, Qos::defaults(), &error));
        QVERIFY2(error.starts_with("'/bad topic' is not a ROS 1 topic name: "), error.c_str());

        // Close everything, then open again: the topics come back on the same node.
        m_publishers.clear();
        second.reset();
        m_node.reset();
        m_peer.clear();
        m_node = Node::open({RosVersion::Ros1, "hatpic_bridge"}, &error);
        QVERIFY2(m_node, error.c_str());
        auto publisher = m_node->advertise("/hatpic/joint_states", MessageType::JointState,
                                           Qos::defaults(), &error);
        QTimer timer;
        connect(&timer, &QTimer::timeout, this, [&] {
            publisher->publish(JointState{header(2, 2), {"again"}, {1}, {0}, {0}});
        });
        timer.start(20);
        // A rospy node started now finds the topic through the master. (The first peer is no
        // witness: it registered with the master before masterRestartRegistersAgain restarted
        // it, so the master tells it nothing, and it comes back only by its own reconnects,
        // whose back-off is rospy's.)
        Ros1Peer fresh;
        QCOMPARE(
            fresh.start(m_core.environment(), {u"--name"_s, u"again_peer"_s, u"--sub"_s,
                                               u"/hatpic/joint_states=sensor_msgs/JointState"_s}),
            QString());
        const auto lastName = [&fresh] {
            const auto received = fresh.received(u"/hatpic/joint_states"_s);
            return received.isEmpty() ? QString()
                                      : received.last()
                                            .value(u"msg"_s)
                                            .toObject()
                                            .value(u"name"_s)
                                            .toArray()
                                            .at(0)
                                            .toString();
        };
        QTRY_COMPARE_WITH_TIMEOUT(lastName(), u"again"_s, 30000);
    }

    // With no Node open the runtime watches no master (no one to tell, and at the process's
    // exit rosconsole may already be gone); the next Node to open hears what happened at once.
    void aClosedNodeWatchesNoMaster()
    {
        const QString lost = u"Lost the ROS 1 master at "_s + m_core.uri();
        const int before = m_log.count(lost);
        m_node.reset();
        m_core.stop();
        QTest::qWait(2500); // two checks' time
        QCOMPARE(m_log.count(lost), before);

        std::string error;
        m_node = Node::open({RosVersion::Ros1, "hatpic_bridge"}, &error);
        QVERIFY2(m_node, error.c_str());
        QTRY_COMPARE_WITH_TIMEOUT(m_log.count(lost), before + 1, 2000);
    }

private:
    bool startPeer()
    {
        if (!m_peer.uri().isEmpty())
            return true;
        const QString problem = m_peer.start(
            m_core.environment(),
            {u"--sub"_s, u"/hatpic/joint_states=sensor_msgs/JointState"_s,
             u"--sub"_s, u"/hatpic/twist=geometry_msgs/TwistStamped"_s,
             u"--sub"_s, u"/hatpic/twist_unstamped=geometry_msgs/Twist"_s,
             u"--sub"_s, u"/mavros/setpoint_position/local=geometry_msgs/PoseStamped"_s,
             u"--sub"_s, u"/hatpic/feedback=geometry_msgs/WrenchStamped"_s,
             u"--sub"_s, u"/robot/wrench_out=geometry_msgs/Wrench"_s,
             u"--pub"_s, u"/wrench_estimation=geometry_msgs/WrenchStamped"_s,
             u"--pub"_s, u"/robot/wrench=geometry_msgs/Wrench"_s,
             u"--pub"_s, u"/robot/twist=geometry_msgs/TwistStamped"_s,
             u"--pub"_s, u"/hatpic/axis=std_msgs/String"_s,
             u"--pub"_s, u"/hatpic/axis_index=std_msgs/UInt8"_s});
        if (!problem.isEmpty())
            qWarning("%s", qPrintable(problem));
        return problem.isEmpty();
    }

    // First: it sets this process's ROS 1 environment before any member starts a thread.
    RosCore m_core{RosCore::ThisProcess::Exported};
    LogCapture m_log;
    Ros1Peer m_peer;
    std::unique_ptr<Node> m_node;
    std::vector<std::unique_ptr<Publisher>> m_publishers;
};

QTEST_GUILESS_MAIN(TestRos1Node)
#include "tst_ros1node.moc"
