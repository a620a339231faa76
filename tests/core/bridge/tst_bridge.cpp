// The bridge over real Cyclone DDS on loopback, against the in-process simulated joystick: a
// test node built as rmw_cyclonedds builds one (its own IDL types, no type information) sees
// the references of a knob held at a known angle under ROS 2's topic and type names with their
// type hashes, and its wrench, published as the published driver does (best effort, transient
// local), reaches the device as τ_ext; the robot side measured, the owner's thread frozen, gain
// changed while running, a release, a relay of the feedback. The limit, stop, the enable
// switch and two knobs: tst_bridgecontrol.
#include "bridgetest.h"
#include "rostestpeer.h"

#include "bridge/bridge.h"
#include "ros/node.h"
#include "session/deviceclient.h"

#include <QElapsedTimer>
#include <QTest>
#include <QTimer>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <future>
#include <limits>
#include <thread>

using namespace hatpic;
using namespace hatpic::bridge;
using hatpic::test::RosTestPeer;
using namespace Qt::StringLiterals;

class TestBridge : public test::BridgeTest
{
    Q_OBJECT
public:
    TestBridge() : BridgeTest(71) {}

private Q_SLOTS:
    void referencesOfAHeldKnob()
    {
        // Let the knob settle at the hand's angle, then listen for half a second.
        QTest::qWait(1500);
        m_peer->take();
        m_peer->clear();
        QTest::qWait(500);
        m_peer->take();
        QVERIFY2(m_peer->joints.size() >= 20 && m_peer->twists.size() >= 20 &&
                     m_peer->poses.size() >= 20,
                 qPrintable(QString::number(m_peer->joints.size())));
        QVERIFY(m_peer->imus.empty()); // a single knob has no tilt: the IMU topic stays silent
        const double received = wallNow();

        for (const auto &j : m_peer->joints) {
            QCOMPARE(j.frame, std::string("hatpic"));
            QCOMPARE(j.names, std::vector<std::string>{"hatpic_knob"});
            QCOMPARE(j.position.size(), 1u);
            QCOMPARE(j.velocity.size(), 1u);
            QCOMPARE(j.effort.size(), 1u);
            QVERIFY2(j.position[0] > 0.25 && j.position[0] < kHeldAngle + 0.05,
                     qPrintable(QString::number(j.position[0])));
            QVERIFY(std::abs(j.stamp.seconds() - received) < 1.0); // the wall clock
        }
        // v_ref = v_max/2 · θ (v_max 1, θ0 0) on linear.x, matched by stamp.
        int matched = 0;
        for (const auto &t : m_peer->twists) {
            const auto j = std::find_if(m_peer->joints.begin(), m_peer->joints.end(),
                                        [&](const auto &j) { return j.stamp == t.stamp; });
            if (j == m_peer->joints.end())
                continue;
            ++matched;
            QVERIFY(std::abs(t.a[0] - 0.5 * j->position[0]) < 1e-12);
            QCOMPARE(t.a[1], 0.0);
            QCOMPARE(t.a[2], 0.0);
            QCOMPARE(t.b, (std::array<double, 3>{0, 0, 0}));
        }
        QVERIFY(matched >= 20);
        // p_ref = ∫ v_ref dt on position.x: it grows at v_ref per second of stamp time.
        const auto &first = m_peer->poses.front();
        const auto &last = m_peer->poses.back();
        const double dt = last.stamp.seconds() - first.stamp.seconds();
        const double rate = (last.position[0] - first.position[0]) / dt;
        const double v = m_peer->twists.back().a[0];
        QVERIFY2(std::abs(rate - v) < 0.1 * v, qPrintable(QString::number(rate)));
        QCOMPARE(last.orientation, (std::array<double, 4>{0, 0, 0, 1}));

        // The same twist unstamped on /haptic_twist, and to a best-effort subscription.
        QVERIFY(m_peer->unstampedTwists.size() >= 20);
        QVERIFY(m_peer->bestEffortTwists.size() >= 20);
        for (const auto &u : m_peer->unstampedTwists) {
            QVERIFY(u.a[0] > 0.1 && u.a[0] < 0.3);
            QCOMPARE(u.b, (std::array<double, 3>{0, 0, 0}));
        }
        QVERIFY(std::any_of(m_peer->twists.begin(), m_peer->twists.end(), [&](const auto &t) {
            return t.a == m_peer->unstampedTwists.back().a;
        }));

        // MoveIt Servo's joint command: the twist's v_ref as the velocity of the joint named,
        // no displacement, no duration; received by a peer without type information.
        QVERIFY(m_peer->jogs.size() >= 20);
        int jogsMatched = 0;
        for (const auto &jog : m_peer->jogs) {
            QCOMPARE(jog.names, std::vector<std::string>{"hatpic_knob"});
            QVERIFY(jog.displacements.empty());
            QCOMPARE(jog.velocities.size(), 1u);
            QCOMPARE(jog.duration, 0.0);
            const auto t = std::find_if(m_peer->twists.begin(), m_peer->twists.end(),
                                        [&](const auto &t) { return t.stamp == jog.stamp; });
            if (t == m_peer->twists.end())
                continue;
            ++jogsMatched;
            QCOMPARE(jog.velocities[0], t->a[0]);
        }
        QVERIFY(jogsMatched >= 20);
    }

