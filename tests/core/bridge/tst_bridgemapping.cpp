// The bridge's DDS-independent parts: wrench → τ_ext (gain, limit, stale, non-finite), the
// outgoing messages' content, sample times, the rate limiter, the settings' rules and the
// publishers' QoS they give.
#include "bridge/enablegate.h"
#include "bridge/referencemessages.h"
#include "bridge/rosendpoints.h"
#include "profile/bridgesettings.h"
#include "teleop/ratelimiter.h"
#include "teleop/wrenchfeedback.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <numbers>

using namespace hatpic;
using namespace hatpic::bridge;
using namespace Qt::StringLiterals;

class TestBridgeMapping : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void defaultsReproduceThePublishedDriver()
    {
        // force.z × 350 load units, clamped to ±350; ±1000 load units = tau_limit (0.44 N·m).
        const FeedbackSettings f;
        QCOMPARE(f.component, (Component{false, 2}));
        QCOMPARE(f.gain, 350.0 / 1000.0 * 0.44);
        QCOMPARE(f.limit, 350.0 / 1000.0 * 0.44);
        QCOMPARE(f.staleAfter, 0.5);
    }

    void wrenchMapsThroughGainAndLimit_data()
    {
        QTest::addColumn<double>("value");
        QTest::addColumn<double>("tau");
        QTest::addColumn<bool>("limited");
        QTest::newRow("zero") << 0.0 << 0.0 << false;
        QTest::newRow("half a newton") << 0.5 << 0.077 << false;
        QTest::newRow("minus half") << -0.5 << -0.077 << false;
        QTest::newRow("exactly one newton") << 1.0 << 0.154 << false;
        QTest::newRow("huge") << 1e9 << 0.154 << true;
        QTest::newRow("huge negative") << -1e9 << -0.154 << true;
        QTest::newRow("largest double") << std::numeric_limits<double>::max() << 0.154 << true;
    }
    void wrenchMapsThroughGainAndLimit()
    {
        QFETCH(double, value);
        QFETCH(double, tau);
        QFETCH(bool, limited);
        WrenchFeedback w;
        QVERIFY(std::abs(w.receive(value, 1.0) - tau) < 1e-15);
        QVERIFY(std::abs(w.torqueAt(1.2) - tau) < 1e-15);
        QCOMPARE(w.counters().received, 1u);
        QCOMPARE(w.counters().limited, limited ? 1u : 0u);
        QCOMPARE(w.counters().nonFinite, 0u);
    }

    void nonFiniteGivesZeroAndIsCounted()
    {
        WrenchFeedback w;
        QCOMPARE(w.receive(0.5, 0.0), 0.077);
        for (const double bad :
             {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
              -std::numeric_limits<double>::infinity()}) {
            QCOMPARE(w.receive(bad, 0.1), 0.0);
            QCOMPARE(w.torqueAt(0.1), 0.0);
        }
        QCOMPARE(w.counters().nonFinite, 3u);
        QCOMPARE(w.counters().received, 4u);
        QCOMPARE(w.receive(-0.5, 0.2), -0.077); // a good one afterwards is used again
    }

    void staleAfterHalfASecond()
    {
        WrenchFeedback w;
        QCOMPARE(w.torqueAt(0.0), 0.0); // none yet: 0, not counted as stale
        QCOMPARE(w.counters().stale, 0u);
        w.receive(1.0, 10.0);
        QCOMPARE(w.torqueAt(10.5), 0.154); // exactly 0.5 s old: still fresh
        QCOMPARE(w.torqueAt(10.5001), 0.0);
        QCOMPARE(w.torqueAt(11.0), 0.0);
        QCOMPARE(w.counters().stale, 1u); // counted once per wrench that went stale
        QVERIFY(w.isStale());
        w.receive(1.0, 12.0);
        QCOMPARE(w.torqueAt(12.1), 0.154);
        QCOMPARE(w.torqueAt(13.0), 0.0);
        QCOMPARE(w.counters().stale, 2u);
    }

    void settingsChangeTakesEffectAtOnce()
    {
        WrenchFeedback w;
        w.receive(1.0, 0.0);
        FeedbackSettings f;
        f.gain = -0.1;
        f.limit = 0.05;
        w.setSettings(f);
        QCOMPARE(w.torqueAt(0.1), -0.05);
        f.limit = 0.2;
        w.setSettings(f);
        QCOMPARE(w.torqueAt(0.1), -0.1);
    }

    void messagesCarryTheSample()
    {
        Sample s;
        s.theta = 0.4;
        s.omega = -0.25;
        s.tau = 0.03;
        s.tau_ext = 0.077;
        s.v_ref = 0.2;
        s.p_ref = 1.5;
        BridgeSettings settings;
        settings.poseOrigin = {0, 0, 0.5};
        const ReferenceMessages m = referenceMessages(s, 1700000000.25, settings,
                                                      settings.axisFor(ReferenceMode::Translation));
        QCOMPARE(m.stamp, (ros::Time{1700000000, 250000000}));
        QCOMPARE(m.joints, 1);
        QCOMPARE(m.position[0], 0.4);
        QCOMPARE(m.velocity[0], -0.25);
        QCOMPARE(m.effort[0], 0.03);
        QCOMPARE(m.jointJogVelocity[0], 0.2);
        QCOMPARE(m.twist, (std::array<double, 6>{0.2, 0, 0, 0, 0, 0}));
        QCOMPARE(m.posePosition, (std::array<double, 3>{1.5, 0, 0.5}));
        QCOMPARE(m.poseOrientation, (std::array<double, 4>{0, 0, 0, 1}));
        QCOMPARE(m.feedbackTorque, 0.077);

        // Rotation: ω_ref on angular.z, yaw_ref as a rotation about z.
        const ReferenceMessages r =
            referenceMessages(s, 0, settings, settings.axisFor(ReferenceMode::Rotation));
        QCOMPARE(r.twist, (std::array<double, 6>{0, 0, 0, 0, 0, 0.2}));
        QCOMPARE(r.posePosition, (std::array<double, 3>{0, 0, 0.5}));
        QCOMPARE(r.poseOrientation[2], std::sin(0.75));
        QCOMPARE(r.poseOrientation[3], std::cos(0.75));

        settings.referenceAxis = Component{false, 2};
        QCOMPARE(settings.axisFor(ReferenceMode::Rotation), (Component{false, 2}));
        const ReferenceMessages z = referenceMessages(s, 0, settings, *settings.referenceAxis);
        QCOMPARE(z.twist[2], 0.2);
        QCOMPARE(z.posePosition[2], 2.0);
    }

    void aBoardsKnobsGoOnTheirOwnAxes()
    {
        // Four knobs: knob 1 on linear.x, 2 … 4 on the default linear.y, linear.z, angular.z.
        BoardSample board;
        board.axes = 4;
        for (std::size_t k = 0; k < 3; ++k) {
            board.more[k].theta = 0.1 * double(k + 2);
            board.more[k].v_ref = 0.01 * double(k + 2);
            board.more[k].p_ref = 0.5 * double(k + 2);
        }
        Sample s;
        s.theta = 0.1;
        s.v_ref = 0.01;
        s.p_ref = 0.5;
        s.board = std::make_shared<const BoardSample>(board);
        BridgeSettings settings;
        const ReferenceMessages m =
            referenceMessages(s, 0, settings, settings.axisFor(ReferenceMode::Translation));
        QCOMPARE(m.joints, 4);
        QCOMPARE(m.position, (std::array<double, 4>{0.1, 0.2, 0.30000000000000004, 0.4}));
        QCOMPARE(m.jointJogVelocity[3], 0.04);
        QCOMPARE(m.twist, (std::array<double, 6>{0.01, 0.02, 0.03, 0, 0, 0.04}));
        QCOMPARE(m.posePosition, (std::array<double, 3>{0.5, 1.0, 1.5}));
        QCOMPARE(m.poseOrientation[2], std::sin(1.0));
        QCOMPARE(m.poseOrientation[3], std::cos(1.0));

        // Rotation mode puts knob 1 on angular.z too: knob 4's axis is taken, its references
        // go nowhere (its joint still does).
        const ReferenceMessages r =
            referenceMessages(s, 0, settings, settings.axisFor(ReferenceMode::Rotation));
        QCOMPARE(r.twist, (std::array<double, 6>{0, 0.02, 0.03, 0, 0, 0.01}));
        QCOMPARE(r.poseOrientation[2], std::sin(0.25));
        QCOMPARE(r.position[3], 0.4);

        // Two angular axes: knob 1's roll, then knob 2's pitch about the frame's own y axis.
        settings.knobAxes = "angular.y,linear.z,force.y";
        const ReferenceMessages q = referenceMessages(s, 0, settings, Component{true, 0});
        const double c1 = std::cos(0.25), s1 = std::sin(0.25), c2 = std::cos(0.5),
                     s2 = std::sin(0.5);
        // q2 ⊗ q1 with q1 = (s1, 0, 0, c1), q2 = (0, s2, 0, c2).
        QVERIFY(std::abs(q.poseOrientation[0] - c2 * s1) < 1e-15);
        QVERIFY(std::abs(q.poseOrientation[1] - s2 * c1) < 1e-15);
        QVERIFY(std::abs(q.poseOrientation[2] + s2 * s1) < 1e-15);
        QVERIFY(std::abs(q.poseOrientation[3] - c2 * c1) < 1e-15);
        QCOMPARE(q.twist, (std::array<double, 6>{0, 0.04, 0.03, 0.01, 0.02, 0}));
    }

    void knobAxesAndJointNamesAreChecked()
    {
        QCOMPARE(parseKnobAxes("linear.y,linear.z,angular.z"),
                 (std::array<Component, 3>{Component{false, 1}, Component{false, 2},
                                           Component{true, 2}}));
        QCOMPARE(parseKnobAxes("force.y,torque.x,linear.x")->at(1), (Component{true, 0}));
        QVERIFY(!parseKnobAxes("linear.y,linear.z"));
        QVERIFY(!parseKnobAxes("linear.y,linear.z,angular.z,angular.x"));
        QVERIFY(!parseKnobAxes("linear.y,force.y,angular.z")); // the same component twice
        QVERIFY(!parseKnobAxes("linear.y,,angular.z"));
        QVERIFY(!parseKnobAxes("linear.y, linear.z,angular.z"));

        QCOMPARE(jointNames("hatpic_knob"),
                 (std::vector<std::string>{"hatpic_knob", "hatpic_knob_2", "hatpic_knob_3",
                                           "hatpic_knob_4"}));
        QCOMPARE(jointNames("x,y", 3), (std::vector<std::string>{"x", "y", "x_3"}));
        QCOMPARE(jointNames("a,b,c,d,e", 4), (std::vector<std::string>{"a", "b", "c", "d"}));
        QVERIFY(jointNames("a,,b").empty());
        QVERIFY(jointNames("a,a").empty());
        QVERIFY(jointNames("a,a_3").empty()); // knob 3 would be a_3 as well

        BridgeSettings s;
        s.knobAxes = "linear.y,linear.y,angular.z";
        s.jointName = "a,a";
        const auto errors = validate(s);
        QCOMPARE(errors.size(), 2u);
        QCOMPARE(errors[0], "joint name: must be names separated by ',', none empty and no two "
                            "alike, got 'a,a'");
        QCOMPARE(errors[1], "knob axes: must be three different components (linear.x … "
                            "angular.z) separated by ',', got 'linear.y,linear.y,angular.z'");
    }

    void sampleWallClock() { QCOMPARE(sampleWallSeconds(100.0, 5.0, 4.98), 100.0 - (5.0 - 4.98)); }

    void rateLimiterKeepsTheRateBySampleTime()
    {
        RateLimiter limiter(100);
        int due = 0;
        for (int i = 0; i < 1000; ++i) // one second at 1 kHz
            due += limiter.due(i * 1e-3) ? 1 : 0;
        QCOMPARE(due, 100);
        // Slower samples than the rate: every one goes out.
        RateLimiter slow(100);
        due = 0;
        for (int i = 0; i < 50; ++i)
            due += slow.due(i * 0.02) ? 1 : 0;
        QCOMPARE(due, 50);
        // A clock that starts over (reconnect) does not stall the output.
        QVERIFY(limiter.due(0.0));
    }

    void settingsRules()
    {
        QVERIFY(validate(BridgeSettings()).empty());
        BridgeSettings s;
        s.publishRateHz = 0;
        s.feedback.gain = std::numeric_limits<double>::quiet_NaN();
        s.feedback.limit = -1;
        s.feedback.staleAfter = 0;
        s.depth = 0;
        s.domainId = 233;
        s.rosVersion = 3;
        s.topics.twist = "/hatpic//twist";
        s.topics.twistUnstamped = "/haptic twist";
        const auto errors = validate(s);
        // In the settings' order (kSettings): the network's first.
        QCOMPARE(errors.size(), 9u);
        QCOMPARE(errors.front(), std::string("ROS version: must be 1 or 2, got 3"));
        QCOMPARE(errors[1],
                 std::string("domain id: must be a whole number from 0 to 232, got 233"));
        QCOMPARE(errors[2], std::string("twist topic: '/hatpic//twist' is not a ROS topic "
                                        "name (letters, digits and '_' between single '/', "
                                        "not starting with a digit)"));
        QCOMPARE(errors[3], std::string("unstamped twist topic: '/haptic twist' is not a ROS "
                                        "topic name (letters, digits and '_' between single "
                                        "'/', not starting with a digit)"));
        QCOMPARE(errors[4],
                 std::string("publish rate: must be above 0 and at most 1000 Hz, got 0"));
        s.rosVersion = 1;
        QCOMPARE(validate(s).size(), 8u);
    }

    // The ROS version and the domain travel together as the network's, apart from the feel.
    // Each topic its own name (one rule, in validate(): the CLI, the config file, a profile
    // and the Bridge panel): an input that is an output is a loop; two others clash in type.
    void topicsHaveNamesOfTheirOwn()
    {
        BridgeSettings s;
        s.topics.wrench = "/hatpic/feedback";
        auto errors = validate(s);
        QCOMPARE(errors.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(errors.front()),
                 u"wrench topic: '/hatpic/feedback' is also the feedback topic; an input that is "
                 u"one of the bridge's own outputs would feed its messages back to it (a topic "
                 u"loop)"_s);
        s = BridgeSettings{};
        s.topics.feedback = "/wrench_estimation";
        QCOMPARE(validate(s).size(), std::size_t(1));
        s = BridgeSettings{};
        s.topics.wrenchUnstamped = "/hatpic/twist";
        QCOMPARE(validate(s).size(), std::size_t(1));
        s = BridgeSettings{};
        s.topics.pose = "/hatpic/twist";
        errors = validate(s);
        QCOMPARE(errors.size(), std::size_t(1));
        QVERIFY2(errors.front().find("two of the bridge's topics of different types") !=
                     std::string::npos,
                 errors.front().c_str());
        s = BridgeSettings{};
        s.topics.wrenchUnstamped = "/wrench_estimation";
        QCOMPARE(validate(s).size(), std::size_t(1));
        s = BridgeSettings{};
        s.topics.twist.clear();
        s.topics.pose.clear(); // empty names are no topics
        QVERIFY(validate(s).empty());
    }

    // One check of the limit against a tau_limit (a profile's host, the device's HELLO).
    void limitWithinTheDevicesTauLimit()
    {
        FeedbackSettings f;
        f.limit = 10;
        QCOMPARE(QString::fromStdString(limitProblem(f, 0.44)),
                 u"limit: must be at most the device's tau_limit (0.44 N·m), got 10"_s);
        f.limit = 0.44;
        QVERIFY(limitProblem(f, 0.44).empty());
        f.limit = 10;
        QVERIFY(limitProblem(f, std::nan("")).empty()); // not known yet
    }

    void networkSettings()
    {
        BridgeSettings feel;
        feel.feedback.gain = 0.3;
        feel.domainId = 5;
        BridgeSettings network;
        network.rosVersion = 1;
        network.domainId = 42;
        const BridgeSettings both = withNetworkOf(feel, network);
        QCOMPARE(both.feedback.gain, 0.3);
        QCOMPARE(both.rosVersion, 1);
        QCOMPARE(both.domainId, 42);
    }

    void topicNames()
    {
        QVERIFY(isValidTopicName("/hatpic/twist"));
        QVERIFY(isValidTopicName("wrench_estimation"));
        QVERIFY(!isValidTopicName("/"));
        QVERIFY(!isValidTopicName("/a/"));
        QVERIFY(!isValidTopicName("/1a"));
        QVERIFY(!isValidTopicName("/a b"));
        QVERIFY(BridgeSettings().topics.twistUnstamped.empty()); // off unless named
    }

    // --qos and --depth set the publishers; the subscriptions always take any publisher.
    void writerQosFromTheSettings()
    {
        BridgeSettings s;
        QCOMPARE(RosEndpoints::writerQos(s), ros::Qos::defaults());
        s.qos = QosProfile::BestEffort;
        s.depth = 3;
        QCOMPARE(RosEndpoints::writerQos(s),
                 (ros::Qos{ros::Qos::Reliability::BestEffort, ros::Qos::Durability::Volatile, 3}));
    }

    void componentsAndProfiles()
    {
        QCOMPARE(Component::parse("force.z"), (Component{false, 2}));
        QCOMPARE(Component::parse("linear.z"), (Component{false, 2}));
        QCOMPARE(Component::parse("torque.x"), (Component{true, 0}));
        QCOMPARE(Component::parse("angular.y")->twistName(), std::string("angular.y"));
        QVERIFY(!Component::parse("force.w"));
        QCOMPARE(parseQosProfile("best-effort"), QosProfile::BestEffort);
        QVERIFY(!parseQosProfile("sometimes"));
    }

    // --namespace: a topic at its default, or relative, goes under the namespace; any other
    // absolute name stays as given; no namespace changes nothing.
    void topicsUnderANamespace()
    {
        const Topics defaults;
        QCOMPARE(topicInNamespace(defaults.jointStates, defaults.jointStates, "knob1"),
                 std::string("/knob1/hatpic/joint_states"));
        QCOMPARE(topicInNamespace(defaults.wrench, defaults.wrench, "/lab/knob2"),
                 std::string("/lab/knob2/wrench_estimation"));
        QCOMPARE(topicInNamespace("/robot/twist", defaults.twist, "knob1"),
                 std::string("/robot/twist"));
        QCOMPARE(topicInNamespace("cmd", defaults.twist, "knob1"), std::string("/knob1/cmd"));
        QCOMPARE(topicInNamespace(defaults.pose, defaults.pose, ""), defaults.pose);
        QCOMPARE(topicInNamespace("", "", "knob1"), std::string());
        QVERIFY(isValidNamespace("knob1") && isValidNamespace("/lab/knob_2") &&
                isValidNamespace(""));
        QVERIFY(!isValidNamespace("1knob") && !isValidNamespace("a//b") &&
                !isValidNamespace("a b") && !isValidNamespace("ns/"));
        BridgeSettings s;
        s.nodeNamespace = "a b";
        const auto errors = validate(s);
        QCOMPARE(errors.size(), 1u);
        QVERIFY(errors.front().starts_with("namespace: 'a b' is not a ROS namespace"));
    }

    // The dead man: without a topic only the local switch counts; with one, released until the
    // first true and again when it falls silent; the published reference holds while released
    // and goes on from there without a jump.
    void enableGate()
    {
        EnableGate none;
        QVERIFY(none.engaged(0));
        none.setLocal(false);
        QVERIFY(!none.engaged(0));

        EnableGate gate(true, 0.5);
        QVERIFY(!gate.engaged(0));
        gate.received(true, 1.0);
        QVERIFY(gate.engaged(1.2));
        QVERIFY(gate.engaged(1.5));
        QVERIFY(!gate.engaged(1.51)); // silent for longer than the timeout
        gate.received(false, 2.0);
        QVERIFY(!gate.engaged(2.1));
        gate.received(true, 2.2);
        gate.setLocal(false);
        QVERIFY(!gate.engaged(2.3));

        // The reference: engaged 0 → 1, released while the device's p_ref goes to 3, engaged
        // again: it goes on from 1 and follows the device's motion from there.
        EnableGate ref;
        QCOMPARE(ref.reference(0.0, true), 0.0);
        QCOMPARE(ref.reference(1.0, true), 1.0);
        QCOMPARE(ref.reference(2.0, false), 1.0);
        QCOMPARE(ref.reference(3.0, false), 1.0);
        QCOMPARE(ref.reference(3.0, true), 1.0);
        QCOMPARE(ref.reference(3.5, true), 1.5);
        QCOMPARE(ref.offset(), 2.0);
        // Released from the start: held where the device's reference was.
        EnableGate late(true);
        QCOMPARE(late.reference(0.4, false), 0.4);
        QCOMPARE(late.reference(0.9, false), 0.4);
        QCOMPARE(late.reference(1.0, true), 0.4);

        // Each knob holds and re-anchors its own reference.
        EnableGate board;
        QCOMPARE(board.reference(1.0, true, 0), 1.0);
        QCOMPARE(board.reference(-2.0, true, 3), -2.0);
        QCOMPARE(board.reference(1.5, false, 0), 1.0);
        QCOMPARE(board.reference(-1.0, false, 3), -2.0);
        QCOMPARE(board.reference(1.5, true, 0), 1.0);
        QCOMPARE(board.reference(-1.0, true, 3), -2.0);
        QCOMPARE(board.offset(0), 0.5);
        QCOMPARE(board.offset(3), 1.0);
        QCOMPARE(board.offset(1), 0.0);
    }

    // A board's other knobs: each component through knob 1's gain and limit, all 0 when stale.
    void otherKnobsShareTheMapping()
    {
        WrenchFeedback w;
        QCOMPARE(w.receive(0.5, 1.0, {-0.5, 1e9, std::numeric_limits<double>::quiet_NaN()}),
                 0.5 * 0.154);
        const AxisTorques t = w.torquesAt(1.1);
        QCOMPARE(t[0], 0.5 * 0.154);
        QCOMPARE(t[1], -0.5 * 0.154);
        QCOMPARE(t[2], 0.154);
        QCOMPARE(t[3], 0.0);
        QCOMPARE(w.counters().limited, 0u); // only knob 1's value is counted
        QCOMPARE(w.torquesAt(1.6), AxisTorques{});
        QCOMPARE(w.counters().stale, 1u);
    }
};

QTEST_GUILESS_MAIN(TestBridgeMapping)
#include "tst_bridgemapping.moc"
