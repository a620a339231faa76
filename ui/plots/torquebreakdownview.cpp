#include "plots/torquebreakdownview.h"

#include "model/torquebreakdown.h"
#include "plots/palette.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"
#include "protocol/messages.h"

#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace hatpic {

namespace {

constexpr std::array<TorqueBreakdownView::Term, TorqueBreakdownView::kTermCount> kTerms{
    TorqueBreakdownView::Term::Inertial, TorqueBreakdownView::Term::Damping,
    TorqueBreakdownView::Term::TauOp,    TorqueBreakdownView::Term::TauRec,
    TorqueBreakdownView::Term::TauExt,   TorqueBreakdownView::Term::TauFx,
    TorqueBreakdownView::Term::Clipped};

QPen termPen(TorqueBreakdownView::Term term)
{
    switch (term) {
    case TorqueBreakdownView::Term::Inertial:
        return QPen(palette::kInertialTerm, 1.5);
    case TorqueBreakdownView::Term::Damping:
        return QPen(palette::kDampingTerm, 1.5);
    case TorqueBreakdownView::Term::TauOp: // −τ: the measured torque's colour
        return QPen(palette::channel(Channel::Tau), 1.5);
    case TorqueBreakdownView::Term::TauRec:
        return QPen(palette::channel(Channel::TauRec), 1.5);
    case TorqueBreakdownView::Term::TauExt:
        return QPen(palette::channel(Channel::TauExt), 1.5);
    case TorqueBreakdownView::Term::TauFx:
        return QPen(palette::channel(Channel::TauFx), 1.5);
    case TorqueBreakdownView::Term::Clipped:
        return QPen(palette::kLimit, 1.5, Qt::DashLine);
    }
    return {};
}

double termValue(const TorqueTerms &t, TorqueBreakdownView::Term term)
{
    switch (term) {
    case TorqueBreakdownView::Term::Inertial:
        return t.inertial;
    case TorqueBreakdownView::Term::Damping:
        return t.damping;
    case TorqueBreakdownView::Term::TauOp:
        return t.tauOp;
    case TorqueBreakdownView::Term::TauRec:
        return t.tauRec;
    case TorqueBreakdownView::Term::TauExt:
        return t.tauExt;
    case TorqueBreakdownView::Term::TauFx:
        return t.tauFx;
    case TorqueBreakdownView::Term::Clipped:
        return t.clipped;
    }
    return 0;
}

} // namespace

QString TorqueBreakdownView::termLabel(Term term)
{
    switch (term) {
    case Term::Inertial:
        return tr("D_adm·ω̇");
    case Term::Damping:
        return tr("M_adm·ω");
    case Term::TauOp:
        return tr("τ_op = −τ");
    case Term::TauRec:
        return tr("τ_rec");
    case Term::TauExt:
        return tr("τ_ext");
    case Term::TauFx:
        return tr("τ_fx");
    case Term::Clipped:
        return tr("clipped");
    }
    return {};
}

TorqueBreakdownView::TorqueBreakdownView(PlotPanel *panel, QWidget *parent)
    : QWidget(parent), m_panel(panel)
{
    m_plot = new QCustomPlot(this);
    m_plot->setObjectName(QStringLiteral("breakdownPlot"));
    m_plot->setMinimumSize(320, 180);
    QCPAxisRect *rect = m_plot->axisRect();
    rect->axis(QCPAxis::atLeft)->setLabel(tr("torque [N·m]"));
    rect->axis(QCPAxis::atBottom)->setLabel(tr("time [s]"));
    QCPAxis *hidden = rect->axis(QCPAxis::atRight);
    hidden->setRange(0, 1);

    m_saturation = m_plot->addGraph(rect->axis(QCPAxis::atBottom), hidden);
    m_saturation->setName(tr("saturated"));
    m_saturation->setLineStyle(QCPGraph::lsStepLeft);
    m_saturation->setPen(Qt::NoPen);
    m_saturation->setBrush(palette::kSaturated);
    for (Term term : kTerms) {
        QCPGraph *g = m_plot->addGraph();
        g->setName(termLabel(term));
        g->setPen(termPen(term));
        m_graphs[static_cast<int>(term)] = g;
    }
    // The legend in rows of three above the plot, never over the curves.
    QCPLegend *legend = m_plot->legend;
    legend->setVisible(true);
    m_plot->axisRect()->insetLayout()->take(legend);
    m_plot->plotLayout()->insertRow(0);
    m_plot->plotLayout()->addElement(0, 0, legend);
    m_plot->plotLayout()->setRowStretchFactor(0, 0.001);
    legend->setWrap(3);
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst); // rearranges the entries by the wrap
    legend->setFont(font());
    legend->setBorderPen(Qt::NoPen);
    legend->setBrush(Qt::NoBrush);
    legend->setMargins(QMargins(4, 2, 4, 0));

    m_notice = new QLabel(this);
    m_notice->setWordWrap(true);
    m_notice->hide();
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_notice);
    layout->addWidget(m_plot, 1);
    setToolTip(tr("The terms of eq. (1), D_adm·ω̇ + M_adm·ω = τ_op + τ_total, over the time "
                  "plots' range. D_adm is the virtual inertia, M_adm the virtual damping; ω̇ "
                  "is the forward difference of ω; τ_op = −τ is the operator's torque; "
                  "τ_fx the effects' (detents, walls, cues), where the device reports it; "
                  "clipped: what the tau_limit clamp removed. Shaded: saturated samples, "
                  "where the device clamped τ_total to tau_limit."));

    connect(panel, &PlotPanel::repainted, this, [this] {
        if (isVisible())
            refresh();
    });
}

