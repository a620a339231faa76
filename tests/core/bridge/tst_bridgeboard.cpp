// The bridge with the IMU branch's board over real Cyclone DDS on loopback: the simulated board
// behind a real pseudo-terminal, a DeviceClient found by auto-detection, and a test node built
// as rmw_cyclonedds builds one. One joint per knob, each knob's references on its own twist
// component, the tilt as sensor_msgs/Imu, and each component of the robot's wrench felt on its
// own knob.
#include "rostestpeer.h"

#include "bridge/bridge.h"
#include "session/deviceclient.h"
#include "sim/simulatorhost.h"

#include <QTest>
#include <QTimer>

#include <array>
#include <cmath>

using namespace hatpic;
using namespace hatpic::bridge;
using hatpic::test::RosTestPeer;
using namespace Qt::StringLiterals;

namespace {
constexpr int kDomain = 76;         //!< this test's own DDS domain
constexpr int kTimeoutMs = 10000;   //!< connecting, discovery
constexpr double kKnob3Push = 0.05; //!< the hand's steady push on knob 3 [N·m]
constexpr double kRoll = 0.3;       //!< the board's tilt [rad]
constexpr double kPitch = -0.2;
} // namespace

class TestBridgeBoard : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        registerSessionMetaTypes();
        SimulatedDevice::Config config;
        config.board = SimulatedDevice::Board::ImuBranch;
        config.otherHands[1] = *HandInput::parse(u"const:%1"_s.arg(kKnob3Push)); // knob 3
        config.roll = kRoll;
        config.pitch = kPitch;
        m_host = std::make_unique<SimulatorHost>(config);
        const QString error = m_host->start();
        QVERIFY2(error.isEmpty(), qPrintable(error));
        connect(&m_client, &DeviceClient::samplesReady, this, [this](const SampleBatch &b) {
            if (!b.isEmpty())
                m_last = b.last();
        });
        ConnectOptions o;
        o.port = m_host->slavePath();
        m_client.connectDevice(o);
        QTRY_COMPARE_WITH_TIMEOUT(m_client.state(), SessionState::Connected, kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(m_last.axes(), 4, kTimeoutMs);

        BridgeSettings settings;
        settings.domainId = kDomain;
        settings.jointName = "x_knob,y_knob";
        // The published ROS script's mapping: force.x, force.y, force.z, torque.z.
        settings.feedback.component = Component{false, 0};
        m_peer = std::make_unique<RosTestPeer>(kDomain);
        QCOMPARE(m_bridge.start(settings), QString());
        QVERIFY(m_peer->isValid());
    }

    void oneJointPerKnob()
    {
        QTRY_VERIFY_WITH_TIMEOUT((m_peer->take(), m_peer->joints.size() >= 5), kTimeoutMs);
        const auto &j = m_peer->joints.back();
        QCOMPARE(j.names, (std::vector<std::string>{"x_knob", "y_knob", "x_knob_3", "x_knob_4"}));
        QCOMPARE(j.position.size(), 4u);
        // Knob 3 pushed against its spring, the others at rest.
        QVERIFY2(j.position[2] > 0.1, qPrintable(QString::number(j.position[2])));
        QVERIFY(std::abs(j.position[0]) < 0.01 && std::abs(j.position[3]) < 0.01);
        // Legacy carries no ω or τ: NaN, as a single knob's.
        QCOMPARE(j.velocity.size(), 4u);
        QVERIFY(std::isnan(j.velocity[1]));
    }

    // The tilt as sensor_msgs/Imu: roll about x, then pitch about y; nothing else given.
    void theTiltAsImu()
    {
        QTRY_VERIFY_WITH_TIMEOUT((m_peer->take(), !m_peer->imus.empty()), kTimeoutMs);
        const auto &imu = m_peer->imus.back();
        QCOMPARE(imu.frame, std::string("hatpic"));
        const double cr = std::cos(kRoll / 2), sr = std::sin(kRoll / 2);
        const double cp = std::cos(kPitch / 2), sp = std::sin(kPitch / 2);
        const std::array<double, 4> expected{sr * cp, cr * sp, -sr * sp, cr * cp};
        for (std::size_t i = 0; i < 4; ++i) // the wire's tilt: 0…2000 over 180°, 0.09° a unit
            QVERIFY2(std::abs(imu.orientation[i] - expected[i]) < 1e-3,
                     qPrintable(QString::number(imu.orientation[i])));
        QCOMPARE(imu.orientationCovariance, (std::array<double, 9>{})); // not known
        QCOMPARE(imu.angularVelocityCovariance[0], -1.0);               // not given
        QCOMPARE(imu.linearAccelerationCovariance[0], -1.0);
        QVERIFY(m_bridge.stats().published[int(OutTopic::Imu)] > 0);
    }

    void eachKnobOnItsOwnComponent()
    {
        // Knob 3 off centre: its reference velocity goes on linear.z, nobody else's.
        QTRY_VERIFY_WITH_TIMEOUT(
            (m_peer->take(), !m_peer->twists.empty() && m_peer->twists.back().a[2] != 0.0),
            kTimeoutMs);
        const auto &t = m_peer->twists.back();
        QCOMPARE(t.a[0], 0.0);
        QCOMPARE(t.a[1], 0.0);
        QCOMPARE(t.b[2], 0.0);
        QVERIFY(t.a[2] > 0);
        QTRY_VERIFY_WITH_TIMEOUT(
            (m_peer->take(), !m_peer->poses.empty() && m_peer->poses.back().position[2] > 0),
            kTimeoutMs);
    }

    void eachKnobFeelsItsComponent()
    {
        QTRY_VERIFY_WITH_TIMEOUT(m_peer->wrenchMatched(), kTimeoutMs);
        // force.y → knob 2, torque.z → knob 4 (opposite ways); force.x (knob 1's) is 0.
        QTimer robot;
        connect(&robot, &QTimer::timeout, this, [this] {
            m_peer->publishWrench({0, 0.5, 0}, {0, 0, -0.5});
        });
        robot.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(m_bridge.stats().torques[1] != 0.0, kTimeoutMs);
        const AxisTorques asked = m_bridge.stats().torques;
        QCOMPARE(asked[0], 0.0);
        QCOMPARE(asked[1], 0.5 * 0.154);
        QCOMPARE(asked[2], 0.0);
        QCOMPARE(asked[3], -0.5 * 0.154);
        // The samples say the device was sent them, and the knobs move that way.
        QTRY_VERIFY_WITH_TIMEOUT(m_last.axis(2)->tau_ext > 0.07, kTimeoutMs);
        QVERIFY(m_last.axis(4)->tau_ext < -0.07);
        QTRY_VERIFY_WITH_TIMEOUT(m_host->device().knobAngles()[1] > 0.01, kTimeoutMs);
        QVERIFY(m_host->device().knobAngles()[3] < -0.01);
        QVERIFY(std::abs(m_host->device().knobAngles()[0]) < 0.01);

        // The robot falls silent: every knob is let go once the wrench is stale.
        robot.stop();
        QTRY_COMPARE_WITH_TIMEOUT(m_bridge.stats().torques, AxisTorques{}, kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(m_last.axis(4)->tau_ext, 0.0, kTimeoutMs);
    }

    void releasedLetsEveryKnobGo()
    {
        QTimer robot;
        connect(&robot, &QTimer::timeout, this, [this] {
            m_peer->publishWrench({0, 0.5, 0.5}, {0, 0, 0});
        });
        robot.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(m_bridge.stats().torques[2] != 0.0, kTimeoutMs);
        m_bridge.setEngaged(false);
        QCOMPARE(m_bridge.stats().torques, AxisTorques{});
        QTRY_COMPARE_WITH_TIMEOUT(m_last.axis(2)->tau_ext, 0.0, kTimeoutMs);
        QCOMPARE(m_last.axis(3)->tau_ext, 0.0);
        m_bridge.setEngaged(true);
        robot.stop();
        m_bridge.stop();
        QTRY_COMPARE_WITH_TIMEOUT(m_last.axis(3)->tau_ext, 0.0, kTimeoutMs);
    }

    void cleanupTestCase()
    {
        m_bridge.stop();
        m_client.disconnectDevice();
    }

private:
    test::LoopbackDds m_loopback; // first: before the session thread starts
    DeviceClient m_client;
    Bridge m_bridge{m_client};
    std::unique_ptr<SimulatorHost> m_host;
    std::unique_ptr<RosTestPeer> m_peer;
    Sample m_last;
};

QTEST_GUILESS_MAIN(TestBridgeBoard)
#include "tst_bridgeboard.moc"
