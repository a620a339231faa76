// The bridge over real Cyclone DDS on loopback, against the in-process simulated joystick and a
// test node built as rmw_cyclonedds builds one: a limit above the device's refused, stop leaving
// τ_ext at zero, the enable switch (the dead man: released, engaged, the local switch,
// silence), two knobs side by side in one domain, each bridge under its own namespace, and the
// operator's choice of the axis a knob drives.
#include "bridgetest.h"
#include "rostestpeer.h"

#include "bridge/bridge.h"
#include "session/deviceclient.h"

#include <QElapsedTimer>
#include <QTest>
#include <QTimer>

#include <algorithm>
#include <cmath>

using namespace hatpic;
using namespace hatpic::bridge;
using hatpic::test::RosTestPeer;
using namespace Qt::StringLiterals;

class TestBridgeControl : public test::BridgeTest
{
    Q_OBJECT
public:
    TestBridgeControl() : BridgeTest(74) {}

private Q_SLOTS:
    // The device renders at most its tau_limit (0.44 N·m, from its HELLO): a limit above it is
    // refused, naming it, at start and while running.
    void aLimitAboveTheDevicesIsRefused()
    {
        BridgeSettings settings = m_bridge.settings();
        settings.feedback.limit = 10;
        QCOMPARE(m_bridge.start(settings),
                 u"limit: must be at most the device's tau_limit (0.44 N·m), got 10."_s);
        settings.feedback.limit = 0.44;
        QCOMPARE(m_bridge.start(settings), QString());
        FeedbackSettings f = settings.feedback;
        f.limit = 0.45;
        QCOMPARE(m_bridge.setFeedbackSettings(f),
                 u"limit: must be at most the device's tau_limit (0.44 N·m), got 0.45."_s);
        QCOMPARE(m_bridge.settings().feedback.limit, 0.44);
        settings.feedback = FeedbackSettings{};
        QCOMPARE(m_bridge.start(settings), QString());
    }

