// A ROS 2 node on real Cyclone DDS on loopback: every message type through a publisher and a
// subscription of two nodes; the QoS pairs that match and those that do not, as between
// rmw_cyclonedds nodes; each endpoint's type hash in USER_DATA and the participant's enclave
// as DDS's built-in topics announce them; domains shared, released and refused; no handler
// call after a subscription is gone.
#include "rostestpeer.h"

#include "ros/node.h"
#include "ros/ros2/typehash.h"

#include <dds/dds.h>

#include <QTest>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <thread>

using namespace hatpic::ros;

namespace {

constexpr int kDomain = 75;      //!< this test's DDS domain
constexpr int kOtherDomain = 76; //!< for the domain's configuration rules

std::unique_ptr<Node> openNode(int domain, std::string *error = nullptr)
{
    NodeOptions options;
    options.name = "test";
    options.domainId = domain;
    return Node::open(options, error);
}

// Messages a subscription got, from its middleware thread.
class Received
{
public:
    MessageHandler handler()
    {
        return [this](const Message &m) {
            const std::lock_guard lock(m_mutex);
            m_messages.push_back(m);
        };
    }
    std::size_t size() const
    {
        const std::lock_guard lock(m_mutex);
        return m_messages.size();
    }
    Message last() const
    {
        const std::lock_guard lock(m_mutex);
        return m_messages.back();
    }

private:
    mutable std::mutex m_mutex;
    std::vector<Message> m_messages;
};

// One message of each type, with every field away from its default.
Message sampleMessage(MessageType type)
{
    const Header header{{1700000000, 123456789}, "frame ü"};
    const Vector3 a{1.5, -2.25, 1e-300}, b{std::numeric_limits<double>::infinity(), 0, -7};
    switch (type) {
    case MessageType::JointState:
        return JointState{header, {"knob", "second"}, {0.5, -1}, {0.25, 2}, {}};
    case MessageType::TwistStamped:
        return TwistStamped{header, {a, b}};
    case MessageType::Twist:
        return Twist{b, a};
    case MessageType::PoseStamped:
        return PoseStamped{header, {{1, 2, 3}, {0, 0, 0.6, 0.8}}};
    case MessageType::WrenchStamped:
        return WrenchStamped{header, {a, b}};
    case MessageType::Wrench:
        return Wrench{b, a};
    case MessageType::Bool:
        return Bool{true};
    case MessageType::JointJog:
        return JointJog{header, {"joint_1", "joint ü"}, {0.125}, {-0.5, 2}, 0.25};
    case MessageType::Imu:
        return Imu{header,
                   {0.1, -0.2, 0.3, 0.9},
                   {1, 2, 3, 4, 5, 6, 7, 8, 9},
                   a,
                   {-1, 0, 0, 0, 0, 0, 0, 0, 1e-9},
                   b,
                   {0.5, 0, 0, 0, 0.5, 0, 0, 0, -0.5}};
    case MessageType::String:
        return String{"angular.z ü"};
    case MessageType::UInt8:
        return UInt8{255};
    }
    return {};
}

// USER_DATA of an endpoint (or participant) sample as text.
std::string userDataOf(const dds_qos_t *qos)
{
    void *data = nullptr;
    size_t size = 0;
    std::string text;
    if (dds_qget_userdata(qos, &data, &size) && data) {
        text.assign(static_cast<const char *>(data), size);
        dds_free(data);
    }
    return text;
}

} // namespace

