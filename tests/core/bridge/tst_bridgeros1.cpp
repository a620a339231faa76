// The bridge over ROS 1 (roscpp) against a real roscore on loopback and a rospy node that is
// not ours, with the in-process simulated joystick held at a known angle: the same topics,
// types and mapping as over ROS 2 (tst_bridge), the wrench back as τ_ext, NaN and silence
// giving 0, and stop() leaving 0; then the IMU branch's board, one joint and one feedback per
// knob; and the operator's choice of axis, by name and by number, from rospy.
#include "roscore.h"

#include "bridge/bridge.h"
#include "session/deviceclient.h"
#include "sim/simulatorhost.h"
#include "simulatoroptions.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace hatpic;
using namespace hatpic::bridge;
using hatpic::test::field;
using hatpic::test::Ros1Peer;
using hatpic::test::RosCore;
using namespace Qt::StringLiterals;

namespace {

constexpr double kHeldAngle = 0.5;        //!< the simulated hand's target [rad]
constexpr double kTauExtTolerance = 1e-6; //!< τ_ext travels as float32 [N·m]

double stampOf(const QJsonObject &message)
{
    return field(message, u"header.stamp.secs"_s) + 1e-9 * field(message, u"header.stamp.nsecs"_s);
}

} // namespace

class TestBridgeRos1 : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        registerSessionMetaTypes();
        QCOMPARE(m_core.start(), QString());
        SimulatedDevice::Config config;
        config.hand = HandInput{HandInput::Kind::VirtualHand, 0, 0, 0, 0, kHeldAngle};
        connect(&m_client, &DeviceClient::samplesReady, this, [this](const SampleBatch &batch) {
            if (!batch.isEmpty())
                m_deviceTauExt = batch.last().tau_ext;
        });
        m_client.connectDevice(test::simulatorOptions(config));
        QTRY_COMPARE_WITH_TIMEOUT(m_client.state(), SessionState::Connected, 10000);
        m_client.setHostParams(HostParams{});

        BridgeSettings settings;
        settings.rosVersion = 1;
        settings.topics.wrenchUnstamped = "/robot/wrench";
        QCOMPARE(m_bridge.start(settings), QString());
        QCOMPARE(m_bridge.where(),
                 u"ROS 1, master "_s + m_core.uri() + u" (node /hatpic_bridge)"_s);
        QCOMPARE(m_peer.start(m_core.environment(),
                              {u"--sub"_s, u"/hatpic/joint_states=sensor_msgs/JointState"_s,
                               u"--sub"_s, u"/hatpic/twist=geometry_msgs/TwistStamped"_s,
                               u"--sub"_s, u"/hatpic/pose=geometry_msgs/PoseStamped"_s,
                               u"--sub"_s, u"/hatpic/feedback=geometry_msgs/WrenchStamped"_s,
                               u"--pub"_s, u"/wrench_estimation=geometry_msgs/WrenchStamped"_s,
                               u"--pub"_s, u"/robot/wrench=geometry_msgs/Wrench"_s,
                               u"--pub"_s, u"/teleop/enable=std_msgs/Bool"_s,
                               u"--sub"_s, u"/hatpic/imu=sensor_msgs/Imu"_s,
                               u"--pub"_s, u"/teleop/axis=std_msgs/String"_s,
                               u"--pub"_s, u"/teleop/axis_index=std_msgs/UInt8"_s}),
                 QString());
    }
    void cleanupTestCase()
    {
        m_bridge.stop();
        m_peer.stop();
        m_core.stop();
    }

    void referencesOfAHeldKnob()
    {
        // Let the knob settle at the hand's angle, then listen for half a second.
        QTRY_VERIFY_WITH_TIMEOUT(m_peer.received(u"/hatpic/twist"_s).size() >= 20, 10000);
        QTest::qWait(1500);
        m_peer.clear();
        QTest::qWait(500);
        const auto joints = m_peer.received(u"/hatpic/joint_states"_s);
        const auto twists = m_peer.received(u"/hatpic/twist"_s);
        const auto poses = m_peer.received(u"/hatpic/pose"_s);
        QVERIFY2(joints.size() >= 20 && twists.size() >= 20 && poses.size() >= 20,
                 qPrintable(QString::number(joints.size())));
        const double received = double(QDateTime::currentMSecsSinceEpoch()) * 1e-3;

        for (const QJsonObject &j : joints) {
            const QJsonObject msg = j.value(u"msg"_s).toObject();
            QCOMPARE(j.value(u"callerid"_s).toString(), u"/hatpic_bridge"_s);
            QCOMPARE(msg.value(u"header"_s).toObject().value(u"frame_id"_s).toString(),
                     u"hatpic"_s);
            QCOMPARE(msg.value(u"name"_s).toArray(), QJsonArray{u"hatpic_knob"_s});
            QCOMPARE(msg.value(u"velocity"_s).toArray().size(), 1);
            QCOMPARE(msg.value(u"effort"_s).toArray().size(), 1);
            const double position = field(j, u"position.0"_s);
            QVERIFY2(position > 0.25 && position < kHeldAngle + 0.05,
                     qPrintable(QString::number(position)));
            QVERIFY(std::abs(stampOf(j) - received) < 1.0); // the wall clock
        }
        // v_ref = v_max/2 · θ (v_max 1, θ0 0) on linear.x, matched by stamp.
        int matched = 0;
        for (const QJsonObject &t : twists) {
            for (const QJsonObject &j : joints) {
                if (field(j, u"header.stamp.secs"_s) != field(t, u"header.stamp.secs"_s) ||
                    field(j, u"header.stamp.nsecs"_s) != field(t, u"header.stamp.nsecs"_s))
                    continue;
                ++matched;
                QVERIFY(std::abs(field(t, u"twist.linear.x"_s) - 0.5 * field(j, u"position.0"_s)) <
                        1e-12);
                QCOMPARE(field(t, u"twist.linear.y"_s), 0.0);
                QCOMPARE(field(t, u"twist.angular.z"_s), 0.0);
            }
        }
        QVERIFY(matched >= 20);
        // p_ref = ∫ v_ref dt on position.x: it grows at v_ref per second of stamp time.
        const double dt = stampOf(poses.last()) - stampOf(poses.first());
        const double rate = (field(poses.last(), u"pose.position.x"_s) -
                             field(poses.first(), u"pose.position.x"_s)) /
                            dt;
        const double v = field(twists.last(), u"twist.linear.x"_s);
        QVERIFY2(std::abs(rate - v) < 0.1 * v, qPrintable(QString::number(rate)));
        QCOMPARE(field(poses.last(), u"pose.orientation.w"_s), 1.0);
    }

    void wrenchBecomesTauExt()
    {
        QTRY_VERIFY_WITH_TIMEOUT(m_peer.connections(u"/wrench_estimation"_s) >= 1, 10000);
        // A robot publishing at 50 Hz (ros1peer.py's rate).
        m_peer.send(uR"(set /wrench_estimation {"wrench": {"force": {"z": 0.5}}})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - 0.077) < kTauExtTolerance, 5000);
        QCOMPARE(m_bridge.stats().tauExt, 0.077);
        QTRY_VERIFY_WITH_TIMEOUT(feedbackSeen(0.077), 3000);

        m_peer.send(uR"(set /wrench_estimation {"wrench": {"force": {"z": NaN}}})"_s);
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 3000);
        QVERIFY(m_bridge.stats().wrenches.nonFinite > 0);
        QTRY_VERIFY_WITH_TIMEOUT(feedbackSeen(0.0), 3000);

        m_peer.send(uR"(set /wrench_estimation {"wrench": {"force": {"z": -1e12}}})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt + 0.154) < kTauExtTolerance, 3000);
        QVERIFY(m_bridge.stats().wrenches.limited > 0);

        // The robot falls silent: after 0.5 s the wrench is stale and τ_ext goes to 0.
        m_peer.send(u"stop /wrench_estimation"_s);
        QElapsedTimer silent;
        silent.start();
        const quint64 staleBefore = m_bridge.stats().wrenches.stale;
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 3000);
        QVERIFY2(silent.elapsed() >= 400, qPrintable(QString::number(silent.elapsed())));
        QCOMPARE(m_bridge.stats().wrenches.stale, staleBefore + 1);
    }

    void unstampedWrenchIsAcceptedToo()
    {
        QTRY_VERIFY_WITH_TIMEOUT(m_peer.connections(u"/robot/wrench"_s) >= 1, 10000);
        m_peer.send(uR"(set /robot/wrench {"force": {"z": -0.25}})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt + 0.0385) < kTauExtTolerance, 5000);
        m_peer.send(u"stop /robot/wrench"_s);
    }

    // The dead man over ROS 1 (ros.md § Enable switch): released until the first true, by
    // false and by silence; the twist zero and τ_ext zero while released.
    void enableSwitch()
    {
        BridgeSettings settings = m_bridge.settings();
        settings.topics.enable = "/teleop/enable";
        QCOMPARE(m_bridge.start(settings), QString());
        QTRY_VERIFY_WITH_TIMEOUT(m_peer.connections(u"/teleop/enable"_s) >= 1, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(m_peer.connections(u"/wrench_estimation"_s) >= 1, 10000);
        m_peer.send(uR"(set /wrench_estimation {"wrench": {"force": {"z": 0.5}}})"_s);
        QTest::qWait(700);
        QCOMPARE(m_deviceTauExt, 0.0);
        QVERIFY(!m_bridge.stats().engaged);
        m_peer.clear();
        QTest::qWait(300);
        QVERIFY(twistsAllZero());

        m_peer.send(uR"(set /teleop/enable {"data": true})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - 0.077) < kTauExtTolerance, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(
            field(m_peer.received(u"/hatpic/twist"_s).last(), u"twist.linear.x"_s) > 0.1, 3000);

        m_peer.send(uR"(set /teleop/enable {"data": false})"_s);
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 3000);
        QTest::qWait(100);
        m_peer.clear();
        QTest::qWait(300);
        QVERIFY(twistsAllZero());

        m_peer.send(uR"(set /teleop/enable {"data": true})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - 0.077) < kTauExtTolerance, 5000);
        m_peer.send(u"stop /teleop/enable"_s); // the teleop node dies
        QElapsedTimer silent;
        silent.start();
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 3000);
        QVERIFY2(silent.elapsed() >= 400, qPrintable(QString::number(silent.elapsed())));
        m_peer.send(u"stop /wrench_estimation"_s);
        settings.topics.enable.clear();
        QCOMPARE(m_bridge.start(settings), QString());
    }

    void stopLeavesTauExtZero()
    {
        m_peer.send(uR"(set /wrench_estimation {"wrench": {"force": {"z": 0.5}}})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - 0.077) < kTauExtTolerance, 5000);
        m_bridge.stop();
        QVERIFY(!m_bridge.isRunning());
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 300); // well before staleness would
        m_peer.send(u"stop /wrench_estimation"_s);
    }

    // The IMU branch's board (simulated, on a real pty) through a bridge of its own on the
    // same topics, once the single knob's has stopped: four joints, each wrench component felt
    // on its knob (ros.md § A board's knobs).
    void aBoardsKnobsOverRos1()
    {
        m_bridge.stop();
        SimulatedDevice::Config config;
        config.board = SimulatedDevice::Board::ImuBranch;
        config.otherHands[1] = *HandInput::parse(u"const:0.05"_s); // knob 3 pushed, 0.05 N·m
        SimulatorHost host(config);
        QCOMPARE(host.start(), QString());
        DeviceClient board;
        Sample last;
        connect(&board, &DeviceClient::samplesReady, this, [&last](const SampleBatch &batch) {
            if (!batch.isEmpty())
                last = batch.last();
        });
        ConnectOptions o;
        o.port = host.slavePath();
        board.connectDevice(o);
        QTRY_COMPARE_WITH_TIMEOUT(last.axes(), 4, 10000);
        Bridge bridge(board);
        BridgeSettings settings;
        settings.rosVersion = 1;
        settings.feedback.component = Component{false, 0}; // the published script's force.x
        QCOMPARE(bridge.start(settings), QString());

        m_peer.clear();
        QTRY_VERIFY_WITH_TIMEOUT(m_peer.received(u"/hatpic/joint_states"_s).size() >= 5, 10000);
        const QJsonObject j = m_peer.received(u"/hatpic/joint_states"_s).last();
        QCOMPARE(j.value(u"msg"_s).toObject().value(u"name"_s).toArray(),
                 (QJsonArray{u"hatpic_knob"_s, u"hatpic_knob_2"_s, u"hatpic_knob_3"_s,
                             u"hatpic_knob_4"_s}));
        QVERIFY2(field(j, u"position.2"_s) > 0.1 && std::abs(field(j, u"position.1"_s)) < 0.01,
                 qPrintable(QString::number(field(j, u"position.2"_s))));
        QTRY_VERIFY_WITH_TIMEOUT(
            field(m_peer.received(u"/hatpic/twist"_s).last(), u"twist.linear.z"_s) > 0, 5000);
        // The tilt (level here) as sensor_msgs/Imu, orientation only.
        QTRY_VERIFY_WITH_TIMEOUT(!m_peer.received(u"/hatpic/imu"_s).isEmpty(), 5000);
        const QJsonObject imu = m_peer.received(u"/hatpic/imu"_s).last();
        QVERIFY(std::abs(field(imu, u"orientation.w"_s) - 1) < 1e-6);
        QCOMPARE(field(imu, u"angular_velocity_covariance.0"_s), -1.0);
        QCOMPARE(field(imu, u"linear_acceleration_covariance.0"_s), -1.0);
        QCOMPARE(field(imu, u"orientation_covariance.0"_s), 0.0);

        m_peer.send(
            uR"(set /wrench_estimation {"wrench": {"force": {"y": 0.5}, "torque": {"z": -0.5}}})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(last.axis(2)->tau_ext > 0.07, 5000);
        QVERIFY(last.axis(4)->tau_ext < -0.07);
        QCOMPARE(bridge.stats().torques, (AxisTorques{0, 0.077, 0, -0.077}));
        bridge.stop();
        QTRY_COMPARE_WITH_TIMEOUT(last.axis(2)->tau_ext, 0.0, 1000);
        QCOMPARE(last.axis(4)->tau_ext, 0.0);
        m_peer.send(u"stop /wrench_estimation"_s);
        board.disconnectDevice();
    }

    // The operator's choice of axis from rospy (ros.md § Choosing the knob's axis), on a knob
    // a hand pushes and lets go: asked mid-push it waits, taken in the dead zone the pose goes
    // on along it, and what names no axis is counted.
    void anAxisChosenOverRos1()
    {
        m_bridge.stop();
        const HandInput hand = *HandInput::parse(u"pushes:0.1:1000:0.8:0.8"_s); // 0.8 s on, 0.8 off
        SimulatedDevice::Config config;
        config.hand = hand;
        DeviceClient knob;
        double theta = 0;
        connect(&knob, &DeviceClient::samplesReady, this, [&theta](const SampleBatch &batch) {
            if (!batch.isEmpty())
                theta = batch.last().theta;
        });
        knob.connectDevice(test::simulatorOptions(config));
        QTRY_COMPARE_WITH_TIMEOUT(knob.state(), SessionState::Connected, 10000);
        knob.setHostParams(HostParams{});
        Bridge bridge(knob);
        BridgeSettings settings;
        settings.rosVersion = 1;
        settings.topics.axis = "/teleop/axis";
        settings.topics.axisIndex = "/teleop/axis_index";
        QCOMPARE(bridge.start(settings), QString());
        QTRY_VERIFY_WITH_TIMEOUT(m_peer.connections(u"/teleop/axis"_s) >= 1 &&
                                     m_peer.connections(u"/teleop/axis_index"_s) >= 1,
                                 10000);
        const Component y{false, 1}, pitch{true, 1};

        QTRY_VERIFY_WITH_TIMEOUT(std::abs(theta) < 0.01, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(theta) > 0.05, 5000);
        m_peer.send(uR"(once /teleop/axis {"data": "linear.y"})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(bridge.stats().pendingAxis == y, 3000);
        QTRY_VERIFY_WITH_TIMEOUT(bridge.stats().axis == y, 3000);
        QCOMPARE(bridge.stats().feltComponent, y);
        QTRY_VERIFY_WITH_TIMEOUT(
            std::abs(field(m_peer.received(u"/hatpic/pose"_s).last(), u"pose.position.y"_s)) > 0.01,
            5000);

        m_peer.send(uR"(once /teleop/axis_index {"data": 4})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(bridge.stats().axis == pitch, 4000);
        m_peer.send(uR"(once /teleop/axis {"data": "up"})"_s);
        QTRY_COMPARE_WITH_TIMEOUT(bridge.stats().axisRejected, std::uint64_t(1), 3000);
        QCOMPARE(bridge.stats().lastAxisRejected, std::string("up"));
        QCOMPARE(bridge.stats().axis, pitch);
        bridge.stop();
        knob.disconnectDevice();
    }

private:
    bool twistsAllZero() const
    {
        const auto twists = m_peer.received(u"/hatpic/twist"_s);
        return !twists.isEmpty() && std::all_of(twists.begin(), twists.end(), [](const auto &t) {
            return field(t, u"twist.linear.x"_s) == 0.0;
        });
    }
    bool feedbackSeen(double tau) const
    {
        const auto feedbacks = m_peer.received(u"/hatpic/feedback"_s);
        return !feedbacks.isEmpty() &&
               std::abs(field(feedbacks.last(), u"wrench.torque.z"_s) - tau) < kTauExtTolerance;
    }

    // First: it sets this process's ROS 1 environment before any member starts a thread.
    RosCore m_core{RosCore::ThisProcess::Exported};
    Ros1Peer m_peer;
    DeviceClient m_client;
    Bridge m_bridge{m_client};
    double m_deviceTauExt = 0;
};

QTEST_GUILESS_MAIN(TestBridgeRos1)
#include "tst_bridgeros1.moc"
