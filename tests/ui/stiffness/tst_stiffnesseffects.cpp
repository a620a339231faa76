// StiffnessView with haptic effects (effects.md): the torque curve is the static torque
// τ_rec + τ_det + τ_wall at hand-computed angles, fine detents are resolved, the rest positions
// and the walls are marked where they are, the device's and the other A/B slot's effects are
// drawn with their parameters, the default effects leave the view exactly as without them, and
// the names say what is drawn.
#include "model/staticcurve.h"
#include "plots/palette.h"
#include "plots/qcp.h"
#include "stiffness/staticcurves.h"
#include "stiffness/stiffnessview.h"
#include "stiffnesscurves.h"
#include "tuning/tuningmodel.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

void editEffects(TuningModel &tuning, const EffectParams &effects)
{
    Tuning t = tuning.edited();
    t.effects = effects;
    tuning.setEdited(t);
}

//! The curve's point whose key is closest to `theta`.
QPointF nearest(const QCPGraph *graph, double theta)
{
    QPointF best(std::nan(""), std::nan(""));
    for (const QPointF &p : points(graph)) {
        if (!(std::abs(p.x() - theta) >= std::abs(best.x() - theta)))
            best = p;
    }
    return best;
}

//! Detents A = 0.04 N·m every 0.2 rad over ±0.45 rad; walls at −0.6 and +0.5 rad, K_w = 2.
EffectParams knob()
{
    // wall_damping: static, no ω, so no damping in the curve.
    return {.detent_strength = 0.04,
            .detent_spacing = 0.2,
            .detent_range = 0.45,
            .wall_min = -0.6,
            .wall_max = 0.5,
            .wall_stiffness = 2.0,
            .wall_damping = 0.3};
}

} // namespace

class TestStiffnessEffects : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void curveIsTheStaticTorque();
    void fineDetentsAreResolved();
    void restPositionsAndWallsAreMarked();
    void deviceEffectsAreDrawnWithTheDevice();
    void comparisonCarriesTheOtherSlotsEffects();
    void defaultEffectsChangeNothing();
    void namesSayWhatIsDrawn();
};

void TestStiffnessEffects::curveIsTheStaticTorque()
{
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, linear(0.5));
    editEffects(tuning, knob());
    const QCPGraph *g = view.torqueGraph();
    // Shown to 1.25 × the farther wall: ±0.75 rad.
    QVERIFY(std::abs(g->keyAxis()->range().upper - 0.75) < 1e-12);
    // θ = 0.05 (a quarter period, on the detent grid): −0.5·0.05 − 0.04 = −0.065 N·m.
    QPointF p = nearest(g, 0.05);
    QVERIFY(std::abs(p.x() - 0.05) < 1e-15);
    QVERIFY(std::abs(p.y() - (-0.065)) < 1e-12);
    // θ = −0.15 (three quarters back, sin(−1.5π) = 1): +0.075 − 0.04 = 0.035 N·m.
    p = nearest(g, -0.15);
    QVERIFY(std::abs(p.x() + 0.15) < 1e-15);
    QVERIFY(std::abs(p.y() - 0.035) < 1e-12);
    // θ ≈ 0.6, beyond the detents, 0.1 beyond wall_max: −0.5·θ − 2·(θ − 0.5), no damping.
    p = nearest(g, 0.6);
    QVERIFY(std::abs(p.x() - 0.6) < 0.002);
    QVERIFY(std::abs(p.y() - (-0.5 * p.x() - 2 * (p.x() - 0.5))) < 1e-12);
    // θ ≈ −0.7, 0.1 beyond wall_min: −0.5·θ − 2·(θ + 0.6).
    p = nearest(g, -0.7);
    QVERIFY(std::abs(p.x() + 0.7) < 0.002);
    QVERIFY(std::abs(p.y() - (-0.5 * p.x() - 2 * (p.x() + 0.6))) < 1e-12);
    // The wall's spring grows beyond what the device renders: the axis stops at 1.5·tau_limit.
    Tuning limited = tuning.edited();
    limited.host.tau_limit = 0.2; // the edited host setting's, which the view follows
    tuning.setEdited(limited);
    QVERIFY(std::abs(g->valueAxis()->range().upper - 0.3) < 1e-12);
    // Every sample: the model's sum; the stiffness plot stays K_rec.
    const auto k = points(view.stiffnessGraph());
    const auto tau = points(g);
    QCOMPARE(k.size(), tau.size());
    for (int i = 0; i < tau.size(); ++i) {
        QVERIFY(tau[i].y() == staticTorque(linear(0.5), knob(), tau[i].x()));
        QVERIFY(k[i].y() == recenteringStiffness(linear(0.5), k[i].x()));
    }
}

