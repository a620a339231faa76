// The operator's choice of axis (ros.md § Choosing the knob's axis), without middleware: a
// request waits for the dead zone, the references go on without a jump (each axis keeps the
// pose it was left with), and the messages carry knob 1's pose on every axis it drove.
#include "bridge/axisselector.h"
#include "bridge/referencemessages.h"
#include "bridge/rosendpoints.h"

#include <QTest>

#include <cmath>

using namespace hatpic;
using namespace hatpic::bridge;

namespace {

const Component kLinearX{false, 0}, kLinearY{false, 1}, kAngularZ{true, 2};

bool near(const SlotPose &a, const SlotPose &b)
{
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::abs(a[i] - b[i]) > 1e-12)
            return false;
    }
    return true;
}

} // namespace

class TestAxisSelector : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void drivesTheDefaultUntilAChoice()
    {
        AxisSelector s(kLinearX);
        QCOMPARE(s.axis(), kLinearX);
        QVERIFY(!s.chosen());
        QCOMPARE(s.pose(0.3), (SlotPose{0.3, 0, 0, 0, 0, 0}));
        s.setDefault(kAngularZ); // the reference mode's: at once, as before
        QCOMPARE(s.axis(), kAngularZ);
        QCOMPARE(s.pose(0.3), (SlotPose{0, 0, 0, 0, 0, 0.3}));
    }

    void aRequestWaitsForTheDeadZone()
    {
        AxisSelector s(kLinearX);
        s.request(kLinearY);
        QCOMPARE(s.pending(), std::optional(kLinearY));
        for (int i = 0; i < 100; ++i)
            QVERIFY(!s.update(0.01 * i, false)); // pushed: never switches
        QCOMPARE(s.axis(), kLinearX);
        QVERIFY(!s.chosen());
        QVERIFY(s.update(1.0, true));
        QCOMPARE(s.axis(), kLinearY);
        QVERIFY(s.chosen());
        QVERIFY(!s.pending());
        QCOMPARE(s.switches(), std::uint64_t(1));
        QVERIFY(!s.update(1.0, true)); // nothing pending
    }

    // The pose never jumps: the axis left keeps what the knob gave it, the one taken goes on
    // from what it held, also on coming back to an axis.
    void thePoseGoesOnWithoutAJump()
    {
        AxisSelector s(kLinearX);
        QCOMPARE(s.pose(0.4)[0], 0.4);
        s.request(kLinearY);
        QVERIFY(s.update(0.4, true));
        QCOMPARE(s.pose(0.4), (SlotPose{0.4, 0, 0, 0, 0, 0}));
        QVERIFY(near(s.pose(0.7), {0.4, 0.3, 0, 0, 0, 0}));
        s.request(kLinearX);
        QVERIFY(s.update(0.7, true));
        QVERIFY(near(s.pose(0.7), {0.4, 0.3, 0, 0, 0, 0}));
        QVERIFY(near(s.pose(0.5), {0.2, 0.3, 0, 0, 0, 0})); // back down x
    }

    void askingForTheDrivenAxisCancelsAPendingOne()
    {
        AxisSelector s(kLinearX);
        s.request(kLinearX); // before any choice: a choice too, that waits
        QCOMPARE(s.pending(), std::optional(kLinearX));
        QVERIFY(s.update(0, true));
        QVERIFY(s.chosen());
        s.request(kLinearY);
        s.request(kLinearX);
        QVERIFY(!s.pending());
        QVERIFY(!s.update(0, true));
        s.setDefault(kAngularZ); // once chosen, the operator's axis stays
        QCOMPARE(s.axis(), kLinearX);
    }

    // The messages: knob 1's twist on the axis driven only; its pose on every axis it holds,
    // rotations composed x, y, z, so that a switch changes no message but the twist's place.
    void messagesCarryEveryAxisHeld()
    {
        AxisSelector s(kLinearX);
        Knobs knobs{};
        knobs[0].p_ref = 0.4;
        knobs[0].v_ref = 0;
        const BridgeSettings settings;
        const auto at = [&](double pRef, double vRef) {
            knobs[0].p_ref = pRef;
            knobs[0].v_ref = vRef;
            const SlotPose pose = s.pose(pRef);
            return referenceMessages(knobs, 1, 1e9, settings, knobComponents(settings, s.axis()),
                                     NAN, NAN, &pose);
        };
        const ReferenceMessages before = at(0.4, 0);
        s.request(kAngularZ);
        QVERIFY(s.update(0.4, true));
        const ReferenceMessages after = at(0.4, 0);
        QCOMPARE(after.posePosition, before.posePosition);
        QCOMPARE(after.poseOrientation, before.poseOrientation);
        const ReferenceMessages turned = at(0.4 + 0.5, 0.2);
        QCOMPARE(turned.posePosition[0], 0.4);
        QCOMPARE(turned.twist, (std::array<double, 6>{0, 0, 0, 0, 0, 0.2}));
        QVERIFY(std::abs(turned.poseOrientation[2] - std::sin(0.25)) < 1e-15);
        QVERIFY(std::abs(turned.poseOrientation[3] - std::cos(0.25)) < 1e-15);
        // Without a selector's pose, knob 1's p_ref on its axis alone, as ever.
        const ReferenceMessages plain = referenceMessages(
            knobs, 1, 1e9, settings, knobComponents(settings, kLinearX), NAN, NAN, nullptr);
        QCOMPARE(plain.posePosition[0], 0.9);
    }

    // What the axis topics carry becomes a request, or a refusal that says what came.
    void axisTopicsMessages()
    {
        QCOMPARE(RosEndpoints::axisRequest(ros::String{" angular.z\n"}).axis,
                 std::optional(kAngularZ));
        QCOMPARE(RosEndpoints::axisRequest(ros::String{"force.y"}).axis, std::optional(kLinearY));
        const auto bad = RosEndpoints::axisRequest(ros::String{"up"});
        QVERIFY(!bad.axis);
        QCOMPARE(bad.text, std::string("up"));
        QVERIFY(RosEndpoints::axisRequest(ros::String{std::string(100000, 'x')}).text.size() < 200);
        QCOMPARE(RosEndpoints::axisRequest(ros::UInt8{1}).axis, std::optional(kLinearY));
        QCOMPARE(RosEndpoints::axisRequest(ros::UInt8{5}).axis, std::optional(kAngularZ));
        const auto six = RosEndpoints::axisRequest(ros::UInt8{6});
        QVERIFY(!six.axis);
        QCOMPARE(six.text, std::string("6"));
    }
};

QTEST_GUILESS_MAIN(TestAxisSelector)
#include "tst_axisselector.moc"
