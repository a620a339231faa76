// StiffnessView: the plotted curves are the model's, the breakpoints are exact, the device's
// curve is dashed, and the live operating point moves. With haptic effects (effects.md): the
// torque curve is the static torque τ_rec + τ_det + τ_wall at hand-computed angles, fine detents
// are resolved, the rest positions and the walls are marked where they are, the device's and
// the other A/B slot's effects are drawn with their parameters, and the default effects leave
// the view exactly as without them.
#include "model/staticcurve.h"
#include "model/stiffness.h"
#include "plots/axistitle.h"
#include "plots/palette.h"
#include "plots/qcp.h"
#include "stiffness/staticcurves.h"
#include "stiffness/stiffnessview.h"
#include "tuning/tuningmodel.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace Qt::StringLiterals;

Q_DECLARE_METATYPE(hatpic::DeviceParams)

namespace {

// Edits as the parameter editor does: the view follows the model.
void editParams(TuningModel &tuning, const DeviceParams &params)
{
    Tuning t = tuning.edited();
    t.device = params;
    tuning.setEdited(t);
}

void editEffects(TuningModel &tuning, const EffectParams &effects)
{
    Tuning t = tuning.edited();
    t.effects = effects;
    tuning.setEdited(t);
}

//! The title of the plot `graph` is drawn in (level, in its corner).
QString title(const QCPGraph *graph)
{
    const QCPItemText *text = cornerTitle(graph->valueAxis()->axisRect());
    return text ? text->text() : QString();
}

QVector<QPointF> points(const QCPGraph *graph)
{
    QVector<QPointF> out;
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
        out << QPointF(it->key, it->value);
    return out;
}

bool hasKey(const QCPGraph *graph, double key)
{
    const auto pts = points(graph);
    return std::any_of(pts.begin(), pts.end(), [key](const QPointF &p) { return p.x() == key; });
}

DeviceParams params(double kMin, double kMax, double n, double qdz, double theta0)
{
    DeviceParams p;
    p.K_min = kMin;
    p.K_max = kMax;
    p.N = n;
    p.Q_dz = qdz;
    p.theta0 = theta0;
    return p;
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

//! K_min = K_max = k, no dead zone: τ_rec = −k·(θ − θ0).
DeviceParams linear(double k, double theta0 = 0)
{
    return params(k, k, 0.2, 0, theta0);
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

class TestStiffnessView : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void curvesMatchModel_data();
    void curvesMatchModel();
    void breakpointsPresent_data();
    void breakpointsPresent();
    void rangeAroundCenter_data();
    void rangeAroundCenter();
    void deviceCurveDashed();
    void coloursMatchTheTimePlots();
    void replayLegendNamesTheRecording();
    void operatingPointMoves();
    void degreesOnlyScaleTheAxis();
    void renders();
    void curveIsTheStaticTorque();
    void fineDetentsAreResolved();
    void restPositionsAndWallsAreMarked();
    void deviceEffectsAreDrawnWithTheDevice();
    void comparisonCarriesTheOtherSlotsEffects();
    void defaultEffectsChangeNothing();
    void deviceCurveReadsOnTheDarkTheme();
    void namesSayWhatIsDrawn();
};

void TestStiffnessView::curvesMatchModel_data()
{
    QTest::addColumn<DeviceParams>("p");
    QTest::newRow("defaults") << DeviceParams{};
    QTest::newRow("notchy") << params(0.1, 1.5, 0.12, 0.04, 0.0);
    QTest::newRow("off-center theta0") << params(0.15, 0.4, 0.1, 0.02, 0.7);
    QTest::newRow("flat K_min equals K_max") << params(0.3, 0.3, 0.2, 0.05, -0.2);
    QTest::newRow("no dead zone") << params(0.0, 0.8, 0.3, 0.0, 0.0);
    QTest::newRow("wide notch clipped to pi/2") << params(0.1, 0.5, 1.2, 0.1, 0.0);
}

void TestStiffnessView::curvesMatchModel()
{
    QFETCH(DeviceParams, p);
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, p);
    const auto tau = points(view.torqueGraph());
    const auto k = points(view.stiffnessGraph());
    QVERIFY(tau.size() >= StiffnessView::kUniformSamples);
    QCOMPARE(k.size(), tau.size());
    for (int i = 0; i < tau.size(); ++i) {
        const double theta = tau[i].x();
        QCOMPARE(k[i].x(), theta);
        // Exactly the model's numbers at every sample, not an approximation.
        QVERIFY2(tau[i].y() == recenteringTorque(p, theta), qPrintable(QString::number(theta)));
        QVERIFY2(k[i].y() == recenteringStiffness(p, theta), qPrintable(QString::number(theta)));
        if (i > 0)
            QVERIFY(theta > tau[i - 1].x()); // sorted, no duplicates
    }
    // Dense enough: no gap wider than the even grid step.
    const double half = StiffnessView::halfRange(p);
    for (int i = 1; i < tau.size(); ++i)
        QVERIFY(tau[i].x() - tau[i - 1].x() <=
                2 * half / (StiffnessView::kUniformSamples - 1) + 1e-12);
}

void TestStiffnessView::breakpointsPresent_data()
{
    curvesMatchModel_data();
}

void TestStiffnessView::breakpointsPresent()
{
    QFETCH(DeviceParams, p);
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, p);
    const QCPGraph *g = view.torqueGraph();
    const double lo = p.theta0 - StiffnessView::halfRange(p);
    const double hi = p.theta0 + StiffnessView::halfRange(p);
    for (double sign : {-1.0, 1.0}) {
        for (double b : {p.Q_dz, p.N, 2 * p.N}) {
            const double theta = p.theta0 + sign * b;
            if (theta >= lo && theta <= hi)
                QVERIFY2(hasKey(g, theta), qPrintable(QString::number(theta)));
        }
        // The jump at ±Q_dz: two adjacent samples next to the edge, the inner one in the dead
        // zone (τ = 0) and the outer one in the notch band, so the jump is drawn vertical.
        if (p.Q_dz > 0) {
            const double edge = p.theta0 + sign * p.Q_dz;
            const auto pts = points(g);
            bool found = false;
            for (int i = 0; i + 1 < pts.size(); ++i) {
                const double a = pts[i].x();
                const double b = pts[i + 1].x();
                if (std::abs(a - edge) > 1e-12 || std::abs(b - edge) > 1e-12)
                    continue;
                const double in = sign > 0 ? a : b;
                const double out = sign > 0 ? b : a;
                found = found || (stiffnessZone(p, in) == StiffnessZone::DeadZone &&
                                  stiffnessZone(p, out) == StiffnessZone::Notch &&
                                  std::nextafter(in, out) == out);
            }
            QVERIFY2(found, qPrintable(QString::number(edge)));
        }
    }
}