class TestRos2Node : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        hatpic::test::confineDdsToLoopback();
        std::string error;
        m_a = openNode(kDomain, &error);
        QVERIFY2(m_a, error.c_str());
        m_b = openNode(kDomain, &error);
        QVERIFY2(m_b, error.c_str());
        // A plain participant that watches the built-in topics, in the domain the nodes made.
        m_observer = dds_create_participant(kDomain, nullptr, nullptr);
        QVERIFY(m_observer > 0);
    }

    void whereItIs()
    {
        QCOMPARE(m_a->where(), std::string("ROS 2, domain 75, discovery SUBNET (CYCLONEDDS_URI "
                                           "applies)"));
    }

    void everyTypeArrivesAsSent_data()
    {
        QTest::addColumn<int>("type");
        for (int i = 0; i < kMessageTypeCount; ++i)
            QTest::newRow(rosTypeName(MessageType(i))) << i;
    }
    void everyTypeArrivesAsSent()
    {
        QFETCH(int, type);
        const auto t = MessageType(type);
        const std::string topic = "/roundtrip/t" + std::to_string(type);
        std::string error;
        Received received;
        auto subscription = m_b->subscribe(topic, t, Qos::matchAny(), received.handler(), &error);
        QVERIFY2(subscription, error.c_str());
        auto publisher = m_a->advertise(topic, t, Qos::defaults(), &error);
        QVERIFY2(publisher, error.c_str());
        const Message sent = sampleMessage(t);
        QTRY_VERIFY_WITH_TIMEOUT((publisher->publish(sent), received.size() > 0), 5000);
        QVERIFY(received.last() == sent);
        QVERIFY(publisher->written() > 0);
        QCOMPARE(publisher->writeErrors(), 0u);
    }

    // Reader and writer QoS that meet, as DDS matches them between rmw_cyclonedds nodes: a
    // best-effort writer does not serve a reliable subscription, a volatile writer does not
    // serve a transient-local one; matchAny() takes them all.
    void qosMatching_data()
    {
        using R = Qos::Reliability;
        using D = Qos::Durability;
        QTest::addColumn<int>("writerReliability");
        QTest::addColumn<int>("writerDurability");
        QTest::addColumn<int>("writerDepth");
        QTest::addColumn<int>("readerReliability");
        QTest::addColumn<int>("readerDurability");
        QTest::addColumn<bool>("matches");
        const auto row = [](const char *name, R wr, D wd, int depth, R rr, D rd, bool matches) {
            QTest::newRow(name) << int(wr) << int(wd) << depth << int(rr) << int(rd) << matches;
        };
        row("default writer, default reader", R::Reliable, D::Volatile, 10, R::Reliable,
            D::Volatile, true);
        row("default writer, match-any reader", R::Reliable, D::Volatile, 10, R::BestEffort,
            D::Volatile, true);
        row("best-effort writer, default reader", R::BestEffort, D::Volatile, 10, R::Reliable,
            D::Volatile, false);
        row("best-effort writer, match-any reader", R::BestEffort, D::Volatile, 10, R::BestEffort,
            D::Volatile, true);
        row("driver's wrench writer, match-any reader", R::BestEffort, D::TransientLocal, 1,
            R::BestEffort, D::Volatile, true);
        row("driver's wrench writer, default reader", R::BestEffort, D::TransientLocal, 1,
            R::Reliable, D::Volatile, false);
        row("volatile writer, transient-local reader", R::Reliable, D::Volatile, 10, R::Reliable,
            D::TransientLocal, false);
        row("transient-local writer, transient-local reader", R::Reliable, D::TransientLocal, 1,
            R::Reliable, D::TransientLocal, true);
    }
    void qosMatching()
    {
        QFETCH(int, writerReliability);
        QFETCH(int, writerDurability);
        QFETCH(int, writerDepth);
        QFETCH(int, readerReliability);
        QFETCH(int, readerDurability);
        QFETCH(bool, matches);
        const std::string topic = "/qos/row" + std::to_string(m_qosRow++);
        const Qos writerQos{Qos::Reliability(writerReliability), Qos::Durability(writerDurability),
                            writerDepth};
        const Qos readerQos{Qos::Reliability(readerReliability), Qos::Durability(readerDurability),
                            1};
        Received received;
        auto subscription =
            m_b->subscribe(topic, MessageType::Twist, readerQos, received.handler(), nullptr);
        auto publisher = m_a->advertise(topic, MessageType::Twist, writerQos, nullptr);
        QVERIFY(subscription && publisher);
        const Message twist = Twist{{1, 0, 0}, {}};
        if (matches) {
            QTRY_VERIFY_WITH_TIMEOUT((publisher->publish(twist), received.size() > 0), 5000);
        } else {
            for (int i = 0; i < 20; ++i) {
                QVERIFY(publisher->publish(twist)); // written, but to no one
                QTest::qWait(20);
            }
            QCOMPARE(received.size(), 0u);
        }
    }

    // Every reader and writer of each type announces "typehash=RIHS01_…;" (the hashes
    // themselves are checked against ROS 2's in tst_ros2types); the participant "enclave=/;".
    void userDataOnTheBuiltInTopics()
    {
        std::vector<std::unique_ptr<Publisher>> publishers;
        std::vector<std::unique_ptr<Subscription>> subscriptions;
        for (int i = 0; i < kMessageTypeCount; ++i) {
            const std::string topic = "/userdata/t" + std::to_string(i);
            publishers.push_back(m_a->advertise(topic, MessageType(i), Qos::defaults(), nullptr));
            subscriptions.push_back(m_b->subscribe(
                topic, MessageType(i), Qos::matchAny(), [](const Message &) {}, nullptr));
            QVERIFY(publishers.back() && subscriptions.back());
        }
        const dds_entity_t publications =
            dds_create_reader(m_observer, DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr);
        const dds_entity_t subscriptionsSeen =
            dds_create_reader(m_observer, DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, nullptr, nullptr);
        const dds_entity_t participants =
            dds_create_reader(m_observer, DDS_BUILTIN_TOPIC_DCPSPARTICIPANT, nullptr, nullptr);
        std::map<std::string, std::string> seen; // "w rt/userdata/t0" → USER_DATA
        const auto take = [&](dds_entity_t reader, const char *prefix) {
            void *samples[64] = {};
            dds_sample_info_t infos[64];
            const dds_return_t n = dds_read(reader, samples, infos, 64, 64);
            for (int i = 0; i < n; ++i) {
                const auto *e = static_cast<const dds_builtintopic_endpoint_t *>(samples[i]);
                if (infos[i].valid_data)
                    seen[prefix + std::string(e->topic_name)] = userDataOf(e->qos);
            }
            if (n > 0)
                dds_return_loan(reader, samples, n);
        };
        const auto allSeen = [&] {
            take(publications, "w ");
            take(subscriptionsSeen, "r ");
            for (int i = 0; i < kMessageTypeCount; ++i) {
                const std::string expected = hatpic::ros::ros2::typeHashUserData(
                    *hatpic::ros::ros2::findType(rosTypeName(MessageType(i))));
                for (const char *prefix : {"w ", "r "}) {
                    if (seen[prefix + std::string("rt/userdata/t") + std::to_string(i)] != expected)
                        return false;
                }
            }
            return true;
        };
        QTRY_VERIFY_WITH_TIMEOUT(allSeen(), 5000);

        void *samples[16] = {};
        dds_sample_info_t infos[16];
        const dds_return_t n = dds_read(participants, samples, infos, 16, 16);
        int enclaves = 0;
        for (int i = 0; i < n; ++i) {
            const auto *p = static_cast<const dds_builtintopic_participant_t *>(samples[i]);
            enclaves += infos[i].valid_data && userDataOf(p->qos) == "enclave=/;" ? 1 : 0;
        }
        if (n > 0)
            dds_return_loan(participants, samples, n);
        QCOMPARE(enclaves, 2); // the two nodes, not the plain observer
    }

    // A node never hears its own publications (rmw's ignore_local_publications; Cyclone's
    // ignorelocal), though another node of the same process is heard: a bridge whose input is
    // also its output cannot feed itself.
    void aNodeNeverHearsItself()
    {
        const std::string topic = "/self/loop";
        std::string error;
        Received received;
        auto subscription = m_a->subscribe(topic, MessageType::WrenchStamped, Qos::matchAny(),
                                           received.handler(), &error);
        QVERIFY2(subscription, error.c_str());
        auto own = m_a->advertise(topic, MessageType::WrenchStamped, Qos::defaults(), &error);
        QVERIFY2(own, error.c_str());
        auto other = m_b->advertise(topic, MessageType::WrenchStamped, Qos::defaults(), &error);
        QVERIFY2(other, error.c_str());
        const WrenchStamped mine{{{1, 0}, "mine"}, {{1, 0, 0}, {0, 0, 0}}};
        const WrenchStamped theirs{{{2, 0}, "theirs"}, {{2, 0, 0}, {0, 0, 0}}};
        QTRY_VERIFY_WITH_TIMEOUT((other->publish(theirs), received.size() > 0), 5000);
        const std::size_t before = received.size();
        for (int i = 0; i < 50; ++i) {
            QVERIFY(own->publish(mine));
            QTest::qWait(2);
        }
        QTest::qWait(300);
        QCOMPARE(received.size(), before);
        QVERIFY(received.last() == Message(theirs));
    }

    void publishOfAnotherTypeIsRefused()
    {
        auto publisher =
            m_a->advertise("/wrongtype", MessageType::TwistStamped, Qos::defaults(), nullptr);
        QVERIFY(publisher);
        QVERIFY(!publisher->publish(Twist{}));
        QCOMPARE(publisher->written(), 0u);
        QCOMPARE(publisher->writeErrors(), 0u);
        QVERIFY(publisher->publish(TwistStamped{}));
        QCOMPARE(publisher->written(), 1u);
    }

    void badArgumentsAreOneSentence()
    {
        std::string error;
        QVERIFY(!m_a->advertise("", MessageType::Twist, Qos::defaults(), &error));
        QCOMPARE(error, std::string("A ROS 2 topic needs a name."));
        QVERIFY(!m_a->subscribe(
            "/x", MessageType::Twist, Qos{Qos::Reliability::Reliable, Qos::Durability::Volatile, 0},
            [](const Message &) {}, &error));
        QCOMPARE(error, std::string("The QoS depth of /x must be at least 1, got 0."));
    }

    // While messages keep coming on another thread, the handler never runs once the
    // subscription's destructor has returned.
    void noHandlerCallAfterTheSubscriptionIsGone()
    {
        auto publisher = m_a->advertise("/gone", MessageType::Wrench, Qos::defaults(), nullptr);
        std::atomic<int> calls{0}, late{0};
        std::atomic<bool> gone{false}, stop{false};
        auto subscription = m_b->subscribe(
            "/gone", MessageType::Wrench, Qos::matchAny(),
            [&](const Message &) {
                if (gone)
                    ++late;
                ++calls;
                std::this_thread::sleep_for(std::chrono::microseconds(500));
            },
            nullptr);
        QVERIFY(publisher && subscription);
        std::thread robot([&] {
            while (!stop) {
                publisher->publish(Wrench{});
                std::this_thread::sleep_for(std::chrono::microseconds(200));
            }
        });
        QTRY_VERIFY_WITH_TIMEOUT(calls > 20, 5000);
        subscription.reset();
        gone = true;
        QTest::qWait(100);
        stop = true;
        robot.join();
        QCOMPARE(late.load(), 0);
    }

    // One process has one configuration per domain, made by its first node and dropped with its
    // last: other discovery settings are refused while a node is in it, and apply afterwards.
    void aDomainKeepsItsSettingsWhileItHasNodes()
    {
        std::string error;
        auto first = openNode(kOtherDomain, &error);
        QVERIFY2(first, error.c_str());
        qputenv("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST");
        QVERIFY(!openNode(kOtherDomain, &error));
        QCOMPARE(error, std::string("Another ROS 2 node of this program is in domain 76 with other "
                                    "discovery settings (ROS_LOCALHOST_ONLY, "
                                    "ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_STATIC_PEERS, "
                                    "CYCLONEDDS_URI changed): close it first."));
        first.reset();
        auto second = openNode(kOtherDomain, &error);
        qunsetenv("ROS_AUTOMATIC_DISCOVERY_RANGE");
        QVERIFY2(second, error.c_str());
        QCOMPARE(second->where(), std::string("ROS 2, domain 76, discovery LOCALHOST "
                                              "(CYCLONEDDS_URI applies)"));
    }

    void badEnvironmentIsOneSentence()
    {
        std::string error;
        qputenv("ROS_AUTOMATIC_DISCOVERY_RANGE", "NEARBY");
        QVERIFY(!openNode(kOtherDomain, &error));
        qunsetenv("ROS_AUTOMATIC_DISCOVERY_RANGE");
        QCOMPARE(error, std::string("ROS_AUTOMATIC_DISCOVERY_RANGE must be SUBNET, LOCALHOST, OFF "
                                    "or SYSTEM_DEFAULT (or unset), got 'NEARBY'."));
        const QByteArray uri = qgetenv("CYCLONEDDS_URI");
        qputenv("CYCLONEDDS_URI", "<CycloneDDS><Domain><General><Interfaces>"
                                  "<NetworkInterface name=\"no-such-interface\"/></Interfaces>"
                                  "</General></Domain></CycloneDDS>");
        QVERIFY(!openNode(kOtherDomain, &error));
        qputenv("CYCLONEDDS_URI", uri);
        QCOMPARE(error, std::string("Cyclone DDS refused the configuration of domain 76 (Error): "
                                    "check CYCLONEDDS_URI and ROS_STATIC_PEERS."));
        qputenv("ROS_DOMAIN_ID", "seven");
        QVERIFY(!openNode(-1, &error));
        QCOMPARE(error, std::string("ROS_DOMAIN_ID must be a whole number from 0 to 2147483647, "
                                    "got 'seven'."));
        qputenv("ROS_DOMAIN_ID", "76");
        auto fromEnvironment = openNode(-1, &error);
        qunsetenv("ROS_DOMAIN_ID");
        QVERIFY2(fromEnvironment, error.c_str());
        QVERIFY(fromEnvironment->where().starts_with("ROS 2, domain 76,"));
    }

    void cleanupTestCase()
    {
        dds_delete(m_observer);
        m_b.reset();
        m_a.reset();
    }

private:
    std::unique_ptr<Node> m_a, m_b;
    dds_entity_t m_observer = 0;
    int m_qosRow = 0;
};

QTEST_GUILESS_MAIN(TestRos2Node)
#include "tst_ros2node.moc"