    // Every reader and writer under ROS 2's topic and type names, announcing its type hash in
    // USER_DATA as rmw_cyclonedds (Iron and later) does: the hashes ROS 2 publishes for these
    // types (`ros2 topic info -v`). The readers are best effort, to match any publisher.
    void endpointsAsRosSeesThem()
    {
        struct Expected
        {
            std::string topic, type, hash;
            bool reliable;
        };
        const std::string joint = "RIHS01_a13ee3a330e346c9d87b5aa18d24e11690752bd33a0350f11c5882b"
                                  "c9179260e";
        const std::string twistStamped = "RIHS01_5f0fcd4f81d5d06ad9b4c4c63e3ea51b82d6ae4d0558f1d47"
                                         "5229b1121db6f64";
        const std::string twist = "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcd"
                                  "dde6fb8d2a";
        const std::string pose = "RIHS01_10f3786d7d40fd2b54367835614bff85d4ad3b5dab62bf8bca0cc232"
                                 "d73b4cd8";
        const std::string wrenchStamped = "RIHS01_8dc3deaf06b2ab281f9f9a742a8961c328ca7cec16e3fd6"
                                          "586d3a5c83fa78f77";
        const std::string wrench = "RIHS01_018e8519d57c16adbe97c9fe1460ef21fec7e31bc541de3d653a35"
                                   "895677ce52";
        const std::string jog = "RIHS01_ba249455a20f70168a1acb7bf43b776b72ff1f7eb5fc4cfea443f749"
                                "e963c6e7";
        const std::string imu = "RIHS01_7d9a00ff131080897a5ec7e26e315954b8eae3353c3f995c55faf715"
                                "74000b5b";
        const Expected writers[] = {
            {"rt/servo_node/delta_joint_cmds", "control_msgs::msg::dds_::JointJog_", jog, true},
            {"rt/hatpic/joint_states", "sensor_msgs::msg::dds_::JointState_", joint, true},
            {"rt/hatpic/twist", "geometry_msgs::msg::dds_::TwistStamped_", twistStamped, true},
            {"rt/haptic_twist", "geometry_msgs::msg::dds_::Twist_", twist, true},
            {"rt/hatpic/pose", "geometry_msgs::msg::dds_::PoseStamped_", pose, true},
            {"rt/hatpic/feedback", "geometry_msgs::msg::dds_::WrenchStamped_", wrenchStamped, true},
            {"rt/hatpic/imu", "sensor_msgs::msg::dds_::Imu_", imu, true}};
        const Expected readers[] = {
            {"rt/wrench_estimation", "geometry_msgs::msg::dds_::WrenchStamped_", wrenchStamped,
             false},
            {"rt/robot/wrench", "geometry_msgs::msg::dds_::Wrench_", wrench, false}};
        const auto check = [](const std::vector<hatpic::test::EndpointSeen> &seen,
                              const Expected &e) {
            const hatpic::test::EndpointSeen wanted{e.topic, e.type, "typehash=" + e.hash + ";",
                                                    e.reliable};
            return std::find(seen.begin(), seen.end(), wanted) != seen.end();
        };
        for (const Expected &e : writers)
            QTRY_VERIFY2_WITH_TIMEOUT(check(m_peer->publications(), e), e.topic.c_str(), 5000);
        for (const Expected &e : readers)
            QTRY_VERIFY2_WITH_TIMEOUT(check(m_peer->subscriptions(), e), e.topic.c_str(), 5000);
    }

