#include "experimentplots.h"

#include "plots/plottheme.h"

#include "plots/axistitle.h"
#include "plots/palette.h"
#include "plots/qcp.h"

#include <QFileInfo>
#include <QSvgGenerator>

#include <cmath>
#include <numbers>

namespace hatpic {

namespace {

constexpr double kDegrees = 180 / std::numbers::pi;

//! A row above the plot for `legend`: it never lies over a curve (issue 21: the Bode legend
//! once hid the measured points at 1280×720).
void legendRow(QCustomPlot *plot, QCPLegend *legend)
{
    // In a row of its own with a filler beside it: an empty legend (before the first result)
    // would otherwise narrow the whole column to its own width.
    auto *row = new QCPLayoutGrid;
    plot->plotLayout()->insertRow(0);
    plot->plotLayout()->addElement(0, 0, row);
    plot->plotLayout()->setRowStretchFactor(0, 0.001);
    row->addElement(0, 0, legend);
    row->addElement(0, 1, new QCPLayoutElement(plot));
    row->setColumnStretchFactor(0, 0.001);
    row->setColumnStretchFactor(1, 1);
    legend->setLayer(QStringLiteral("legend"));
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    legend->setBorderPen(Qt::NoPen);
    legend->setBrush(Qt::NoBrush);
    legend->setMargins(QMargins(4, 2, 4, 0));
    plot->legend = legend;
}

QCustomPlot *makePlot(QWidget *parent, const QString &name)
{
    auto *plot = new QCustomPlot(parent);
    plot->setObjectName(name);
    plot->setMinimumSize(200, 120); // the dock must fit under the plots at 1280×720
    plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    return plot;
}

//! The default layout's one axis rect, with the legend in a row above it.
void withLegendAbove(QCustomPlot *plot)
{
    QCPLegend *legend = plot->legend;
    plot->axisRect()->insetLayout()->take(legend);
    plot->axisRect()->insetLayout()->simplify();
    legendRow(plot, legend);
    legend->setVisible(true);
}

QCPGraph *addGraph(QCustomPlot *plot, QCPAxis *x, QCPAxis *y, const QString &name,
                   const QColor &colour, Qt::PenStyle style = Qt::SolidLine)
{
    QCPGraph *g = plot->addGraph(x, y);
    g->setName(name);
    QPen pen(colour, 1.5);
    pen.setStyle(style);
    g->setPen(pen);
    return g;
}

void logAxis(QCPAxis *axis)
{
    axis->setScaleType(QCPAxis::stLogarithmic);
    axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
}

} // namespace

ExperimentPlots::ExperimentPlots(QWidget *parent) : QTabWidget(parent)
{
    m_step = makePlot(this, QStringLiteral("stepPlot"));
    withLegendAbove(m_step);
    m_step->xAxis->setLabel(tr("time since the step [s]"));
    m_step->yAxis->setLabel(tr("Δθ [rad]"));
    addTab(m_step, tr("Step"));

    // Two rects on one frequency axis, labelled once, so that nothing collides in a short dock.
    m_bode = makePlot(this, QStringLiteral("bodePlot"));
    m_bode->plotLayout()->clear();
    auto *magnitude = new QCPAxisRect(m_bode);
    auto *phase = new QCPAxisRect(m_bode);
    m_bode->plotLayout()->addElement(0, 0, magnitude);
    m_bode->plotLayout()->addElement(1, 0, phase);
    auto *margins = new QCPMarginGroup(m_bode);
    for (QCPAxisRect *rect : {magnitude, phase}) {
        logAxis(rect->axis(QCPAxis::atBottom));
        rect->setRangeZoomAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
        rect->axis(QCPAxis::atLeft)->ticker()->setTickCount(3); // short plots: few numbers
    }
    phase->axis(QCPAxis::atBottom)->setLabel(tr("frequency [Hz]"));
    // Titles level in the top right corner, where the curves fall away from: written along
    // the axes they were longer than a short plot is tall.
    setCornerTitle(magnitude, tr("gain [dB]"));
    setCornerTitle(phase, tr("phase [°]"));
    legendRow(m_bode, new QCPLegend);
    addTab(m_bode, tr("Bode θ/τ_ext"));
    setTabToolTip(BodeTab, tr("The gain of θ/τ_ext in dB re 1 rad/(N·m), and its phase"));

    m_spectrum = makePlot(this, QStringLiteral("spectrumPlot"));
    withLegendAbove(m_spectrum);
    m_spectrum->xAxis->setLabel(tr("frequency [Hz]"));
    m_spectrum->yAxis->setLabel(tr("θ [dB re 1 rad]"));
    m_spectrum->yAxis2->setVisible(true);
    m_spectrum->yAxis2->setLabel(tr("τ [dB re 1 N·m]"));
    addTab(m_spectrum, tr("Spectrum"));
    // The theme's colours, as the main plots (issue 27: these stayed white in the dark theme).
    for (QCustomPlot *plot : {m_step, m_bode, m_spectrum})
        plottheme::follow(plot);
}

QCustomPlot *ExperimentPlots::plot(Tab tab) const
{
    switch (tab) {
    case StepTab:
        return m_step;
    case BodeTab:
        return m_bode;
    case SpectrumTab:
        return m_spectrum;
    }
    return nullptr;
}

void ExperimentPlots::showResult(const ExperimentResult &result)
{
    switch (result.plan.kind) {
    case ExperimentKind::Step:
        showStep(result);
        break;
    case ExperimentKind::Frequency:
        showBode(result);
        break;
    case ExperimentKind::Spectrum:
        showSpectra(result.thetaSpectrum, result.tauSpectrum, tr("at rest"));
        break;
    }
}

void ExperimentPlots::showStep(const ExperimentResult &r)
{
    m_step->clearGraphs();
    QCPGraph *measured = addGraph(m_step, m_step->xAxis, m_step->yAxis, tr("θ measured"),
                                  palette::channel(Channel::Theta));
    // What else held the knob, where every picture of the step carries it.
    m_step->xAxis->setLabel(tr("time since the step [s] · hand: %1").arg(runHandText(r.hand)));
    QCPGraph *model = addGraph(m_step, m_step->xAxis, m_step->yAxis, tr("θ ideal model"),
                               palette::channel(Channel::Theta), Qt::DashLine);
    const double before = r.stepMeasured.initial;
    QVector<double> t, y;
    for (const Sample &s : r.samples) {
        const double since = s.t_s - r.stepAt;
        if (since >= -r.plan.settle / 4 && since <= r.plan.duration) {
            t.append(since);
            y.append(s.theta - before);
        }
    }
    measured->setData(t, y, true);
    t.clear();
    y.clear();
    for (const Sample &s : r.ideal) {
        const double since = s.t_s - r.idealStepAt;
        if (since >= -r.plan.settle / 4 && since <= r.plan.duration) {
            t.append(since);
            y.append(s.theta - r.stepIdeal.initial);
        }
    }
    model->setData(t, y, true);
    m_step->rescaleAxes();
    plottheme::apply(m_step, m_step->palette()); // the new legend entries too; replots
    setCurrentWidget(m_step);
}

void ExperimentPlots::showBode(const ExperimentResult &r)
{
    m_bode->clearGraphs();
    QCPAxisRect *magnitude = m_bode->axisRect(0);
    QCPAxisRect *phase = m_bode->axisRect(1);
    auto axes = [](QCPAxisRect *rect) {
        return std::pair{rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft)};
    };
    const QColor colour = palette::channel(Channel::Theta);
    const auto [mx, my] = axes(magnitude);
    const auto [px, py] = axes(phase);
    QCPGraph *modelMag = addGraph(m_bode, mx, my, tr("model"), colour, Qt::DashLine);
    QCPGraph *measuredMag = addGraph(m_bode, mx, my, tr("measured"), colour);
    QCPGraph *modelPhase = addGraph(m_bode, px, py, tr("model"), colour, Qt::DashLine);
    QCPGraph *measuredPhase = addGraph(m_bode, px, py, tr("measured"), colour);
    modelPhase->removeFromLegend();
    measuredPhase->removeFromLegend();
    for (QCPGraph *g : {measuredMag, measuredPhase})
        g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 6));
    if (r.points.empty()) {
        plottheme::apply(m_bode, m_bode->palette()); // the new legend entries too; replots
        return;
    }
    const double lo = r.points.front().frequency / 2;
    const double hi = r.points.back().frequency * 2;
    QVector<double> f, mag, ph;
    for (int i = 0; i <= 200; ++i) {
        const double fi = lo * std::pow(hi / lo, i / 200.0);
        const std::complex<double> h = analysis::modelGain(r.params, fi);
        f.append(fi);
        mag.append(20 * std::log10(std::abs(h)));
        ph.append(std::arg(h) * kDegrees);
    }
    modelMag->setData(f, mag, true);
    modelPhase->setData(f, ph, true);
    f.clear();
    mag.clear();
    ph.clear();
    for (const analysis::FrequencyPoint &p : r.points) {
        f.append(p.frequency);
        mag.append(20 * std::log10(p.magnitude));
        ph.append(p.phase * kDegrees);
    }
    measuredMag->setData(f, mag, true);
    measuredPhase->setData(f, ph, true);
    for (QCPAxisRect *rect : {magnitude, phase}) {
        rect->axis(QCPAxis::atBottom)->setRange(lo, hi);
        rect->axis(QCPAxis::atLeft)->rescale();
        rect->axis(QCPAxis::atLeft)->scaleRange(1.1);
    }
    plottheme::apply(m_bode, m_bode->palette()); // the new legend entries too; replots
    setCurrentWidget(m_bode);
}