void TestStiffnessEffects::fineDetentsAreResolved()
{
    // s = 0.01 rad (the spec's finest): 601 samples over ±π/2 would be ~2 per period.
    const EffectParams fx{.detent_strength = 0.02, .detent_spacing = 0.01, .detent_range = 1.0};
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, linear(0.0));
    editEffects(tuning, fx);
    const auto tau = points(view.torqueGraph());
    double lo = 0;
    double hi = 0;
    int inPeriod = 0;
    for (const QPointF &p : tau) {
        lo = std::min(lo, p.y());
        hi = std::max(hi, p.y());
        inPeriod += p.x() >= 0.5 - 1e-12 && p.x() < 0.51 - 1e-12;
    }
    // Every crest reached, enough samples per period, and a bounded curve.
    QVERIFY(std::abs(hi - 0.02) < 1e-12 && std::abs(lo + 0.02) < 1e-12);
    QVERIFY2(inPeriod >= kSamplesPerDetent, qPrintable(QString::number(inPeriod)));
    QVERIFY(tau.size() <= StiffnessView::kUniformSamples + kMaxDetentSamples + 32);
}

void TestStiffnessEffects::restPositionsAndWallsAreMarked()
{
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, linear(0.5, 0.05));
    editEffects(tuning, knob());
    const EffectMarks &marks = view.editedMarks();
    // Rest positions θ0 + i·0.2 within ±0.45: i = −2 … 2, on the curve (τ_det = 0 there).
    const auto rest = points(marks.restPositions());
    QCOMPARE(rest.size(), 5);
    QVERIFY(marks.restPositions()->visible());
    for (int i = 0; i < 5; ++i) {
        const double theta = 0.05 + (i - 2) * 0.2;
        QVERIFY(std::abs(rest[i].x() - theta) < 1e-12);
        QVERIFY(std::abs(rest[i].y() - (-0.5 * (theta - 0.05))) < 1e-12);
    }
    // Walls at θ0 − 0.6 and θ0 + 0.5, across both plots, solid, in τ_fx's colour.
    const QVector<double> walls = marks.wallKeys();
    QCOMPARE(walls.size(), 2);
    QVERIFY(std::abs(walls[0] - (0.05 - 0.6)) < 1e-12);
    QVERIFY(std::abs(walls[1] - (0.05 + 0.5)) < 1e-12);
    for (QCPItemStraightLine *line : marks.wallLines()) {
        QVERIFY(line->visible());
        QCOMPARE(line->pen().style(), Qt::SolidLine);
        QCOMPARE(line->pen().color(), palette::channel(Channel::TauFx));
    }
    // In degrees the marks move with the axis.
    view.setAngleInDegrees(true);
    QVERIFY(std::abs(marks.wallKeys()[1] - 0.55 * 180 / std::numbers::pi) < 1e-9);
    QVERIFY(std::abs(points(marks.restPositions())[2].x() - 0.05 * 180 / std::numbers::pi) < 1e-9);
    view.setAngleInDegrees(false);
    // Walls off (K_w = 0): no lines; detents off (R = 0): no markers.
    EffectParams off = knob();
    off.wall_stiffness = 0;
    off.detent_range = 0;
    editEffects(tuning, off);
    QVERIFY(marks.wallKeys().isEmpty());
    QVERIFY(!marks.restPositions()->visible());
    // A wall outside the view (at the end of travel, π) is not drawn.
    EffectParams far = knob();
    far.wall_max = std::numbers::pi;
    editEffects(tuning, far);
    QCOMPARE(marks.wallKeys().size(), 1);
}

void TestStiffnessEffects::deviceEffectsAreDrawnWithTheDevice()
{
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, linear(0.5));
    EffectParams device = knob();
    device.wall_max = 0.3;
    // Effects without device parameters draw nothing.
    view.setDeviceTuning({std::nullopt, device});
    QVERIFY(view.deviceMarks().wallKeys().isEmpty());
    QVERIFY(!view.deviceTorqueGraph()->visible());
    view.setDeviceTuning({linear(0.4, 0.1), device});
    const auto tau = points(view.deviceTorqueGraph());
    QVERIFY(!tau.isEmpty());
    for (const QPointF &p : tau)
        QVERIFY(p.y() == staticTorque(linear(0.4, 0.1), device, p.x()));
    // θ0 = 0.1 + wall_max 0.3: 0.4; the device's marks are dashed and hollow.
    const QVector<double> walls = view.deviceMarks().wallKeys();
    QCOMPARE(walls.size(), 2);
    QVERIFY(std::abs(walls[1] - 0.4) < 1e-12);
    QCOMPARE(view.deviceMarks().wallLines()[1]->pen().style(), Qt::DashLine);
    QCOMPARE(view.deviceMarks().restPositions()->scatterStyle().shape(), QCPScatterStyle::ssCircle);
    QCOMPARE(points(view.deviceMarks().restPositions()).size(), 5);
    // A device without the effects capability: its curve is τ_rec alone, no marks.
    view.setDeviceTuning({linear(0.4, 0.1), std::nullopt});
    for (const QPointF &p : points(view.deviceTorqueGraph()))
        QVERIFY(p.y() == recenteringTorque(linear(0.4, 0.1), p.x()));
    QVERIFY(view.deviceMarks().wallKeys().isEmpty());
    QVERIFY(!view.deviceMarks().restPositions()->visible());
    // The edited marks are untouched by the device's.
    QVERIFY(view.editedMarks().wallKeys().isEmpty());
}

