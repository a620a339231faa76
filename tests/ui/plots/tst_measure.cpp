// Measuring on the plots, with real widgets offscreen: the two cursors and their Δ values
// against known samples (mouse and keyboard), the XY view, the torque breakdown against
// hand-computed terms, and the picture exports (PNG size, SVG that parses, the caption).
#include "plots/fadingtrail.h"
#include "plots/measurecursors.h"
#include "plots/palette.h"
#include "plots/plotexport.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"
#include "plots/torquebreakdownview.h"
#include "plots/xyview.h"
#include "protocol/messages.h"

#include <QComboBox>
#include <QFile>
#include <QImageReader>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

using namespace hatpic;

namespace {

constexpr double kRate = 1000; // [Hz]

//! θ = 0.1·t, ω = 0.1 + 0.2·t (ω̇ = 0.2), τ = −0.05·t, τ_rec = −0.4·θ, τ_ext = 0.01,
//! τ_total = τ_rec + τ_ext clamped to ±0.02 (saturated then), v_ref = 0.5·θ, p_ref = t.
Sample sampleAt(int i)
{
    Sample s;
    s.t_s = i / kRate;
    s.theta = 0.1 * s.t_s;
    s.omega = 0.1 + 0.2 * s.t_s;
    s.tau = -0.05 * s.t_s;
    s.tau_rec = -0.4 * s.theta;
    s.tau_ext = 0.01;
    const double sum = s.tau_rec + s.tau_ext;
    s.tau_total = std::clamp(sum, -0.02, 0.02);
    if (s.tau_total != sum)
        s.flags |= v2::kFlagSaturated;
    s.v_ref = 0.5 * s.theta;
    s.p_ref = s.t_s;
    return s;
}

void fill(SampleBuffer &buffer, int from, int to)
{
    for (int i = from; i < to; ++i)
        buffer.append(sampleAt(i));
}

//! The value of `graph` at time `t` (its data hold every sample).
double valueAt(const QCPGraph *graph, double t)
{
    auto it = graph->data()->findBegin(t - 1e-9, false);
    if (it == graph->data()->constEnd() || std::abs(it->key - t) > 1e-9)
        return std::nan("");
    return it->value;
}

} // namespace

class TestMeasure : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void cursorsGiveDeltaOfEveryVisibleSeries();
    void cursorsFollowDisplayUnits();
    void cursorsByMouse();
    void cursorsByKeyboard();
    void xyViewDrawsTheChosenPair();
    void breakdownMatchesHandComputedTerms();
    void breakdownWithoutParameters();
    void breakdownShowsTheEffectTorque();
    void exportsPngAtTheChosenSize();
    void exportsSvgThatParses();
    void refusesAnAbsurdSize();

private:
    std::unique_ptr<SampleBuffer> m_buffer;
    std::unique_ptr<PlotPanel> m_panel;
};

void TestMeasure::init()
{
    m_buffer = std::make_unique<SampleBuffer>();
    fill(*m_buffer, 0, 3000); // 0 … 2.999 s
    m_panel = std::make_unique<PlotPanel>();
    m_panel->setSource(m_buffer.get());
    m_panel->setWindowLength(3);
    m_panel->resize(1000, 700);
    m_panel->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_panel.get()));
    m_panel->repaintNow();
    m_panel->repaintNow(); // laid out at this size
}

void TestMeasure::cleanup()
{
    m_panel.reset(); // before the buffer it reads
    m_buffer.reset();
}