QString TorqueBreakdownView::notice() const
{
    return m_notice->isVisible() ? m_notice->text() : QString();
}

void TorqueBreakdownView::refresh()
{
    QCPAxis *x = m_plot->axisRect()->axis(QCPAxis::atBottom);
    const double t0 = m_panel->viewStart();
    const double t1 = std::min(m_panel->viewEnd(), m_panel->dataEnd().value_or(INFINITY));
    x->setRange(t0, m_panel->viewEnd());

    const SampleBuffer *src = m_panel->shownSource();
    const std::optional<DeviceParams> &params = m_panel->deviceParams();
    m_notice->setVisible(!params.has_value());
    if (!params)
        m_notice->setText(tr("D_adm·ω̇ and M_adm·ω need the parameters: connect a device or "
                             "replay a recording."));
    std::array<QVector<QCPGraphData>, kTermCount> data;
    QVector<QCPGraphData> saturation;
    if (src && !src->isEmpty()) {
        const qsizetype first = src->lowerBound(t0);
        const qsizetype last = src->upperBound(t1);
        for (auto &d : data)
            d.reserve(last - first);
        bool saturated = false;
        for (qsizetype i = first; i < last; ++i) {
            // Forward difference (the step this sample's torques drive); backward at the end.
            const qsizetype after = std::min<qsizetype>(i + 1, src->size() - 1);
            const qsizetype before = after == i ? std::max<qsizetype>(i - 1, 0) : i;
            TorqueBalanceInput in;
            in.omega = src->value(Channel::Omega, i);
            in.omegaDot = rateOfChange(src->time(before), src->value(Channel::Omega, before),
                                       src->time(after), src->value(Channel::Omega, after));
            in.tau = src->value(Channel::Tau, i);
            in.tauRec = src->value(Channel::TauRec, i);
            in.tauExt = src->value(Channel::TauExt, i);
            in.tauTotal = src->value(Channel::TauTotal, i);
            // τ_fx is unknown (NaN) from a device without effects: no term, and none in the sum.
            const double fx = src->value(Channel::TauFx, i);
            in.tauFx = std::isfinite(fx) ? fx : 0.0;
            in.saturated = (src->flags(i) & v2::kFlagSaturated) != 0;
            const TorqueTerms terms = torqueTerms(params.value_or(DeviceParams{}), in);
            const double t = src->time(i);
            for (Term term : kTerms) {
                const bool needsParams = term == Term::Inertial || term == Term::Damping;
                if (term == Term::TauFx && !std::isfinite(fx))
                    continue;
                if (!needsParams || params)
                    data[static_cast<int>(term)].append({t, termValue(terms, term)});
            }
            const bool sat = in.saturated;
            if (i == first || sat != saturated)
                saturation.append({t, sat ? 1.0 : 0.0});
            saturated = sat;
        }
        if (last > first)
            saturation.append({src->time(last - 1), saturated ? 1.0 : 0.0});
    }
    double lo = INFINITY;
    double hi = -INFINITY;
    for (Term term : kTerms) {
        for (const QCPGraphData &d : data[static_cast<int>(term)]) {
            if (std::isfinite(d.value)) {
                lo = std::min(lo, d.value);
                hi = std::max(hi, d.value);
            }
        }
        graph(term)->data()->set(data[static_cast<int>(term)], true);
    }
    m_saturation->data()->set(saturation, true);
    if (lo <= hi) {
        const double margin = std::max(0.08 * (hi - lo), 1e-3);
        m_plot->axisRect()->axis(QCPAxis::atLeft)->setRange(lo - margin, hi + margin);
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace hatpic
