// StiffnessView: the plotted curves are the model's, the breakpoints are exact, the range is
// centred, the device's curve is dashed and reads on the dark theme, the colours are the time
// plots', a replay's legend names the recording, and the live operating point moves. With
// haptic effects: tst_stiffnesseffects.
#include "model/stiffness.h"
#include "plots/palette.h"
#include "plots/qcp.h"
#include "stiffness/stiffnessview.h"
#include "stiffnesscurves.h"
#include "tuning/tuningmodel.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

Q_DECLARE_METATYPE(hatpic::DeviceParams)

namespace {

bool hasKey(const QCPGraph *graph, double key)
{
    const auto pts = points(graph);
    return std::any_of(pts.begin(), pts.end(), [key](const QPointF &p) { return p.x() == key; });
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
    void deviceCurveReadsOnTheDarkTheme();
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

QTEST_MAIN(TestStiffnessView)
#include "tst_stiffnessview.moc"
