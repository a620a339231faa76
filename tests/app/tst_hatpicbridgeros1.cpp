// hatpic-bridge --ros 1, run as a real process against a simulated joystick on a
// pseudo-terminal, a real roscore on loopback and a rospy node that is not ours: started
// before the master (it says so and connects when the master comes), the MAVROS recipe's
// topics and origin, the wrench round trip with NaN giving 0, statistics, ROS_NAMESPACE, bad
// options, and SIGINT leaving the device with τ_ext 0.
#include "roscore.h"

#include "sim/simulatorhost.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QProcess>
#include <QTest>

#include <cmath>
#include <csignal>

using namespace hatpic;
using hatpic::test::field;
using hatpic::test::Ros1Peer;
using hatpic::test::RosCore;
using namespace Qt::StringLiterals;

namespace {

constexpr double kTauExtTolerance = 1e-6; //!< τ_ext travels as float32 [N·m]

} // namespace

class TestHatpicBridgeRos1 : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void badOptionsAreOneSentence_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("masterUri");
        QTest::addColumn<int>("code");
        QTest::addColumn<QByteArray>("message");
        QTest::newRow("version") << QStringList{u"--port"_s, u"sim"_s, u"--ros"_s, u"3"_s}
                                 << QString() << 4
                                 << QByteArray("ROS version: must be 1 or 2, got 3.");
        QTest::newRow("not a number")
            << QStringList{u"--port"_s, u"sim"_s, u"--ros"_s, u"one"_s} << QString() << 4
            << QByteArray("--ros needs a whole number, got 'one'.");
        QTest::newRow("master uri")
            << QStringList{u"--port"_s, u"sim"_s, u"--ros"_s, u"1"_s} << u"localhost"_s << 1
            << QByteArray("ROS_MASTER_URI must be http://HOST:PORT, got 'localhost'.");
    }
    void badOptionsAreOneSentence()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, masterUri);
        QFETCH(int, code);
        QFETCH(QByteArray, message);
        QProcess bridge;
        QProcessEnvironment env = m_core.environment();
        if (!masterUri.isEmpty())
            env.insert(u"ROS_MASTER_URI"_s, masterUri);
        bridge.setProcessEnvironment(env);
        bridge.start(QStringLiteral(HATPIC_BRIDGE_PATH), arguments);
        QVERIFY(bridge.waitForFinished(10000));
        QCOMPARE(bridge.exitCode(), code);
        const QByteArray err = bridge.readAllStandardError();
        QVERIFY2(err.contains(message), err.constData());
        QCOMPARE(err.trimmed().count('\n'), 0);
    }

    // Started before the master, with the published ROS 1 driver's MAVROS setting for the
    // pose: says so once, connects when the master comes, and then does everything.
    void noMasterAtStartThenRoundTripAndSigint()
    {
        SimulatedDevice::Config config;
        config.hand = HandInput{HandInput::Kind::VirtualHand, 0, 0, 0, 0, 0.5};
        SimulatorHost host(config);
        QCOMPARE(host.start(), QString());
        QProcess bridge;
        bridge.setProcessEnvironment(m_core.environment());
        bridge.start(QStringLiteral(HATPIC_BRIDGE_PATH),
                     {u"--ros"_s, u"1"_s, u"--port"_s, host.slavePath(), u"--pose-topic"_s,
                      u"/mavros/setpoint_position/local"_s, u"--origin"_s, u"0,0,0.5"_s});
        QVERIFY(bridge.waitForStarted());
        QByteArray err, out;
        const QByteArray said = "No ROS 1 master at " + m_core.uri().toUtf8() +
                                " (ROS_MASTER_URI): /hatpic_bridge tries again every second.";
        QTRY_VERIFY_WITH_TIMEOUT((err += bridge.readAllStandardError(), err.contains(said)), 10000);

        QCOMPARE(m_core.start(), QString());
        Ros1Peer peer;
        QCOMPARE(peer.start(m_core.environment(),
                            {u"--sub"_s, u"/hatpic/joint_states=sensor_msgs/JointState"_s,
                             u"--sub"_s, u"/hatpic/twist=geometry_msgs/TwistStamped"_s, u"--sub"_s,
                             u"/mavros/setpoint_position/local=geometry_msgs/PoseStamped"_s,
                             u"--sub"_s, u"/hatpic/feedback=geometry_msgs/WrenchStamped"_s,
                             u"--pub"_s, u"/wrench_estimation=geometry_msgs/WrenchStamped"_s}),
                 QString());

        // References of the held knob, from /hatpic_bridge.
        QTRY_VERIFY_WITH_TIMEOUT(peer.received(u"/hatpic/twist"_s).size() >= 50, 15000);
        const QJsonObject twist = peer.received(u"/hatpic/twist"_s).last();
        QCOMPARE(twist.value(u"callerid"_s).toString(), u"/hatpic_bridge"_s);
        const double v = field(twist, u"twist.linear.x"_s);
        QVERIFY2(v > 0.1 && v < 0.3, qPrintable(QString::number(v)));
        QTRY_VERIFY_WITH_TIMEOUT(!peer.received(u"/mavros/setpoint_position/local"_s).isEmpty(),
                                 5000);
        QCOMPARE(
            field(peer.received(u"/mavros/setpoint_position/local"_s).last(), u"pose.position.z"_s),
            0.5);
        QCOMPARE(peer.received(u"/hatpic/joint_states"_s)
                     .last()
                     .value(u"msg"_s)
                     .toObject()
                     .value(u"name"_s)
                     .toArray(),
                 QJsonArray{u"hatpic_knob"_s});

        // A wrench at 50 Hz reaches the device and comes back on /hatpic/feedback; NaN gives 0.
        QTRY_VERIFY_WITH_TIMEOUT(peer.connections(u"/wrench_estimation"_s) >= 1, 10000);
        const auto feedbackIs = [&peer](double tau) {
            const auto feedbacks = peer.received(u"/hatpic/feedback"_s);
            return !feedbacks.isEmpty() &&
                   std::abs(field(feedbacks.last(), u"wrench.torque.z"_s) - tau) < kTauExtTolerance;
        };
        peer.send(uR"(set /wrench_estimation {"wrench": {"force": {"z": 0.5}}})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(feedbackIs(0.077), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(
            (out += bridge.readAllStandardOutput(), out.contains("| tau_ext 0.077 N·m")), 5000);
        QVERIFY2(out.contains("out joint_states "), out.constData());
        peer.send(uR"(set /wrench_estimation {"wrench": {"force": {"z": NaN}}})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(feedbackIs(0.0), 5000);
        // The statistics count the rejected wrench.
        const auto lastStats = [&] {
            out += bridge.readAllStandardOutput();
            const QList<QByteArray> lines = out.trimmed().split('\n');
            return lines.isEmpty() ? QByteArray() : lines.last();
        };
        QTRY_VERIFY_WITH_TIMEOUT(!lastStats().contains("non-finite 0,"), 5000);
        peer.send(uR"(set /wrench_estimation {"wrench": {"force": {"z": 0.5}}})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(feedbackIs(0.077), 10000);

        // SIGINT while the wrench is still coming: exit 0 within a second, and the device's
        // telemetry showed τ_ext 0 on /hatpic/feedback before the bridge went.
        QElapsedTimer stopping;
        stopping.start();
        ::kill(pid_t(bridge.processId()), SIGINT);
        QTRY_VERIFY_WITH_TIMEOUT(bridge.state() == QProcess::NotRunning, 5000);
        const qint64 stopMs = stopping.elapsed();
        peer.send(u"stop /wrench_estimation"_s);
        QCOMPARE(bridge.exitStatus(), QProcess::NormalExit);
        QCOMPARE(bridge.exitCode(), 0);
        QVERIFY2(stopMs < 1000, qPrintable(QString::number(stopMs)));
        QVERIFY(feedbackIs(0.0));
        err += bridge.readAllStandardError();
        QCOMPARE(err.count(said), 1);
    }

    // ROS_NAMESPACE (ros.md § Several knobs): the node, a relative topic and the topics at
    // their defaults are in it; an absolute topic given explicitly is not.
    void namespaceHoldsTheNodeAndItsTopics()
    {
        QCOMPARE(m_core.start(), QString());
        SimulatorHost host{SimulatedDevice::Config{}};
        QCOMPARE(host.start(), QString());
        QProcess bridge;
        QProcessEnvironment env = m_core.environment();
        env.insert(u"ROS_NAMESPACE"_s, u"/robot1"_s);
        bridge.setProcessEnvironment(env);
        bridge.start(QStringLiteral(HATPIC_BRIDGE_PATH),
                     {u"--ros"_s, u"1"_s, u"--port"_s, host.slavePath(), u"--twist-topic"_s,
                      u"hatpic/twist"_s, u"--pose-topic"_s, u"/elsewhere/pose"_s});
        QVERIFY(bridge.waitForStarted());
        Ros1Peer peer;
        QCOMPARE(peer.start(m_core.environment(),
                            {u"--sub"_s, u"/robot1/hatpic/twist=geometry_msgs/TwistStamped"_s,
                             u"--sub"_s, u"/robot1/hatpic/joint_states=sensor_msgs/JointState"_s,
                             u"--sub"_s, u"/elsewhere/pose=geometry_msgs/PoseStamped"_s}),
                 QString());
        QTRY_VERIFY_WITH_TIMEOUT(!peer.received(u"/robot1/hatpic/joint_states"_s).isEmpty(), 15000);
        QTRY_VERIFY_WITH_TIMEOUT(!peer.received(u"/elsewhere/pose"_s).isEmpty(), 5000);
        twistFromThen(peer, u"/robot1"_s, bridge);
        if (QTest::currentTestFailed())
            return;

        // --namespace wins over ROS_NAMESPACE.
        bridge.start(
            QStringLiteral(HATPIC_BRIDGE_PATH),
            {u"--ros"_s, u"1"_s, u"--port"_s, host.slavePath(), u"--namespace"_s, u"knob2"_s});
        QVERIFY(bridge.waitForStarted());
        Ros1Peer second;
        QCOMPARE(second.start(m_core.environment(),
                              {u"--sub"_s, u"/knob2/hatpic/twist=geometry_msgs/TwistStamped"_s}),
                 QString());
        twistFromThen(second, u"/knob2"_s, bridge);
    }

    void cleanupTestCase() { m_core.stop(); }

private:
    // `peer` receives NS/hatpic/twist from the node NS/hatpic_bridge; then the bridge stops on
    // SIGINT with exit code 0.
    void twistFromThen(const Ros1Peer &peer, const QString &ns, QProcess &bridge)
    {
        const QString topic = ns + u"/hatpic/twist"_s;
        QTRY_VERIFY_WITH_TIMEOUT(!peer.received(topic).isEmpty(), 15000);
        QCOMPARE(peer.received(topic).last().value(u"callerid"_s).toString(),
                 ns + u"/hatpic_bridge"_s);
        ::kill(pid_t(bridge.processId()), SIGINT);
        QTRY_VERIFY_WITH_TIMEOUT(bridge.state() == QProcess::NotRunning, 5000);
        QCOMPARE(bridge.exitCode(), 0);
    }

    RosCore m_core;
};

QTEST_GUILESS_MAIN(TestHatpicBridgeRos1)
#include "tst_hatpicbridgeros1.moc"