void TestStiffnessView::rangeAroundCenter_data()
{
    QTest::addColumn<double>("n");
    QTest::addColumn<double>("theta0");
    QTest::addColumn<double>("half");
    QTest::newRow("narrow notch: at least 0.5 rad") << 0.1 << 0.0 << 0.5;
    QTest::newRow("2.5 N") << 0.4 << 0.3 << 1.0;
    QTest::newRow("wide notch: at most pi/2") << 1.0 << -0.5 << std::numbers::pi / 2;
}

void TestStiffnessView::rangeAroundCenter()
{
    QFETCH(double, n);
    QFETCH(double, theta0);
    QFETCH(double, half);
    const DeviceParams p = params(0.1, 0.4, n, 0.01, theta0);
    QCOMPARE(StiffnessView::halfRange(p), half);
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, p);
    const QCPRange range = view.torqueGraph()->keyAxis()->range();
    QCOMPARE(range.lower, theta0 - half);
    QCOMPARE(range.upper, theta0 + half);
    QCOMPARE(view.stiffnessGraph()->keyAxis()->range(), range);
    const auto pts = points(view.torqueGraph());
    QCOMPARE(pts.first().x(), theta0 - half);
    QCOMPARE(pts.last().x(), theta0 + half);
}

void TestStiffnessView::replayLegendNamesTheRecording()
{
    // In replay the dashed curve is not the device's and the dot is not live.
    TuningModel tuning;
    StiffnessView view(tuning);
    QCOMPARE(view.deviceTorqueGraph()->name(), u"device"_s);
    view.setReplaying(true);
    QCOMPARE(view.deviceTorqueGraph()->name(), u"recording"_s);
    QVERIFY(view.operatingPointGraph()->name().contains(u"playhead"_s));
    view.setReplaying(false);
    QCOMPARE(view.deviceTorqueGraph()->name(), u"device"_s);
    QVERIFY(view.operatingPointGraph()->name().startsWith(u"live"_s));
}

