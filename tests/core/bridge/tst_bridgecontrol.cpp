// The bridge over real Cyclone DDS on loopback, against the in-process simulated joystick and a
// test node built as rmw_cyclonedds builds one: a limit above the device's refused, stop leaving
// τ_ext at zero, the enable switch (the dead man: released, engaged, the local switch,
// silence), and two knobs side by side in one domain, each bridge under its own namespace.
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
};

QTEST_GUILESS_MAIN(TestBridgeControl)
#include "tst_bridgecontrol.moc"