void TestMeasure::cursorsGiveDeltaOfEveryVisibleSeries()
{
    MeasureCursors *m = m_panel->measure();
    QVERIFY(!m->readout());
    m->setEnabled(true);
    // Placed at a third and two thirds of the view, on samples.
    QVERIFY(m->time(0) && m->time(1));
    QVERIFY(*m->time(0) < *m->time(1));
    m->setTime(0, 1.0002); // snaps to the sample at 1.000 s
    m->setTime(1, 1.4999);
    QCOMPARE(*m->time(0), 1.0);
    QCOMPARE(*m->time(1), 1.5);
    const std::optional<MeasureCursors::Readout> r = m->readout();
    QVERIFY(r);
    QCOMPARE(r->dt, 0.5);
    QVERIFY(m->dtText().contains(QStringLiteral("Δt = 0.500 s")));
    QVERIFY(m->dtText().contains(QStringLiteral("2 Hz")));
    // Every visible series (ω and τ_fx's three parts are hidden by default), each
    // Δ = value(B) − value(A).
    QCOMPARE(r->deltas.size(), kChannelCount - 4);
    for (const MeasureCursors::Delta &d : r->deltas) {
        const double expected = m_buffer->value(d.channel, 1500) - m_buffer->value(d.channel, 1000);
        QVERIFY2(std::abs(d.delta - expected) < 1e-12, qPrintable(channelLabel(d.channel)));
    }
    QVERIFY(std::abs(r->deltas[0].delta - 0.05) < 1e-12); // θ: 0.1 rad/s × 0.5 s
    // The legends say it: "θ Δ +0.0500 rad", "τ (measured) Δ −0.0250 N·m".
    m_panel->repaintNow();
    QVERIFY2(m_panel->graph(Channel::Theta)->name().contains(QStringLiteral("Δ +0.0500")),
             qPrintable(m_panel->graph(Channel::Theta)->name()));
    QVERIFY(m_panel->graph(Channel::Tau)->name().contains(QStringLiteral("Δ −0.0250")));
    // Hiding a series drops it.
    m_panel->setChannelVisible(Channel::PRef, false);
    QCOMPARE(m->readout()->deltas.size(), kChannelCount - 5);
    m->setEnabled(false);
    QVERIFY(!m->readout());
    m_panel->repaintNow();
    QVERIFY(!m_panel->graph(Channel::Theta)->name().contains(QStringLiteral("Δ")));
}

void TestMeasure::cursorsFollowDisplayUnits()
{
    MeasureCursors *m = m_panel->measure();
    m->setEnabled(true);
    m->setTime(0, 0.5);
    m->setTime(1, 2.5);
    m_panel->setAngleInDegrees(true);
    const auto r = m->readout();
    QVERIFY(r);
    const double degrees = 0.2 * 180 / std::numbers::pi; // Δθ = 0.2 rad
    QVERIFY(std::abs(r->deltas[0].delta - degrees) < 1e-9);
    m_panel->repaintNow();
    QVERIFY2(m_panel->graph(Channel::Theta)->name().contains(QStringLiteral("Δ +11.46")),
             qPrintable(m_panel->graph(Channel::Theta)->name()));
}