    void stopLeavesTauExtZero()
    {
        BridgeSettings settings = m_bridge.settings();
        QCOMPARE(m_bridge.start(settings), QString()); // start() ends a release
        QTRY_VERIFY_WITH_TIMEOUT(m_peer->wrenchMatched(), 5000);
        QTimer robot;
        connect(&robot, &QTimer::timeout, this, [&] { m_peer->publishWrench(0.5); });
        robot.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(m_deviceTauExt != 0.0, 5000);
        robot.stop();
        m_bridge.stop();
        QVERIFY(!m_bridge.isRunning());
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 300); // well before staleness would
    }

    // The dead man (ros.md § Enable switch): with an enable topic, nothing moves and no force
    // comes back until the first true; released (false, silence or the local switch), the
    // twist and τ_ext are zero and the pose holds; engaged again, the pose goes on from there.
    void enableSwitch()
    {
        BridgeSettings settings = m_bridge.settings();
        settings.topics.enable = "/teleop/enable";
        QCOMPARE(m_bridge.start(settings), QString());
        QTRY_VERIFY_WITH_TIMEOUT(m_peer->wrenchMatched(), 5000);
        bool enabled = false, talking = false;
        QTimer robot;
        connect(&robot, &QTimer::timeout, this, [&] {
            m_peer->publishWrench(0.5);
            if (talking)
                m_peer->publishEnable(enabled);
        });
        robot.start(20);
        const double tau = 0.5 * m_bridge.settings().feedback.gain;

        // No enable message yet: released.
        QTest::qWait(600);
        QVERIFY(!m_bridge.stats().engaged);
        QCOMPARE(m_deviceTauExt, 0.0);
        m_peer->take();
        m_peer->clear();
        QTest::qWait(200);
        m_peer->take();
        QVERIFY(!m_peer->twists.empty() && !m_peer->jogs.empty());
        QVERIFY(allTwistsZero());

        // Engaged by the first true.
        enabled = talking = true;
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - tau) < kTauExtTolerance, 3000);
        QVERIFY(m_bridge.stats().engaged);
        QTRY_VERIFY_WITH_TIMEOUT(lastTwist() > 0.1, 3000);

        // Released by false: τ_ext and the twist zero, the pose held.
        enabled = false;
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 1000);
        QTest::qWait(100);
        m_peer->take();
        m_peer->clear();
        QTest::qWait(300);
        m_peer->take();
        QVERIFY(allTwistsZero());
        QVERIFY(m_peer->poses.size() >= 10);
        const double held = m_peer->poses.back().position[0];
        for (const auto &p : m_peer->poses)
            QCOMPARE(p.position[0], held);

        // Engaged again: the pose goes on from where it held (one sample's step, not the
        // distance the device's p_ref went on meanwhile).
        enabled = true;
        QTRY_VERIFY_WITH_TIMEOUT(lastTwist() > 0.1, 3000);
        const auto first = std::find_if(m_peer->poses.begin(), m_peer->poses.end(),
                                        [&](const auto &p) { return p.position[0] != held; });
        QVERIFY(first != m_peer->poses.end());
        QVERIFY2(first->position[0] > held && first->position[0] - held < 0.01,
                 qPrintable(QStringLiteral("%1 after %2").arg(first->position[0]).arg(held)));
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - tau) < kTauExtTolerance, 3000);

        // The local switch (the tuner's) releases it too.
        m_bridge.setEngaged(false);
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 500);
        QCOMPARE(m_bridge.start(settings), QString()); // a reopening keeps it released
        QTRY_VERIFY_WITH_TIMEOUT(m_peer->wrenchMatched(), 5000);
        QTest::qWait(300);
        QCOMPARE(m_deviceTauExt, 0.0);
        QVERIFY(!m_bridge.stats().localEngaged);
        m_bridge.setEngaged(true);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - tau) < kTauExtTolerance, 3000);

        // The dead man falls silent: released after kEnableTimeout, though the wrench goes on.
        talking = false;
        QElapsedTimer silent;
        silent.start();
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 3000);
        QVERIFY2(silent.elapsed() >= 400, qPrintable(QString::number(silent.elapsed())));
        QVERIFY(!m_bridge.stats().engaged);
        QTest::qWait(100);
        m_peer->take();
        m_peer->clear();
        QTest::qWait(200);
        m_peer->take();
        QVERIFY(allTwistsZero());
        robot.stop();
        settings.topics.enable.clear();
        QCOMPARE(m_bridge.start(settings), QString());
    }

    // Two knobs side by side (a class, a lab): a second knob and bridge in the namespace knob2
    // on the same domain. Each peer sees only its own knob's references, and each robot's
    // wrench reaches only its own knob.
    void twoKnobsSideBySide()
    {
        double secondTauExt = 0; // outlives the client that writes it
        DeviceClient second;
        QVERIFY(connectKnob(second, -kHeldAngle, secondTauExt));
        BridgeSettings settings;
        settings.domainId = kDomain;
        settings.nodeNamespace = "knob2";
        Bridge bridge2(second);
        RosTestPeer peer2(kDomain, {}, "/knob2");
        QVERIFY(peer2.isValid());
        QCOMPARE(bridge2.start(settings), QString());
        QVERIFY(bridge2.where().contains(u"node /knob2/hatpic_bridge"));

        QTest::qWait(1500);
        m_peer->take();
        peer2.take();
        m_peer->clear();
        peer2.clear();
        QTest::qWait(500);
        m_peer->take();
        peer2.take();
        QVERIFY(m_peer->joints.size() >= 20 && peer2.joints.size() >= 20);
        for (const auto &j : m_peer->joints)
            QVERIFY(j.position[0] > 0.25);
        for (const auto &j : peer2.joints)
            QVERIFY(j.position[0] < -0.25);

        QTRY_VERIFY_WITH_TIMEOUT(peer2.wrenchMatched(), 5000);
        QTimer robot2;
        connect(&robot2, &QTimer::timeout, this, [&] { peer2.publishWrench(0.5); });
        robot2.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(secondTauExt - 0.077) < kTauExtTolerance, 5000);
        QTest::qWait(200);
        QCOMPARE(m_deviceTauExt, 0.0);
        robot2.stop();
        bridge2.stop();
        second.disconnectDevice();
    }

    // The operator's choice of axis (ros.md § Choosing the knob's axis), on a knob a hand
    // pushes and lets go again and again, under the namespace knob3: a choice made mid-push
    // waits for the dead zone; then the knob drives the new axis and feels its component, the
    // pose going on without a jump and the axis left keeping its pose. The same by number;
    // what names no axis is counted and shown, never acted on.
    void operatorChoosesTheAxis()
    {
        double tauExt = 0, theta = 0; // outlive the client that writes them
        DeviceClient knob;
        const HandInput hand = *HandInput::parse(u"pushes:0.1:1000:0.8:0.8"_s); // 0.8 s on, 0.8 off
        QVERIFY(connectKnob(knob, hand, tauExt, &theta));
        BridgeSettings settings;
        settings.domainId = kDomain;
        settings.nodeNamespace = "knob3";
        settings.topics.axis = "/teleop/axis";
        settings.topics.axisIndex = "/teleop/axis_index";
        Bridge bridge(knob);
        RosTestPeer peer(kDomain, {}, "/knob3");
        QVERIFY(peer.isValid());
        QCOMPARE(bridge.start(settings), QString());
        QTRY_VERIFY_WITH_TIMEOUT(peer.axisMatched() && peer.axisMatched(true), 5000);
        QTRY_VERIFY_WITH_TIMEOUT(peer.wrenchMatched(), 5000);
        // The robot pushes back along y only: not felt while the knob drives x (force.z).
        QTimer robot;
        connect(&robot, &QTimer::timeout, this, [&] {
            peer.publishWrench({0, 0.5, 0}, {0, 0, 0});
        });
        robot.start(10);
        const Component x{false, 0}, y{false, 1}, yaw{true, 2};

        // Mid-push: the choice waits.
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(theta) < 0.01, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(theta) > 0.05, 5000);
        peer.take();
        peer.clear();
        peer.publishAxis("linear.y");
        QTRY_VERIFY_WITH_TIMEOUT(bridge.stats().pendingAxis == y, 2000);
        QCOMPARE(bridge.stats().axis, x);
        QVERIFY2(std::abs(theta) > 0.03, qPrintable(QString::number(theta)));
        QCOMPARE(tauExt, 0.0);
        // Let go: in the dead zone it drives y, and feels force.y.
        QTRY_VERIFY_WITH_TIMEOUT(bridge.stats().axis == y, 3000);
        QVERIFY(!bridge.stats().pendingAxis);
        QCOMPARE(bridge.stats().feltComponent, y);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(tauExt - 0.5 * settings.feedback.gain) < kTauExtTolerance,
                                 2000);
        // A steady force holds the knob out of its dead zone (which has no spring): the robot
        // falls silent, and its wrench goes stale.
        robot.stop();
        QTRY_COMPARE_WITH_TIMEOUT(tauExt, 0.0, 2000);
        // The next push moves the pose along y; x keeps what the knob gave it.
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(lastTwistOf(peer, 1)) > 0.05, 4000);
        QTest::qWait(100);
        peer.take();
        QVERIFY(peer.poses.size() >= 50);
        const double heldX = peer.poses.back().position[0];
        QVERIFY2(std::abs(heldX) > 0.02, qPrintable(QString::number(heldX)));
        std::size_t afterSwitch = 0;
        for (std::size_t i = 1; i < peer.poses.size(); ++i) {
            const auto &a = peer.poses[i - 1].position, &b = peer.poses[i].position;
            QVERIFY2(std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]) < 0.02,
                     qPrintable(QStringLiteral("pose jumps at %1").arg(i)));
            if (b[1] != 0 && afterSwitch == 0)
                afterSwitch = i;
        }
        QVERIFY(afterSwitch > 0);
        for (std::size_t i = afterSwitch; i < peer.poses.size(); ++i)
            QCOMPARE(peer.poses[i].position[0], heldX);
        for (const auto &t : peer.twists)
            QVERIFY(t.a[0] == 0 || t.a[1] == 0); // never both: one axis at a time

        // By number: 5 is angular.z; the position holds, the orientation goes on from identity.
        peer.publishAxisIndex(5);
        QTRY_VERIFY_WITH_TIMEOUT(bridge.stats().axis == yaw, 4000);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(lastTwistOf(peer, 5)) > 0.05, 4000);
        QTest::qWait(300);
        peer.take();
        const auto &turned = peer.poses.back();
        QVERIFY(std::abs(turned.orientation[2]) > 0.001);
        QCOMPARE(turned.position[0], heldX);

        // What names no axis: counted, shown, the axis kept.
        peer.publishAxis("up");
        peer.publishAxisIndex(9);
        QTRY_COMPARE_WITH_TIMEOUT(bridge.stats().axisRejected, std::uint64_t(2), 2000);
        QCOMPARE(bridge.stats().lastAxisRejected, std::string("9"));
        QCOMPARE(bridge.stats().axis, yaw);
        QVERIFY(!bridge.stats().pendingAxis);
        bridge.stop();
        knob.disconnectDevice();
    }

private:
    static double lastTwistOf(RosTestPeer &peer, int slot)
    {
        peer.take();
        if (peer.twists.empty())
            return 0.0;
        const auto &t = peer.twists.back();
        return slot < 3 ? t.a[std::size_t(slot)] : t.b[std::size_t(slot - 3)];
    }
};

QTEST_GUILESS_MAIN(TestBridgeControl)
#include "tst_bridgecontrol.moc"