void TestStiffnessView::coloursMatchTheTimePlots()
{
    // τ_rec's colour for the τ_rec(θ) curves, the notch band amber as in the time plots (the
    // stiffness view once shaded it blue and drew the device curve orange, τ_total's colour).
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, DeviceParams{});
    view.setDeviceTuning({DeviceParams{}, std::nullopt});
    const QColor tauRec = palette::channel(Channel::TauRec);
    QCOMPARE(view.torqueGraph()->pen().color(), tauRec);
    QCOMPARE(view.deviceTorqueGraph()->pen().color().hue(), tauRec.hue());
    for (const QCPGraph *g : {view.torqueGraph(), view.deviceTorqueGraph()}) {
        for (Channel other : kAllChannels) {
            if (other != Channel::TauRec)
                QVERIFY(g->pen().color() != palette::channel(other));
        }
    }
    QCustomPlot *plot = view.findChild<QCustomPlot *>(u"stiffness_plot"_s);
    QVERIFY(plot);
    int notch = 0;
    int deadZone = 0;
    for (int i = 0; i < plot->itemCount(); ++i) {
        if (auto *rect = qobject_cast<QCPItemRect *>(plot->item(i))) {
            notch += rect->brush().color() == palette::kNotch;
            deadZone += rect->brush().color() == palette::kDeadZone;
        }
    }
    QCOMPARE(notch, 2);
    QCOMPARE(deadZone, 2);
}

void TestStiffnessView::deviceCurveDashed()
{
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, DeviceParams{});
    QVERIFY(!view.deviceTorqueGraph()->visible());
    QCOMPARE(view.torqueGraph()->pen().style(), Qt::SolidLine);

    const DeviceParams device = params(0.1, 1.0, 0.15, 0.03, 0.05);
    view.setDeviceTuning({device, std::nullopt});
    QVERIFY(view.deviceTorqueGraph()->visible());
    QVERIFY(view.deviceStiffnessGraph()->visible());
    QCOMPARE(view.deviceTorqueGraph()->pen().style(), Qt::DashLine);
    QCOMPARE(view.deviceStiffnessGraph()->pen().style(), Qt::DashLine);
    const auto pts = points(view.deviceTorqueGraph());
    QVERIFY(!pts.isEmpty());
    for (const QPointF &pt : pts)
        QVERIFY(pt.y() == recenteringTorque(device, pt.x()));
    // The device's own jump is drawn exactly too.
    QVERIFY(hasKey(view.deviceTorqueGraph(), device.theta0 + device.Q_dz));
    // Over the edited set's range.
    QCOMPARE(pts.first().x(), -StiffnessView::halfRange(DeviceParams{}));

    view.setDeviceTuning({});
    QVERIFY(!view.deviceTorqueGraph()->visible());
    QVERIFY(view.deviceTorqueGraph()->data()->isEmpty());
}