void TestStiffnessEffects::comparisonCarriesTheOtherSlotsEffects()
{
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, linear(0.5));
    view.setComparison(linear(0.3), 0, knob());
    const QCPGraph *other = view.slotTorqueGraph(1);
    QVERIFY(other && other->visible());
    for (const QPointF &p : points(other))
        QVERIFY(p.y() == staticTorque(linear(0.3), knob(), p.x()));
    // The edited slot keeps its own (default) effects: τ_rec alone.
    for (const QPointF &p : points(view.slotTorqueGraph(0)))
        QVERIFY(p.y() == recenteringTorque(linear(0.5), p.x()));
    // Without the argument, the other slot's effects are the defaults.
    view.setComparison(linear(0.3), 0);
    for (const QPointF &p : points(view.slotTorqueGraph(1)))
        QVERIFY(p.y() == recenteringTorque(linear(0.3), p.x()));
}

void TestStiffnessEffects::defaultEffectsChangeNothing()
{
    const DeviceParams p = params(0.1, 1.5, 0.12, 0.04, 0.0);
    DeviceParams device = p;
    device.K_max = 1.0;
    TuningModel plainTuning;
    StiffnessView plain(plainTuning);
    editParams(plainTuning, p);
    plain.setDeviceTuning({device, std::nullopt});
    TuningModel defaultsTuning;
    StiffnessView withDefaults(defaultsTuning);
    editParams(defaultsTuning, p);
    editEffects(defaultsTuning, EffectParams{});
    withDefaults.setDeviceTuning({device, EffectParams{}});
    QCOMPARE(points(withDefaults.torqueGraph()), points(plain.torqueGraph()));
    QCOMPARE(points(withDefaults.stiffnessGraph()), points(plain.stiffnessGraph()));
    QCOMPARE(points(withDefaults.deviceTorqueGraph()), points(plain.deviceTorqueGraph()));
    QCOMPARE(withDefaults.torqueGraph()->keyAxis()->range(),
             plain.torqueGraph()->keyAxis()->range());
    QCOMPARE(withDefaults.torqueGraph()->valueAxis()->range(),
             plain.torqueGraph()->valueAxis()->range());
    QCOMPARE(title(withDefaults.torqueGraph()), u"τ_rec [N·m]"_s);
    QVERIFY(!withDefaults.editedMarks().restPositions()->visible());
    QVERIFY(withDefaults.editedMarks().wallKeys().isEmpty());
    QVERIFY(withDefaults.deviceMarks().wallKeys().isEmpty());
    QCOMPARE(withDefaults.operatingPointGraph()->name(), plain.operatingPointGraph()->name());
    const QImage a = plain.plot()->toPixmap(500, 400).toImage();
    const QImage b = withDefaults.plot()->toPixmap(500, 400).toImage();
    QCOMPARE(a, b);
}

void TestStiffnessEffects::namesSayWhatIsDrawn()
{
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, linear(0.5));
    QCOMPARE(title(view.torqueGraph()), u"τ_rec [N·m]"_s);
    QVERIFY(!view.operatingPointGraph()->name().contains(u"τ_fx"_s));
    editEffects(tuning, knob());
    QCOMPARE(title(view.torqueGraph()), u"static τ [N·m]"_s);
    QVERIFY(view.operatingPointGraph()->name().contains(u"τ_rec + τ_fx"_s));
    view.setReplaying(true);
    QVERIFY(view.operatingPointGraph()->name().contains(u"playhead"_s));
    QVERIFY(view.operatingPointGraph()->name().contains(u"τ_fx"_s));
    // The rest positions have a legend entry while they are drawn.
    bool inLegend = false;
    for (QCPLayoutElement *e : view.plot()->plotLayout()->elements(true)) {
        if (auto *legend = qobject_cast<QCPLegend *>(e))
            inLegend = inLegend || legend->hasItemWithPlottable(view.editedMarks().restPositions());
    }
    QVERIFY(inLegend);
    editEffects(tuning, EffectParams{});
    QCOMPARE(title(view.torqueGraph()), u"τ_rec [N·m]"_s);
    inLegend = false;
    for (QCPLayoutElement *e : view.plot()->plotLayout()->elements(true)) {
        if (auto *legend = qobject_cast<QCPLegend *>(e))
            inLegend = inLegend || legend->hasItemWithPlottable(view.editedMarks().restPositions());
    }
    QVERIFY(!inLegend);
}

QTEST_MAIN(TestStiffnessEffects)
#include "tst_stiffnesseffects.moc"
