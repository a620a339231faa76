// ROS 2's discovery variables → the Cyclone DDS configuration of our domain, as Jazzy's rcl
// reads them and rmw_cyclonedds writes the configuration (check_create_domain): one row per
// case, the expected text written out as rmw makes it; and the values we refuse.
#include "ros/ros2/discovery.h"

#include <QTest>

using namespace hatpic::ros::ros2;
using namespace Qt::StringLiterals;

namespace {

constexpr long kPid = 4242;
const std::string kOpen = "<CycloneDDS><Domain>";
const std::string kNoMulticast = "<General><AllowMulticast>false</AllowMulticast></General>";
const std::string kAutoIndex = "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
                               "<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>";
const std::string kClose = "</Discovery></Domain></CycloneDDS>,";

} // namespace

class TestRos2Discovery : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void configurationAsRmwMakesIt_data()
    {
        QTest::addColumn<QString>("localhostOnly");
        QTest::addColumn<QString>("range");
        QTest::addColumn<QString>("peers");
        QTest::addColumn<QString>("uri");
        QTest::addColumn<QString>("config");
        const auto row = [](const char *name, const char *localhostOnly, const char *range,
                            const char *peers, const char *uri, const std::string &config) {
            QTest::newRow(name) << QString::fromUtf8(localhostOnly) << QString::fromUtf8(range)
                                << QString::fromUtf8(peers) << QString::fromUtf8(uri)
                                << QString::fromStdString(config);
        };
        // Unset means SUBNET: Cyclone's multicast, fixed participant-index ports.
        row("nothing set", "", "", "", "", kOpen + kAutoIndex + kClose);
        row("subnet", "", "SUBNET", "", "", kOpen + kAutoIndex + kClose);
        row("subnet with peers", "", "SUBNET", "10.0.0.2;robot.local", "",
            kOpen + kAutoIndex +
                "<Peers><Peer address=\"10.0.0.2\"/><Peer address=\"robot.local\"/></Peers>" +
                kClose);
        row("localhost", "", "LOCALHOST", "", "",
            kOpen + kNoMulticast + kAutoIndex + "<Peers><Peer address=\"localhost\"/></Peers>" +
                kClose);
        row("localhost, empty peer entries dropped", "", "LOCALHOST", ";10.0.0.2;;", "",
            kOpen + kNoMulticast + kAutoIndex +
                "<Peers><Peer address=\"localhost\"/><Peer address=\"10.0.0.2\"/></Peers>" +
                kClose);
        row("off ignores the peers", "", "OFF", "10.0.0.2", "",
            kOpen + kNoMulticast +
                "<Discovery><ParticipantIndex>none</ParticipantIndex>"
                "<Tag>ros_discovery_off_4242</Tag>" +
                kClose);
        row("system default leaves Cyclone alone", "", "SYSTEM_DEFAULT", "10.0.0.2", "", "");
        row("localhost only wins over range and peers", "1", "OFF", "10.0.0.2", "",
            kOpen + kNoMulticast + kAutoIndex + "<Peers><Peer address=\"localhost\"/></Peers>" +
                kClose);
        row("localhost only 0 leaves the range", "0", "LOCALHOST", "", "",
            kOpen + kNoMulticast + kAutoIndex + "<Peers><Peer address=\"localhost\"/></Peers>" +
                kClose);
        // rcl turns localhost-only on for exactly "1": "10", "1 " and "yes" leave it off.
        row("localhost only 10 is not 1", "10", "", "", "", kOpen + kAutoIndex + kClose);
        row("localhost only '1 ' is not 1", "1 ", "", "", "", kOpen + kAutoIndex + kClose);
        row("localhost only yes is not 1", "yes", "", "", "", kOpen + kAutoIndex + kClose);
        row("CYCLONEDDS_URI after, so it wins", "", "", "", "file:///etc/cyclone.xml",
            kOpen + kAutoIndex + kClose + "file:///etc/cyclone.xml");
        row("system default with CYCLONEDDS_URI", "", "SYSTEM_DEFAULT", "", "<CycloneDDS/>",
            "<CycloneDDS/>");
    }
    void configurationAsRmwMakesIt()
    {
        QFETCH(QString, localhostOnly);
        QFETCH(QString, range);
        QFETCH(QString, peers);
        QFETCH(QString, uri);
        QFETCH(QString, config);
        const DiscoveryEnvironment env{localhostOnly.toStdString(), range.toStdString(),
                                       peers.toStdString(), uri.toStdString()};
        std::string error;
        const auto discovery = discoveryFrom(env, &error);
        QVERIFY2(discovery, error.c_str());
        QCOMPARE(QString::fromStdString(cycloneConfig(*discovery, env.cycloneUri, kPid)), config);
    }

    void refusedValuesAreOneSentence_data()
    {
        QTest::addColumn<QString>("range");
        QTest::addColumn<QString>("peers");
        QTest::addColumn<QString>("error");
        QTest::newRow("unknown range")
            << u"NEARBY"_s << QString()
            << u"ROS_AUTOMATIC_DISCOVERY_RANGE must be SUBNET, LOCALHOST, OFF or SYSTEM_DEFAULT "
               "(or unset), got 'NEARBY'."_s;
        QTest::newRow("range in lower case")
            << u"localhost"_s << QString()
            << u"ROS_AUTOMATIC_DISCOVERY_RANGE must be SUBNET, LOCALHOST, OFF or SYSTEM_DEFAULT "
               "(or unset), got 'localhost'."_s;
        QTest::newRow("peer too long")
            << u"SUBNET"_s << QString(256, u'a')
            << u"ROS_STATIC_PEERS: each address must be at most 255 characters, got one of 256."_s;
        QTest::newRow("peer with markup")
            << u"LOCALHOST"_s << u"10.0.0.2;a\"/><Peer address=\"b"_s
            << u"ROS_STATIC_PEERS: an address must not contain < > & \" or ', got "
               "'a\"/><Peer address=\"b'."_s;
    }
    void refusedValuesAreOneSentence()
    {
        QFETCH(QString, range);
        QFETCH(QString, peers);
        QFETCH(QString, error);
        std::string got;
        QVERIFY(!discoveryFrom({"", range.toStdString(), peers.toStdString(), ""}, &got));
        QCOMPARE(QString::fromStdString(got), error);
    }

    // What rcl does not read is not checked either.
    void ignoredVariablesAreNotChecked()
    {
        std::string error;
        const auto localhostOnly =
            discoveryFrom({"1", "NEARBY", QString(300, u'a').toStdString(), ""}, &error);
        QVERIFY(localhostOnly);
        QCOMPARE(localhostOnly->range, DiscoveryRange::Localhost);
        QVERIFY(localhostOnly->staticPeers.empty());
        const auto off = discoveryFrom({"", "OFF", "<bad>", ""}, &error);
        QVERIFY(off);
        QVERIFY(off->staticPeers.empty());
    }

    void readFromTheProcess()
    {
        qputenv("ROS_LOCALHOST_ONLY", "0");
        qputenv("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST");
        qputenv("ROS_STATIC_PEERS", "10.0.0.2");
        qputenv("CYCLONEDDS_URI", "file:///x.xml");
        const DiscoveryEnvironment env = DiscoveryEnvironment::fromProcess();
        for (const char *name : {"ROS_LOCALHOST_ONLY", "ROS_AUTOMATIC_DISCOVERY_RANGE",
                                 "ROS_STATIC_PEERS", "CYCLONEDDS_URI"})
            qunsetenv(name);
        QCOMPARE(env.localhostOnly, std::string("0"));
        QCOMPARE(env.automaticRange, std::string("LOCALHOST"));
        QCOMPARE(env.staticPeers, std::string("10.0.0.2"));
        QCOMPARE(env.cycloneUri, std::string("file:///x.xml"));
        QCOMPARE(DiscoveryEnvironment::fromProcess().automaticRange, std::string());
    }
};

QTEST_GUILESS_MAIN(TestRos2Discovery)
#include "tst_ros2discovery.moc"