    void wrenchBecomesTauExt()
    {
        QTRY_VERIFY_WITH_TIMEOUT(m_peer->wrenchMatched(), 5000);
        // A robot publishing at 50 Hz as the published driver does: best effort, transient
        // local, keep last 1.
        double force = 0.5;
        QTimer robot;
        connect(&robot, &QTimer::timeout, this, [&] { m_peer->publishWrench(force); });
        robot.start(20);

        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - 0.077) < kTauExtTolerance, 5000);
        QCOMPARE(m_bridge.stats().tauExt, 0.077);
        QTRY_VERIFY_WITH_TIMEOUT(feedbackSeen(0.077), 3000);

        force = std::numeric_limits<double>::quiet_NaN();
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 3000);
        QVERIFY(m_bridge.stats().wrenches.nonFinite > 0);
        QTRY_VERIFY_WITH_TIMEOUT(feedbackSeen(0.0), 3000);

        force = 1e12;
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - 0.154) < kTauExtTolerance, 3000);
        QVERIFY(m_bridge.stats().wrenches.limited > 0);
        force = -1e12;
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt + 0.154) < kTauExtTolerance, 3000);

        // The robot falls silent: after 0.5 s the wrench is stale and τ_ext goes to 0.
        robot.stop();
        QElapsedTimer silent;
        silent.start();
        const quint64 staleBefore = m_bridge.stats().wrenches.stale;
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 3000);
        QVERIFY2(silent.elapsed() >= 450, qPrintable(QString::number(silent.elapsed())));
        QCOMPARE(m_bridge.stats().wrenches.stale, staleBefore + 1);
    }

    // What the Bridge panel shows of the robot side, measured over the real loop: the stamp's
    // one-way delay, the device's echo of a new τ_ext, losses estimated from the gaps, and the
    // energy τ_ext puts into the knob.
    void robotSideMeasured()
    {
        QTRY_VERIFY_WITH_TIMEOUT(m_peer->wrenchMatched(), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 3000);
        QTest::qWait(300); // the knob at rest in the hand
        const BridgeStats before = m_bridge.stats();
        const double thetaBefore = m_deviceTheta;
        QVERIFY(before.passivity.samples > 0);

        // A robot whose stamps are 0.3 s old when they arrive (a clock behind, or a slow
        // network), at 50 Hz, one message in four lost on the way.
        const double force = 0.5;
        const double tau = force * m_bridge.settings().feedback.gain;
        int sent = 0, skipped = 0;
        QTimer robot;
        robot.setTimerType(Qt::PreciseTimer);
        connect(&robot, &QTimer::timeout, this, [&] {
            if (++sent % 4 == 0)
                ++skipped;
            else
                m_peer->publishWrench(force, 0, wallNow() - 0.3);
        });
        robot.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - tau) < kTauExtTolerance, 5000);
        QTest::qWait(1500);
        robot.stop();
        const BridgeStats after = m_bridge.stats();
        const double thetaAfter = m_deviceTheta;

        const Spread &stamp = after.timing.stampDelay;
        QVERIFY(stamp.count > before.timing.stampDelay.count + 20);
        QVERIFY2(stamp.median >= 0.3 && stamp.median < 0.4,
                 qPrintable(QString::number(stamp.median)));
        QVERIFY(stamp.p95 >= stamp.median);
        // The device showed the new τ_ext (once: the force did not change) within its cycle,
        // the session's queue and a telemetry frame: well under 100 ms in process.
        QCOMPARE(after.timing.echoDelay.count, before.timing.echoDelay.count + 1);
        QVERIFY2(after.timing.echoDelay.median > 0 && after.timing.echoDelay.median < 0.1,
                 qPrintable(QString::number(after.timing.echoDelay.median)));
        QVERIFY(after.timing.age >= 0 && after.timing.age < 0.5);
        QVERIFY2(std::abs(after.timing.interval - 0.02) < 0.005,
                 qPrintable(QString::number(after.timing.interval)));
        const auto lost = after.timing.lost - before.timing.lost;
        QVERIFY2(lost * 2 >= std::uint64_t(skipped) && lost <= 2 * std::uint64_t(skipped),
                 qPrintable(QStringLiteral("%1 lost of %2").arg(lost).arg(skipped)));

        // τ_ext pushed the knob the way it went: the energy it gave is τ_ext · Δθ (> 0). In
        // contact, but one push that then holds is a contact's approach, excused: no warning
        // (docs/teleop.md; a loop that goes on generating is warned of in tst_teleoploop).
        const double delta = after.passivity.energy - before.passivity.energy;
        const double expected = tau * (thetaAfter - thetaBefore);
        QVERIFY2(expected > 1e-3 && std::abs(delta - expected) < 0.2 * expected,
                 qPrintable(QStringLiteral("%1 J, expected %2 J").arg(delta).arg(expected)));
        QVERIFY(after.passivity.inContact);
        QVERIFY(!after.passivity.warning);
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 3000);
    }

    void theRobotPathNeverWaitsForTheOwnersThread()
    {
        // The Bridge's owner (this thread: the GUI's in the tuner) freezes for 400 ms while the
        // robot sends a wrench. Samples still go out, stamped as they came, and the wrench
        // still reaches the device: neither waits for the frozen thread.
        QTRY_VERIFY_WITH_TIMEOUT(m_peer->wrenchMatched(), 5000);
        FeedbackSettings f = m_bridge.settings().feedback;
        f.staleAfter = 2; // one wrench, held through the freeze
        m_bridge.setFeedbackSettings(f);
        QTest::qWait(200);
        m_peer->take();
        m_peer->clear();
        const double frozenAt = wallNow();
        m_peer->publishWrench(0.25);
        std::this_thread::sleep_for(std::chrono::milliseconds(400));
        const double thawedAt = wallNow();
        m_peer->take();
        const auto during = [&](const auto &messages) {
            return std::count_if(messages.begin(), messages.end(), [&](const auto &m) {
                return m.stamp.seconds() > frozenAt && m.stamp.seconds() < thawedAt;
            });
        };
        // 100 messages per second on each topic: about 40 of them in the freeze.
        QVERIFY2(during(m_peer->joints) >= 30, qPrintable(QString::number(during(m_peer->joints))));
        QVERIFY2(during(m_peer->feedbacks) >= 30,
                 qPrintable(QString::number(during(m_peer->feedbacks))));
        // The device rendered the wrench's τ_ext before the owner's thread ran again.
        const double tau = 0.25 * f.gain;
        QVERIFY(std::any_of(m_peer->feedbacks.begin(), m_peer->feedbacks.end(), [&](const auto &m) {
            return std::abs(m.b[2] - tau) < kTauExtTolerance && m.stamp.seconds() < thawedAt;
        }));
        f.staleAfter = 0.5;
        m_bridge.setFeedbackSettings(f);
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 3000);
    }

    void unstampedWrenchIsAcceptedToo()
    {
        QTRY_VERIFY_WITH_TIMEOUT(m_peer->wrenchMatched(true), 5000);
        QTimer robot;
        connect(&robot, &QTimer::timeout, this, [&] { m_peer->publishUnstampedWrench(-0.25); });
        robot.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt + 0.0385) < kTauExtTolerance, 5000);
    }

    void gainAndLimitChangeWhileRunning()
    {
        QTimer robot;
        connect(&robot, &QTimer::timeout, this, [&] { m_peer->publishWrench(1.0); });
        robot.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - 0.154) < kTauExtTolerance, 5000);
        FeedbackSettings f = m_bridge.settings().feedback;
        f.gain = 0.05;
        m_bridge.setFeedbackSettings(f);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - 0.05) < kTauExtTolerance, 3000);
    }

    void releaseHoldsZeroWhileTheWrenchKeepsComing()
    {
        QTimer robot;
        connect(&robot, &QTimer::timeout, this, [&] { m_peer->publishWrench(0.5); });
        robot.start(20);
        const double tau = 0.5 * m_bridge.settings().feedback.gain;
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - tau) < kTauExtTolerance, 5000);
        m_bridge.releaseFeedback();
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 300);
        QTRY_VERIFY_WITH_TIMEOUT(feedbackSeen(0.0), 1000); // still publishing
        // Past several staleness checks and wrenches, it stays at 0.
        QTest::qWait(3 * Bridge::kCheckIntervalMs + 100);
        QCOMPARE(m_deviceTauExt, 0.0);
        QCOMPARE(m_bridge.stats().tauExt, 0.0);
        QVERIFY(m_bridge.isRunning());
    }

    // A relay of the feedback topic onto the wrench topic, in this process: Cyclone DDS hands
    // the relay the feedback inside the bridge's publish(), and the relay's wrench to the
    // bridge's handler on the same thread. The bridge must neither hang (it published holding
    // the lock its handler takes) nor keep its own τ_ext alive through the relay: the echo is
    // ignored, so once the robot's seed stops τ_ext goes to 0 with the staleness watchdog.
    void aRelayOfTheFeedbackNeitherHangsNorLatches()
    {
        BridgeSettings settings = m_bridge.settings();
        settings.feedback.component = Component{true, 2}; // torque.z: what the feedback carries
        settings.feedback.gain = 1;
        QCOMPARE(m_bridge.start(settings), QString());
        std::string error;
        auto relayNode = ros::Node::open({ros::RosVersion::Ros2, "relay", kDomain}, &error);
        QVERIFY2(relayNode, error.c_str());
        auto relayOut = relayNode->advertise("/wrench_estimation", ros::MessageType::WrenchStamped,
                                             ros::Qos::defaults(), &error);
        QVERIFY2(relayOut, error.c_str());
        std::atomic<int> relayed{0};
        auto relayIn = relayNode->subscribe(
            "/hatpic/feedback", ros::MessageType::WrenchStamped, ros::Qos::matchAny(),
            [&](const ros::Message &m) {
                relayOut->publish(m);
                ++relayed;
            },
            &error);
        QVERIFY2(relayIn, error.c_str());
        QTRY_VERIFY_WITH_TIMEOUT(m_peer->wrenchMatched(), 5000);
        // The robot's seed: 0.5 s of torque.z 0.1 N·m.
        QTimer robot;
        connect(&robot, &QTimer::timeout, this, [&] { m_peer->publishWrench(0, 0.1); });
        robot.start(20);
        QTest::qWait(500);
        robot.stop();
        // stats() takes the bridge's lock: a bridge that hangs never answers.
        const auto answers = [this](BridgeStats *out) {
            auto f = std::async(std::launch::async, [this] { return m_bridge.stats(); });
            if (f.wait_for(std::chrono::seconds(3)) != std::future_status::ready)
                qFatal("the bridge hangs: its own feedback came back inside its publish()");
            *out = f.get();
        };
        BridgeStats stats;
        answers(&stats);
        QVERIFY(relayed > 0);
        QElapsedTimer silent;
        silent.start();
        QTRY_VERIFY_WITH_TIMEOUT((answers(&stats), stats.tauExt == 0.0), 3000);
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 1000);
        // It stays there, while the relay keeps relaying the 0s.
        QTest::qWait(1000);
        answers(&stats);
        QCOMPARE(stats.tauExt, 0.0);
        QVERIFY2(stats.echoes > 0, qPrintable(QString::number(stats.echoes)));
        relayIn.reset();
        relayOut.reset();
        relayNode.reset();
        settings.feedback = FeedbackSettings{};
        QCOMPARE(m_bridge.start(settings), QString());
    }
};

QTEST_GUILESS_MAIN(TestBridge)
#include "tst_bridge.moc"