void TestMeasure::cursorsByMouse()
{
    MeasureCursors *m = m_panel->measure();
    m->setEnabled(true);
    QCustomPlot *plot = m_panel->customPlot();
    QCPAxisRect *rect = m_panel->axisRect(PlotPanel::Plot::Torque);
    QCPAxis *x = rect->axis(QCPAxis::atBottom);
    const int y = rect->rect().center().y();
    // A click places A, Shift+click B, each at the sample under the mouse.
    const int xa = int(x->coordToPixel(0.8));
    const int xb = int(x->coordToPixel(2.2));
    QTest::mouseClick(plot, Qt::LeftButton, {}, QPoint(xa, y));
    QTest::mouseClick(plot, Qt::LeftButton, Qt::ShiftModifier, QPoint(xb, y));
    const double perPixel = x->range().size() / rect->width();
    QVERIFY(std::abs(*m->time(0) - 0.8) <= perPixel);
    QVERIFY(std::abs(*m->time(1) - 2.2) <= perPixel);
    QCOMPARE(m->active(), 1);
    // Dragging A's line moves A, not the view.
    const double viewStart = m_panel->viewStart();
    const int from = int(x->coordToPixel(*m->time(0)));
    QTest::mousePress(plot, Qt::LeftButton, {}, QPoint(from + 2, y));
    QMouseEvent move(QEvent::MouseMove, QPointF(from + 100, y),
                     plot->mapToGlobal(QPointF(from + 100, y)), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(plot, &move);
    QTest::mouseRelease(plot, Qt::LeftButton, {}, QPoint(from + 100, y));
    QVERIFY(std::abs(*m->time(0) - x->pixelToCoord(from + 100)) <= perPixel);
    QCOMPARE(m->active(), 0);
    QCOMPARE(m_panel->viewStart(), viewStart);
}

void TestMeasure::cursorsByKeyboard()
{
    MeasureCursors *m = m_panel->measure();
    m->setEnabled(true);
    m->setTime(0, 1.0);
    m->setTime(1, 2.0);
    QCustomPlot *plot = m_panel->customPlot();
    plot->setFocus();
    QCPAxisRect *rect = m_panel->axisRect(PlotPanel::Plot::Angle);
    const double perPixel = rect->axis(QCPAxis::atBottom)->range().size() / rect->width();
    QTest::keyClick(plot, Qt::Key_B);
    QCOMPARE(m->active(), 1);
    QTest::keyClick(plot, Qt::Key_Left);
    QVERIFY(*m->time(1) < 2.0);
    QVERIFY(std::abs(*m->time(1) - (2.0 - perPixel)) <= 0.0011);
    QTest::keyClick(plot, Qt::Key_A);
    QTest::keyClick(plot, Qt::Key_Right, Qt::ShiftModifier); // ten pixels
    QVERIFY(std::abs(*m->time(0) - (1.0 + 10 * perPixel)) <= 0.0011);
    // Δt follows.
    QVERIFY(std::abs(m->readout()->dt - (*m->time(1) - *m->time(0))) < 1e-12);
    // Off: the keys do nothing.
    m->setEnabled(false);
    const double before = *m->time(0);
    QTest::keyClick(plot, Qt::Key_Right);
    QCOMPARE(*m->time(0), before);
}

void TestMeasure::xyViewDrawsTheChosenPair()
{
    m_panel->setChannelVisible(Channel::Omega, true);
    XyView xy(m_panel.get());
    xy.resize(500, 400);
    xy.show();
    QVERIFY(QTest::qWaitForWindowExposed(&xy));
    QCOMPARE(xy.xChannel(), Channel::Theta); // the phase plane by default
    QCOMPARE(xy.yChannel(), Channel::Omega);
    m_panel->repaintNow(); // the view follows the panel's repaints
    // Every sample of the visible range, oldest first, (θ, ω) in display units.
    QCOMPARE(xy.trail().pointCount(), qsizetype(3000));
    const QCPCurve *newest = xy.trail().piece(FadingTrail::kPieces - 1);
    const QCPCurveData last = *(newest->data()->constEnd() - 1);
    QCOMPARE(last.key, m_buffer->value(Channel::Theta, 2999));
    QCOMPARE(last.value, m_buffer->value(Channel::Omega, 2999));
    QVERIFY(xy.trail().piece(0)->pen().color().alpha() < newest->pen().color().alpha());
    QCOMPARE(xy.pointGraph()->data()->size(), 1);
    QVERIFY(xy.plot()->xAxis->label().startsWith(QStringLiteral("θ [rad]")));
    // Any pair, in the panel's units.
    xy.yBox()->setCurrentIndex(channelIndex(Channel::TauRec));
    m_panel->setAngleInDegrees(true);
    m_panel->repaintNow();
    const QCPCurveData lastDeg =
        *(xy.trail().piece(FadingTrail::kPieces - 1)->data()->constEnd() - 1);
    QCOMPARE(lastDeg.key, m_buffer->value(Channel::Theta, 2999) * 180 / std::numbers::pi);
    QCOMPARE(lastDeg.value, m_buffer->value(Channel::TauRec, 2999));
    QVERIFY(xy.plot()->yAxis->label().contains(QStringLiteral("N·m")));
    // Replay-like: data end at a playhead.
    m_panel->setDataEnd(1.5);
    m_panel->repaintNow();
    const QCPCurveData atHead =
        *(xy.trail().piece(FadingTrail::kPieces - 1)->data()->constEnd() - 1);
    QCOMPARE(atHead.value, m_buffer->value(Channel::TauRec, 1500));
}

void TestMeasure::breakdownMatchesHandComputedTerms()
{
    DeviceParams params;
    params.D_adm = 2e-3;
    params.M_adm = 0.05;
    m_panel->setDeviceParams(params);
    TorqueBreakdownView view(m_panel.get());
    view.resize(600, 400);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    m_panel->repaintNow();
    QVERIFY(view.notice().isEmpty());
    // At t = 1 s (sample 1000), by hand from sampleAt(): ω̇ = 0.2, ω = 0.3, τ = −0.05,
    // τ_rec = −0.04, τ_ext = 0.01, τ_total = −0.02 (clamped from −0.03).
    const double t = 1.0;
    auto at = [&](TorqueBreakdownView::Term term) { return valueAt(view.graph(term), t); };
    QVERIFY(std::abs(at(TorqueBreakdownView::Term::Inertial) - 2e-3 * 0.2) < 1e-9);
    QVERIFY(std::abs(at(TorqueBreakdownView::Term::Damping) - 0.05 * 0.3) < 1e-12);
    QVERIFY(std::abs(at(TorqueBreakdownView::Term::TauOp) - 0.05) < 1e-12);
    QVERIFY(std::abs(at(TorqueBreakdownView::Term::TauRec) - -0.04) < 1e-12);
    QVERIFY(std::abs(at(TorqueBreakdownView::Term::TauExt) - 0.01) < 1e-12);
    QVERIFY(std::abs(at(TorqueBreakdownView::Term::Clipped) - -0.01) < 1e-12);
    // Until t ≈ 0.75 s |τ_rec + τ_ext| ≤ 0.02: nothing clipped; the shading starts where the
    // clamp does.
    QCOMPARE(valueAt(view.graph(TorqueBreakdownView::Term::Clipped), 0.5), 0.0);
    qsizetype firstSaturated = 0;
    while (!(m_buffer->flags(firstSaturated) & v2::kFlagSaturated))
        ++firstSaturated;
    QVERIFY(std::abs(m_buffer->time(firstSaturated) - 0.75) < 0.0015);
    const QCPGraph *shade = view.saturationGraph();
    QVERIFY(shade->brush().style() != Qt::NoBrush);
    QCOMPARE(shade->data()->constBegin()->value, 0.0);
    bool rose = false;
    for (auto it = shade->data()->constBegin(); it != shade->data()->constEnd(); ++it) {
        if (it->value == 1.0) {
            QCOMPARE(it->key, m_buffer->time(firstSaturated));
            rose = true;
            break;
        }
    }
    QVERIFY(rose);
    QCOMPARE(view.plot()->xAxis->range().lower, m_panel->viewStart());
}

void TestMeasure::breakdownWithoutParameters()
{
    TorqueBreakdownView view(m_panel.get());
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    m_panel->repaintNow();
    QVERIFY(!view.notice().isEmpty());
    QCOMPARE(view.graph(TorqueBreakdownView::Term::Inertial)->data()->size(), 0);
    QVERIFY(view.graph(TorqueBreakdownView::Term::TauRec)->data()->size() > 0);
}

void TestMeasure::breakdownShowsTheEffectTorque()
{
    TorqueBreakdownView view(m_panel.get());
    view.resize(600, 400);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    // A sample from a device without effects: τ_fx unknown, so no term there and 0 in the sum.
    Sample unknown = sampleAt(3000);
    unknown.tau_fx = std::numeric_limits<double>::quiet_NaN();
    m_buffer->append(unknown);
    // One with τ_fx = 0.005 N·m: at t = 3.001 s (τ_rec = −0.12004, τ_ext = 0.01) the clamp to
    // −0.02 took (−0.12004 + 0.005 + 0.01) − (−0.02) = −0.08504.
    Sample fx = sampleAt(3001);
    fx.tau_fx = 0.005;
    fx.tau_total = -0.02;
    fx.flags |= v2::kFlagSaturated;
    m_buffer->append(fx);
    m_panel->repaintNow();
    const QCPGraph *tauFx = view.graph(TorqueBreakdownView::Term::TauFx);
    QCOMPARE(tauFx->name(), QStringLiteral("τ_fx"));
    QCOMPARE(valueAt(tauFx, 3.001), 0.005);
    QVERIFY(std::abs(valueAt(view.graph(TorqueBreakdownView::Term::Clipped), 3.001) -
                     (-0.12004 + 0.005 + 0.01 + 0.02)) < 1e-12);
    QVERIFY(std::isnan(valueAt(tauFx, 3.0)));
    QVERIFY(std::abs(valueAt(view.graph(TorqueBreakdownView::Term::Clipped), 3.0) -
                     (unknown.tau_rec + unknown.tau_ext - unknown.tau_total)) < 1e-12);
}

void TestMeasure::exportsPngAtTheChosenSize()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("view.png"));
    DeviceParams params;
    params.K_max = 0.6;
    PlotImageOptions options;
    options.size = QSize(1600, 900);
    options.scale = 2;
    options.caption = plotCaption(QStringLiteral("Notchy"), params, HostParams{});
    QVERIFY(options.caption.contains(QStringLiteral("Notchy")));
    QVERIFY(options.caption.contains(QStringLiteral("K_max = 0.6 N·m/rad")));
    QVERIFY(options.caption.contains(QStringLiteral("tau_limit = 0.44 N·m")));
    QString error;
    QVERIFY2(m_panel->exportImage(path, options, &error), qPrintable(error));
    QImageReader reader(path);
    QCOMPARE(reader.format(), QByteArray("png"));
    QCOMPARE(reader.size(), QSize(1600, 900));
    const QImage image = reader.read();
    // The caption is drawn in the band at the top: dark pixels there.
    int dark = 0;
    for (int x = 0; x < image.width(); ++x)
        dark += qGray(image.pixel(x, 24)) < 128 ? 1 : 0;
    QVERIFY2(dark > 10, qPrintable(QString::number(dark)));
    // The plot on screen keeps its size.
    QCOMPARE(m_panel->customPlot()->viewport().size(), m_panel->customPlot()->size());
}

