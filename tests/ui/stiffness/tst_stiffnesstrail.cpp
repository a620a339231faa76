// The stiffness view's trail of the operating point, with real widgets offscreen: (θ, measured
// τ) over the last seconds of what the time plots show — live, or up to a replay's playhead —
// older points fainter, so a hysteresis loop and chatter at the dead-zone edge show.
#include "plots/fadingtrail.h"
#include "plots/palette.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"
#include "stiffness/stiffnessview.h"
#include "tuning/tuningmodel.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace hatpic;

namespace {

constexpr double kRate = 1000; // [Hz]

//! A loop: θ = 0.1·sin(2πt), τ = −0.4·θ − 0.02·cos(2πt) (τ leads θ, as with damping).
void fill(SampleBuffer &buffer, int count)
{
    for (int i = 0; i < count; ++i) {
        Sample s;
        s.t_s = i / kRate;
        const double phase = 2 * std::numbers::pi * s.t_s;
        s.theta = 0.1 * std::sin(phase);
        s.tau = -0.4 * s.theta - 0.02 * std::cos(phase);
        s.tau_rec = -0.4 * s.theta;
        s.tau_total = s.tau_rec;
        buffer.append(s);
    }
}

//! A panel drawing a buffer, and a stiffness view following its trail.
struct Rig
{
    SampleBuffer buffer;
    PlotPanel panel;
    TuningModel tuning;
    StiffnessView view{tuning};

    explicit Rig(int samples)
    {
        panel.setSource(&buffer);
        view.followTrail(&panel);
        fill(buffer, samples);
    }
};

QCPCurveData newest(const FadingTrail &trail)
{
    return *(trail.piece(FadingTrail::kPieces - 1)->data()->constEnd() - 1);
}

} // namespace

class TestStiffnessTrail : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void trailCoversTheLastSecondsAndFades();
    void trailShowsTheLoop();
    void trailEndsAtThePlayhead();
};

void TestStiffnessTrail::trailCoversTheLastSecondsAndFades()
{
    Rig rig(0);
    SampleBuffer &buffer = rig.buffer;
    StiffnessView &view = rig.view;
    rig.panel.repaintNow();
    QCOMPARE(view.trail()->pointCount(), 0);
    fill(buffer, 5000); // 0 … 4.999 s
    rig.panel.repaintNow();
    // [4.999 − 3, 4.999] at 1 kHz: 3001 samples.
    QCOMPARE(view.trail()->pointCount(), qsizetype(StiffnessView::kTrailSeconds * kRate + 1));
    const QCPCurveData last = newest(*view.trail());
    QCOMPARE(last.key, buffer.value(Channel::Theta, 4999));
    QCOMPARE(last.value, buffer.value(Channel::Tau, 4999));
    // Older pieces fainter, all in τ's colour, under the live point.
    int alpha = -1;
    for (int i = 0; i < FadingTrail::kPieces; ++i) {
        const QColor c = view.trail()->piece(i)->pen().color();
        QCOMPARE(c.rgb(), palette::channel(Channel::Tau).rgb());
        QVERIFY(c.alpha() > alpha);
        alpha = c.alpha();
    }
    QCPLayer *overlay = view.operatingPointGraph()->layer();
    QCOMPARE(view.trail()->piece(0)->layer(), overlay);
    QVERIFY(overlay->children().indexOf(view.trail()->piece(FadingTrail::kPieces - 1)) <
            overlay->children().indexOf(view.operatingPointGraph()));
    // Degrees on the θ axis.
    view.setAngleInDegrees(true);
    rig.panel.repaintNow();
    QCOMPARE(newest(*view.trail()).key,
             buffer.value(Channel::Theta, 4999) * 180 / std::numbers::pi);
}

void TestStiffnessTrail::trailShowsTheLoop()
{
    // Over a period, at the same θ = 0 the trail passes twice with different τ: a loop, not
    // the τ_rec curve.
    Rig rig(4001);
    rig.panel.repaintNow();
    double up = NAN;
    double down = NAN;
    for (int i = 0; i < FadingTrail::kPieces; ++i) {
        const auto data = rig.view.trail()->piece(i)->data();
        for (auto it = data->constBegin(); it != data->constEnd(); ++it) {
            if (std::abs(it->key) < 1e-4)
                (it->value < 0 ? up : down) = it->value;
        }
    }
    QVERIFY(std::abs(up - -0.02) < 1e-3);
    QVERIFY(std::abs(down - 0.02) < 1e-3);
}

void TestStiffnessTrail::trailEndsAtThePlayhead()
{
    Rig rig(5000);
    rig.panel.setFollowLatest(false);
    rig.panel.setViewEnd(3.0);
    rig.panel.setDataEnd(2.0); // a replay's playhead
    rig.panel.repaintNow();
    QCOMPARE(newest(*rig.view.trail()).value, rig.buffer.value(Channel::Tau, 2000));
    QCOMPARE(rig.view.trail()->pointCount(), qsizetype(2001)); // 0 … 2 s: less than the length
    rig.buffer.clear();
    rig.panel.repaintNow();
    QCOMPARE(rig.view.trail()->pointCount(), 0);
}

QTEST_MAIN(TestStiffnessTrail)
#include "tst_stiffnesstrail.moc"