void ExperimentPlots::showSpectra(const analysis::Spectrum &theta, const analysis::Spectrum &tau,
                                  const QString &title)
{
    m_spectrum->clearGraphs();
    QCPGraph *th = addGraph(m_spectrum, m_spectrum->xAxis, m_spectrum->yAxis,
                            tr("θ (%1)").arg(title), palette::channel(Channel::Theta));
    QCPGraph *ta = addGraph(m_spectrum, m_spectrum->xAxis, m_spectrum->yAxis2,
                            tr("τ (%1)").arg(title), palette::channel(Channel::Tau));
    // Bin 0 (the mean, taken out) carries nothing to see.
    auto fill = [](QCPGraph *g, const analysis::Spectrum &s) {
        QVector<double> f, db;
        for (std::size_t k = 1; k < s.frequency.size(); ++k) {
            f.append(s.frequency[k]);
            db.append(s.magnitudeDb[k]);
        }
        g->setData(f, db, true);
        g->rescaleAxes();
    };
    fill(th, theta);
    fill(ta, tau);
    plottheme::apply(m_spectrum, m_spectrum->palette()); // the new legend entries too; replots
    setCurrentWidget(m_spectrum);
}

bool ExperimentPlots::exportImage(const QString &path, QString *error) const
{
    auto *plot = qobject_cast<QCustomPlot *>(currentWidget());
    bool ok = false;
    if (QFileInfo(path).suffix().compare(u"svg", Qt::CaseInsensitive) == 0) {
        QSvgGenerator svg;
        svg.setFileName(path);
        svg.setSize(plot->size());
        svg.setViewBox(QRect(QPoint(0, 0), plot->size()));
        svg.setTitle(tabText(currentIndex()));
        QCPPainter painter;
        ok = painter.begin(&svg);
        if (ok) {
            plot->toPainter(&painter, plot->width(), plot->height());
            ok = painter.end();
        }
    } else {
        ok = plot->savePng(path);
    }
    if (!ok && error)
        *error = tr("Could not write %1.").arg(path);
    return ok;
}

} // namespace hatpic