void TestMeasure::exportsSvgThatParses()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("view.svg"));
    PlotImageOptions options;
    options.size = QSize(1280, 720);
    options.caption = plotCaption(QStringLiteral("Soft"), DeviceParams{}, HostParams{});
    QString error;
    QVERIFY2(m_panel->exportImage(path, options, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QXmlStreamReader xml(&file);
    int elements = 0;
    bool sized = false;
    bool captioned = false;
    while (!xml.atEnd()) {
        if (xml.readNext() == QXmlStreamReader::StartElement) {
            ++elements;
            if (xml.name() == u"svg")
                sized = xml.attributes().value(QStringLiteral("viewBox")) == u"0 0 1280 720";
        } else if (xml.isCharacters() && xml.text().contains(u"Profile Soft")) {
            captioned = true;
        }
    }
    QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
    QVERIFY(sized);
    QVERIFY(captioned);
    QVERIFY(elements > 50);
}

void TestMeasure::refusesAnAbsurdSize()
{
    QTemporaryDir dir;
    PlotImageOptions options;
    options.size = QSize(50, 20000);
    QString error;
    QVERIFY(!m_panel->exportImage(dir.filePath(QStringLiteral("x.png")), options, &error));
    QVERIFY(error.contains(QStringLiteral("50×20000")));
    QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("x.png"))));
}

QTEST_MAIN(TestMeasure)
#include "tst_measure.moc"