void TestStiffnessView::operatingPointMoves()
{
    TuningModel tuning;
    StiffnessView view(tuning);
    editParams(tuning, DeviceParams{});
    QVERIFY(view.operatingPointGraph()->data()->isEmpty());
    view.setOperatingPoint(0.05, -0.02);
    auto pts = points(view.operatingPointGraph());
    QCOMPARE(pts.size(), 1);
    QCOMPARE(pts[0], QPointF(0.05, -0.02));
    QCOMPARE(view.operatingPointGraph()->lineStyle(), QCPGraph::lsNone);
    QVERIFY(view.operatingPointGraph()->scatterStyle().shape() != QCPScatterStyle::ssNone);

    view.setOperatingPoint(-0.3, 0.06);
    pts = points(view.operatingPointGraph());
    QCOMPARE(pts.size(), 1);
    QCOMPARE(pts[0], QPointF(-0.3, 0.06));

    // Survives a parameter change.
    editParams(tuning, params(0.1, 0.5, 0.2, 0.02, 0.0));
    QCOMPARE(points(view.operatingPointGraph()).value(0), QPointF(-0.3, 0.06));

    view.clearOperatingPoint();
    QVERIFY(view.operatingPointGraph()->data()->isEmpty());
}

void TestStiffnessView::degreesOnlyScaleTheAxis()
{
    TuningModel tuning;
    StiffnessView view(tuning);
    const DeviceParams p = params(0.1, 0.5, 0.2, 0.02, 0.0);
    editParams(tuning, p);
    view.setOperatingPoint(0.1, -0.05);
    view.setAngleInDegrees(true);
    const double toDeg = 180.0 / std::numbers::pi;
    QVERIFY(view.stiffnessGraph()->keyAxis()->label().contains(u"°"_s));
    QCOMPARE(view.torqueGraph()->keyAxis()->range().upper, StiffnessView::halfRange(p) * toDeg);
    for (const QPointF &pt : points(view.torqueGraph()))
        QVERIFY(std::abs(pt.y() - recenteringTorque(p, pt.x() / toDeg)) < 1e-12 ||
                std::abs(std::abs(pt.x() / toDeg) - p.Q_dz) < 1e-9); // the jump itself
    QCOMPARE(points(view.operatingPointGraph()).value(0).x(), 0.1 * toDeg);
    view.setAngleInDegrees(false);
    QVERIFY(view.stiffnessGraph()->keyAxis()->label().contains(u"rad"_s));
    QCOMPARE(points(view.operatingPointGraph()).value(0).x(), 0.1);
}

void TestStiffnessView::renders()
{
    TuningModel tuning;
    StiffnessView view(tuning);
    view.resize(500, 400);
    editParams(tuning, DeviceParams{});
    view.setDeviceTuning({params(0.1, 1.0, 0.15, 0.03, 0.05), std::nullopt});
    view.setOperatingPoint(0.08, -0.03);
    const QPixmap pixmap = view.plot()->toPixmap(500, 400);
    QVERIFY(!pixmap.isNull());
    QCOMPARE(title(view.torqueGraph()), u"τ_rec [N·m]"_s);
    QCOMPARE(title(view.stiffnessGraph()), u"K_rec [N·m/rad]"_s);
}

void TestStiffnessView::curveIsTheStaticTorque()
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

void TestStiffnessView::fineDetentsAreResolved()
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

void TestStiffnessView::restPositionsAndWallsAreMarked()
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

void TestStiffnessView::deviceEffectsAreDrawnWithTheDevice()
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

void TestStiffnessView::comparisonCarriesTheOtherSlotsEffects()
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

void TestStiffnessView::defaultEffectsChangeNothing()
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

void TestStiffnessView::deviceCurveReadsOnTheDarkTheme()
{
    // The device's dashed curve is τ_rec's own colour (which reads 3:1 on both themes,
    // tst_theme), not a darker shade that was faint on the dark one.
    TuningModel tuning;
    StiffnessView view(tuning);
    view.setDeviceTuning({linear(0.5), std::nullopt});
    QCOMPARE(view.deviceTorqueGraph()->pen().color(), palette::channel(Channel::TauRec));
    QCOMPARE(view.deviceStiffnessGraph()->pen().color(), palette::channel(Channel::TauRec));
    QCOMPARE(view.deviceTorqueGraph()->pen().style(), Qt::DashLine);
}

void TestStiffnessView::namesSayWhatIsDrawn()
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

QTEST_MAIN(TestStiffnessView)
#include "tst_stiffnessview.moc"
