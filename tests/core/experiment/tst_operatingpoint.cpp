// Tests for the operating point's caveats (docs/experiments.md § The operating point): the ideal
// model's own run has none; the knob held in a detent far out, a response of a few counts, the
// effects' torque and a sine that hardly moves the knob each get theirs; effects that act in
// the notch band are named before a run.
#include "experiment/idealresponse.h"
#include "experiment/operatingpoint.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

ExperimentResult idealRun(ExperimentKind kind, const DeviceParams &p)
{
    const ExperimentPlan plan = ExperimentPlan::defaults(kind, p);
    return analyseExperiment(plan, idealResponse(plan, p, 0.44, 1000), ClockMap(0), p, 0.44);
}

bool anyContains(const QStringList &list, const QString &text)
{
    return std::any_of(list.begin(), list.end(),
                       [&](const QString &s) { return s.contains(text); });
}

} // namespace

class TestOperatingPoint : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void theModelsOwnRunHasNoCaveat();
    void aKnobHeldInADetent();
    void effectsTorqueDuringTheRun();
    void sinesThatHardlyMoveTheKnob();
    void effectsInTheBandAreNamedBeforeARun();
};

void TestOperatingPoint::theModelsOwnRunHasNoCaveat()
{
    const DeviceParams p;
    for (ExperimentKind kind :
         {ExperimentKind::Step, ExperimentKind::Frequency, ExperimentKind::Spectrum}) {
        const ExperimentResult r = idealRun(kind, p);
        QVERIFY2(operatingPointCaveats(r).isEmpty(),
                 qPrintable(operatingPointCaveats(r).join(u'\n')));
    }
}

// Issue 27: on the Detents preset the knob sat in a detent at 0.78 rad and the step moved it 2
// encoder counts; ω_n 61.6 "against 114" was reported as a result.
void TestOperatingPoint::aKnobHeldInADetent()
{
    ExperimentResult r = idealRun(ExperimentKind::Step, DeviceParams{});
    for (Sample &s : r.samples)
        s.theta += 0.75;
    r.stepMeasured.initial = 0.780;
    r.stepMeasured.final = 0.780 + 2 * encoderCount();
    const QStringList caveats = operatingPointCaveats(r);
    QCOMPARE(caveats.size(), 2);
    QVERIFY2(caveats[0].contains(u"θ − θ0 = 0.780 rad before the step"_s), qPrintable(caveats[0]));
    QVERIFY(caveats[0].contains(u"outside the notch band (0.02–0.1 rad)"_s));
    QVERIFY2(caveats[1].contains(u"moved the knob 2 encoder counts (3.1 mrad)"_s),
             qPrintable(caveats[1]));
    // Four counts are still too few, five are enough.
    r.stepMeasured.initial = 0.04;
    r.stepMeasured.final = 0.04 + 4 * encoderCount();
    QVERIFY(anyContains(operatingPointCaveats(r), u"4 encoder counts"_s));
    r.stepMeasured.final = 0.04 + 5.01 * encoderCount();
    QVERIFY(operatingPointCaveats(r).isEmpty());
}

void TestOperatingPoint::effectsTorqueDuringTheRun()
{
    ExperimentResult r = idealRun(ExperimentKind::Step, DeviceParams{});
    QVERIFY(operatingPointCaveats(r).isEmpty());
    r.samples[r.samples.size() / 2].tau_fx = 0.04; // a detent's pull, against a 0.016 N·m step
    QVERIFY(anyContains(operatingPointCaveats(r), u"pushed with up to 0.040 N·m"_s));
    // A device that does not report τ_fx (NaN): unknown, no caveat.
    r.samples[r.samples.size() / 2].tau_fx = std::nan("");
    QVERIFY(operatingPointCaveats(r).isEmpty());
}

void TestOperatingPoint::sinesThatHardlyMoveTheKnob()
{
    DeviceParams p;
    ExperimentPlan plan = ExperimentPlan::defaults(ExperimentKind::Frequency, p);
    plan.amplitude = 0.002; // ±5 mrad at low frequency: a swing of under 7 counts
    ExperimentResult r =
        analyseExperiment(plan, idealResponse(plan, p, 0.44, 1000), ClockMap(0), p, 0.44);
    QVERIFY(operatingPointCaveats(r).isEmpty());
    plan.amplitude = 0.0008; // a swing of 4 mrad: under 3 counts
    r = analyseExperiment(plan, idealResponse(plan, p, 0.44, 1000), ClockMap(0), p, 0.44);
    QVERIFY2(anyContains(operatingPointCaveats(r), u"The slowest sine moved the knob"_s),
             qPrintable(operatingPointCaveats(r).join(u'\n')));
    // The bias out of the band: the knob swings around 0.2 rad.
    plan = ExperimentPlan::defaults(ExperimentKind::Frequency, p);
    plan.offset = 0.4 * 0.3; // K_min·… beyond N
    r = analyseExperiment(plan, idealResponse(plan, p, 0.44, 1000), ClockMap(0), p, 0.44);
    QVERIFY2(anyContains(operatingPointCaveats(r), u"on average, outside the notch band"_s),
             qPrintable(operatingPointCaveats(r).join(u'\n')));
}

void TestOperatingPoint::effectsInTheBandAreNamedBeforeARun()
{
    DeviceTuning tuning{DeviceParams{}, EffectParams{}};
    QVERIFY(operatingPointWarnings(ExperimentKind::Step, tuning).isEmpty());
    tuning.effects->detent_strength = 0.04;
    tuning.effects->detent_range = 0.9;
    QVERIFY(operatingPointWarnings(ExperimentKind::Step, tuning)
                .first()
                .startsWith(u"Detents are on (0.04 N·m every 0.2 rad)"_s));
    QVERIFY(operatingPointWarnings(ExperimentKind::Spectrum, tuning).isEmpty());
    tuning.effects = EffectParams{};
    tuning.effects->wall_stiffness = 5;
    tuning.effects->wall_max = 0.05; // inside N = 0.1
    QVERIFY(anyContains(operatingPointWarnings(ExperimentKind::Frequency, tuning),
                        u"An end stop lies inside the notch band"_s));
}

QTEST_GUILESS_MAIN(TestOperatingPoint)
#include "tst_operatingpoint.moc"
