// RecordingTrigger: fires once on a crossing in the edge's direction, never on the first
// sample or a NaN, and not at all for plans that do not start on a threshold; plans sanitized.
#include "telemetry/recordingtrigger.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace hatpic;

namespace {

Sample at(double t, double theta, double tau = 0)
{
    Sample s;
    s.t_s = t;
    s.theta = theta;
    s.tau = tau;
    return s;
}

RecordingPlan threshold(RecordingPlan::Quantity q, RecordingPlan::Edge e, double level)
{
    RecordingPlan p;
    p.start = RecordingPlan::Start::Threshold;
    p.quantity = q;
    p.edge = e;
    p.level = level;
    return p;
}

//! Index of the sample that fires, −1 when none does.
int firingIndex(RecordingTrigger &trigger, const QList<Sample> &samples)
{
    int fired = -1;
    for (int i = 0; i < samples.size(); ++i) {
        if (trigger.feed(samples[i])) {
            if (fired >= 0)
                return -2; // fired twice
            fired = i;
        }
    }
    return fired;
}

} // namespace

class TestRecordingTrigger : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void crossings_data();
    void crossings();
    void tauThreshold();
    void skipsNaN();
    void resetArmsAgain();
    void otherPlansNeverFire();
    void sanitizes();
    void eventText();
};

void TestRecordingTrigger::crossings_data()
{
    QTest::addColumn<int>("edge");
    QTest::addColumn<QList<double>>("thetas");
    QTest::addColumn<int>("expected");
    using E = RecordingPlan::Edge;
    QTest::newRow("rising fires on the first at the level")
        << int(E::Rising) << QList<double>{0.0, 0.1, 0.2, 0.3} << 2;
    QTest::newRow("rising ignores falling") << int(E::Rising) << QList<double>{0.5, 0.3, 0.1} << -1;
    QTest::newRow("already above does not fire")
        << int(E::Rising) << QList<double>{0.3, 0.4, 0.5} << -1;
    QTest::newRow("rising after dipping below")
        << int(E::Rising) << QList<double>{0.3, 0.1, 0.25} << 2;
    QTest::newRow("falling fires below") << int(E::Falling) << QList<double>{0.5, 0.3, 0.1} << 2;
    QTest::newRow("falling ignores rising") << int(E::Falling) << QList<double>{0.0, 0.3} << -1;
    QTest::newRow("fires once on oscillation")
        << int(E::Rising) << QList<double>{0.0, 0.3, 0.0, 0.3, 0.0, 0.3} << 1;
}

void TestRecordingTrigger::crossings()
{
    QFETCH(int, edge);
    QFETCH(QList<double>, thetas);
    QFETCH(int, expected);
    RecordingTrigger trigger(
        threshold(RecordingPlan::Quantity::Theta, static_cast<RecordingPlan::Edge>(edge), 0.2));
    QList<Sample> samples;
    for (int i = 0; i < thetas.size(); ++i)
        samples.append(at(i * 1e-3, thetas[i]));
    QCOMPARE(firingIndex(trigger, samples), expected);
    QCOMPARE(trigger.fired(), expected >= 0);
}

void TestRecordingTrigger::tauThreshold()
{
    RecordingTrigger trigger(
        threshold(RecordingPlan::Quantity::Tau, RecordingPlan::Edge::Falling, -0.05));
    // θ crossing does nothing; τ falling through −0.05 fires.
    QCOMPARE(firingIndex(trigger, {at(0, -1, 0), at(1, 1, -0.01), at(2, 5, -0.06)}), 2);
}

void TestRecordingTrigger::skipsNaN()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    RecordingTrigger trigger(
        threshold(RecordingPlan::Quantity::Tau, RecordingPlan::Edge::Rising, 0.1));
    // Legacy samples carry no τ: the NaNs neither fire nor set the side.
    QCOMPARE(firingIndex(trigger, {at(0, 0, nan), at(1, 0, 0.2), at(2, 0, nan), at(3, 0, 0.0),
                                   at(4, 0, nan), at(5, 0, 0.3)}),
             5);
}

void TestRecordingTrigger::resetArmsAgain()
{
    RecordingTrigger trigger(
        threshold(RecordingPlan::Quantity::Theta, RecordingPlan::Edge::Rising, 0));
    QCOMPARE(firingIndex(trigger, {at(0, -1), at(1, 1)}), 1);
    QVERIFY(!trigger.feed(at(2, -1)));
    QVERIFY(!trigger.feed(at(3, 1)));
    trigger.reset();
    QVERIFY(!trigger.fired());
    QVERIFY(!trigger.feed(at(4, 1))); // the first sample after a reset only sets the side
    QVERIFY(!trigger.feed(at(5, -1)));
    QVERIFY(trigger.feed(at(6, 1)));
}

void TestRecordingTrigger::otherPlansNeverFire()
{
    for (RecordingPlan::Start start : {RecordingPlan::Start::Now, RecordingPlan::Start::NextPush}) {
        RecordingPlan plan =
            threshold(RecordingPlan::Quantity::Theta, RecordingPlan::Edge::Rising, 0);
        plan.start = start;
        RecordingTrigger trigger(plan);
        QCOMPARE(firingIndex(trigger, {at(0, -1), at(1, 1), at(2, -1), at(3, 1)}), -1);
    }
}

void TestRecordingTrigger::sanitizes()
{
    RecordingPlan plan;
    plan.level = std::numeric_limits<double>::infinity();
    plan.preTrigger_s = 1e9;
    plan.duration_s = -3;
    const RecordingPlan p = plan.sanitized();
    QCOMPARE(p.level, 0.0);
    QCOMPARE(p.preTrigger_s, RecordingPlan::kMaxPreTrigger_s);
    QCOMPARE(p.duration_s, 0.0);
    plan.preTrigger_s = std::numeric_limits<double>::quiet_NaN();
    QCOMPARE(plan.sanitized().preTrigger_s, 0.0);
    // The trigger works on the sanitized plan.
    QCOMPARE(RecordingTrigger(plan).plan().preTrigger_s, 0.0);
}

void TestRecordingTrigger::eventText()
{
    QCOMPARE(triggerEventText(RecordingPlan{}), QStringLiteral("trigger: start"));
    RecordingPlan push;
    push.start = RecordingPlan::Start::NextPush;
    QCOMPARE(triggerEventText(push), QStringLiteral("trigger: push"));
    QCOMPARE(triggerEventText(
                 threshold(RecordingPlan::Quantity::Tau, RecordingPlan::Edge::Falling, -0.5)),
             QStringLiteral("trigger: tau falling through -0.5"));
    QCOMPARE(triggerEventText(
                 threshold(RecordingPlan::Quantity::Theta, RecordingPlan::Edge::Rising, 0.2)),
             QStringLiteral("trigger: theta rising through 0.2"));
}

QTEST_GUILESS_MAIN(TestRecordingTrigger)
#include "tst_recordingtrigger.moc"
