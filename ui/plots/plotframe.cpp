#include "plots/plotframe.h"

#include "plots/displayunits.h"
#include "plots/palette.h"
#include "plots/plotoverlays.h"
#include "plots/plottheme.h"
#include "plots/qcp.h"
#include "plots/samplebuffer.h"

#include <QFontMetrics>

#include <algorithm>
#include <limits>

namespace hatpic {

namespace {

static_assert(PlotFrame::kPlotCount == PlotOverlays::kPlotCount);

//! Smallest span autoscale shows, so that a resting signal is not magnified into noise.
constexpr std::array<double, PlotFrame::kPlotCount> kMinSpan{0.02, 0.01, 0.01}; // SI

//! `axis` fitted to [lo, hi], at least `minSpan` wide, with margins; unchanged while the current
//! range holds the data with a margin and is not much wider.
void fit(QCPAxis *axis, double lo, double hi, double minSpan)
{
    if (!(lo <= hi))
        return;
    if (hi - lo < minSpan) {
        const double mid = (lo + hi) / 2;
        lo = mid - minSpan / 2;
        hi = mid + minSpan / 2;
    }
    const double margin = 0.06 * (hi - lo);
    const QCPRange current = axis->range();
    if (current.lower <= lo - margin && current.upper >= hi + margin &&
        current.size() < 1.6 * (hi - lo + 2 * margin))
        return;
    axis->setRange(lo - 2 * margin, hi + 2 * margin);
}

constexpr int kLegendWidth = 200; //!< [px] at least, fixed so that changing values do not reflow

} // namespace

PlotFrame::PlotFrame(QCustomPlot *plot)
{
    plot->plotLayout()->clear();
    // Wide enough for the longest entry, a Δ of the measuring cursors: icon, gaps, text.
    m_wideLegendWidth = std::max(
        kLegendWidth,
        QFontMetrics(plot->font()).horizontalAdvance(QStringLiteral("τ (measured) Δ −0.0000 N·m")) +
            18 + 36);
    auto *margins = new QCPMarginGroup(plot);
    for (int i = 0; i < kPlotCount; ++i) {
        auto *rect = new QCPAxisRect(plot);
        rect->setupFullAxesBox(false);
        rect->axis(QCPAxis::atTop)->setVisible(false);
        rect->axis(QCPAxis::atRight)->setVisible(false);
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
        rect->axis(QCPAxis::atLeft)->setNumberFormat(QStringLiteral("gb"));
        rect->axis(QCPAxis::atRight)->setNumberFormat(QStringLiteral("gb"));
        rect->setRangeZoomFactor(0.85);
        plot->plotLayout()->addElement(i, 0, rect);
        m_rects[i] = rect;

        // The legend sits at the top of a column beside its plot; a filler takes the rest.
        auto *column = new QCPLayoutGrid;
        plot->plotLayout()->addElement(i, 1, column);
        auto *legend = new QCPLegend;
        column->addElement(0, 0, legend);
        column->addElement(1, 0, new QCPLayoutElement(plot));
        column->setRowStretchFactor(0, 0.001);
        column->setRowStretchFactor(1, 1);
        column->setRowSpacing(0);
        legend->setLayer(QStringLiteral("legend"));
        legend->setVisible(true);
        legend->setBorderPen(Qt::NoPen);
        legend->setBrush(Qt::NoBrush);
        legend->setMinimumSize(kLegendWidth, 0);
        legend->setMaximumSize(kLegendWidth, QWIDGETSIZE_MAX);
        legend->setMargins(QMargins(6, 8, 4, 4));
        legend->setRowSpacing(2);
        legend->setIconSize(18, 10);
        m_legends[i] = legend;

        if (i + 1 < kPlotCount) {
            rect->axis(QCPAxis::atBottom)->setTickLabels(false);
            rect->setAutoMargins(QCP::msLeft | QCP::msRight | QCP::msTop);
            rect->setMargins(QMargins(0, 0, 0, 6));
        }
    }
    plot->plotLayout()->setColumnStretchFactor(0, 1);
    plot->plotLayout()->setColumnStretchFactor(1, 0.01);
    plot->plotLayout()->setColumnSpacing(0);
    plot->plotLayout()->setRowSpacing(0);

    addGraph(Channel::Theta, PlotKind::Angle, false);
    addGraph(Channel::Omega, PlotKind::Angle, true);
    addGraph(Channel::Tau, PlotKind::Torque, false);
    addGraph(Channel::TauRec, PlotKind::Torque, false);
    addGraph(Channel::TauExt, PlotKind::Torque, false);
    addGraph(Channel::TauTotal, PlotKind::Torque, false);
    addGraph(Channel::TauFx, PlotKind::Torque, false);
    addGraph(Channel::TauDet, PlotKind::Torque, false);
    addGraph(Channel::TauWall, PlotKind::Torque, false);
    addGraph(Channel::TauVib, PlotKind::Torque, false);
    addGraph(Channel::VRef, PlotKind::Reference, false);
    addGraph(Channel::PRef, PlotKind::Reference, true);
    // τ_total = τ_rec + τ_ext lies exactly on τ_rec while τ_ext = 0: τ_rec goes wide underneath,
    // τ_total dashed on top, so both stay visible. In a robot's wall τ_ext equals τ_rec (the
    // teleoperation demo's equilibrium): τ_ext, drawn after τ_rec, is 2 px inside τ_rec's 4, so
    // the wall's push shows in its own colour with τ_rec on both sides (issue 27: a 1 px τ_ext
    // vanished in a 3 px τ_rec). The two wide pens cost as the one did (docs/performance.md).
    graph(Channel::TauRec)->setPen(QPen(palette::channel(Channel::TauRec), 4.0));
    graph(Channel::TauExt)->setPen(QPen(palette::channel(Channel::TauExt), 2.0));
    graph(Channel::TauTotal)->setPen(QPen(palette::channel(Channel::TauTotal), 1.0, Qt::DashLine));
    graph(Channel::Omega)->setVisible(false);
    // τ_fx's parts, off until asked for: τ_fx's colour, each in its own line style.
    const std::pair<Channel, Qt::PenStyle> parts[] = {{Channel::TauDet, Qt::DashLine},
                                                      {Channel::TauWall, Qt::DotLine},
                                                      {Channel::TauVib, Qt::DashDotLine}};
    for (const auto &[channel, style] : parts) {
        graph(channel)->setPen(QPen(palette::channel(channel), 1.0, style));
        graph(channel)->setVisible(false);
    }

    QCPAxisRect *angle = rect(PlotKind::Angle);
    auto makeKey = [&](const QString &name, const QColor &color) {
        auto *key = new QCPGraph(angle->axis(QCPAxis::atBottom), angle->axis(QCPAxis::atLeft));
        key->setName(name);
        key->setPen(Qt::NoPen);
        key->setBrush(QColor(color.red(), color.green(), color.blue(), 140));
        key->removeFromLegend();
        key->addToLegend(legend(PlotKind::Angle));
        return key;
    };
    m_deadZoneKey = makeKey(tr("dead zone ±Q_dz"), palette::kDeadZone);
    m_notchKey = makeKey(tr("notch band ±N"), palette::kNotch);
    // Room below the text: the legend clips each item to its rect, which would cut the "_".
    for (QCPLegend *legend : m_legends) {
        for (int k = 0; k < legend->itemCount(); ++k)
            legend->item(k)->setMargins(QMargins(2, 1, 2, 3));
    }

    // Ranges that make sense before any data arrive (autoscale takes over with the data).
    rect(PlotKind::Angle)->axis(QCPAxis::atLeft)->setRange(-0.5, 0.5);
    rect(PlotKind::Angle)->axis(QCPAxis::atRight)->setRange(-2, 2);
    rect(PlotKind::Torque)->axis(QCPAxis::atLeft)->setRange(-0.1, 0.1);
    rect(PlotKind::Reference)->axis(QCPAxis::atLeft)->setRange(-0.5, 0.5);
    rect(PlotKind::Reference)->axis(QCPAxis::atRight)->setRange(-0.5, 0.5);
}

void PlotFrame::addGraph(Channel channel, PlotKind plot, bool rightAxis)
{
    QCPAxisRect *r = rect(plot);
    QCPAxis *y = r->axis(rightAxis ? QCPAxis::atRight : QCPAxis::atLeft);
    auto *g = new QCPGraph(r->axis(QCPAxis::atBottom), y);
    g->setName(channelLabel(channel));
    // 1 px: Qt draws it with its fast cosmetic stroker; a wider pen is outlined and filled
    // as a polygon, which doubled the cost of a frame (docs/performance.md).
    g->setPen(QPen(palette::channel(channel), 1.0));
    g->setAdaptiveSampling(false); // the Decimator already reduced the data to the pixels
    g->removeFromLegend();
    g->addToLegend(legend(plot));
    m_graphs[channelIndex(channel)] = g;
}

void PlotFrame::setAxisLabels(const DisplayUnits &units)
{
    rect(PlotKind::Angle)
        ->axis(QCPAxis::atLeft)
        ->setLabel(tr("θ [%1]").arg(units.unit(Channel::Theta)));
    // setupFullAxesBox hid the right axes' tick labels; ω and p_ref need theirs.
    QCPAxis *omega = rect(PlotKind::Angle)->axis(QCPAxis::atRight);
    omega->setLabel(tr("ω [%1]").arg(units.unit(Channel::Omega)));
    omega->setTickLabels(true);
    rect(PlotKind::Torque)->axis(QCPAxis::atLeft)->setLabel(tr("torque [N·m]"));
    rect(PlotKind::Reference)
        ->axis(QCPAxis::atLeft)
        ->setLabel(tr("v_ref [%1]").arg(units.unit(Channel::VRef)));
    QCPAxis *p = rect(PlotKind::Reference)->axis(QCPAxis::atRight);
    p->setLabel(tr("p_ref [%1]").arg(units.unit(Channel::PRef)));
    p->setVisible(true);
    p->setTickLabels(true);
    rect(PlotKind::Reference)->axis(QCPAxis::atBottom)->setLabel(tr("time [s]"));
}

void PlotFrame::rescaleAxes(const DisplayUnits &before, const DisplayUnits &after)
{
    auto rescale = [&](QCPAxis *axis, Channel channel) {
        const double factor = after.scale(channel) / before.scale(channel);
        if (factor != 1.0)
            axis->setRange(axis->range().lower * factor, axis->range().upper * factor);
    };
    rescale(rect(PlotKind::Angle)->axis(QCPAxis::atLeft), Channel::Theta);
    rescale(rect(PlotKind::Angle)->axis(QCPAxis::atRight), Channel::Omega);
    rescale(rect(PlotKind::Reference)->axis(QCPAxis::atLeft), Channel::VRef);
    rescale(rect(PlotKind::Reference)->axis(QCPAxis::atRight), Channel::PRef);
}

void PlotFrame::autoscale(const std::array<DecimationResult, kChannelCount> &ranges,
                          const DisplayUnits &units, const std::optional<DeviceParams> &bands)
{
    double lo;
    double hi;
    auto collect = [&](std::initializer_list<Channel> channels) {
        lo = std::numeric_limits<double>::infinity();
        hi = -lo;
        for (Channel channel : channels) {
            const DecimationResult &r = ranges[channelIndex(channel)];
            if (r.hasValues && graph(channel)->visible()) {
                lo = std::min(lo, r.min);
                hi = std::max(hi, r.max);
            }
        }
    };
    const double angleScale = units.scale(Channel::Theta);
    collect({Channel::Theta});
    if (bands && lo <= hi) {
        // Keep the notch band in sight so the operator sees where the knob is relative to it.
        lo = std::min(lo, (bands->theta0 - bands->N) * angleScale);
        hi = std::max(hi, (bands->theta0 + bands->N) * angleScale);
    }
    fit(rect(PlotKind::Angle)->axis(QCPAxis::atLeft), lo, hi, kMinSpan[0] * angleScale);
    collect({Channel::Omega});
    fit(rect(PlotKind::Angle)->axis(QCPAxis::atRight), lo, hi, 0.1 * angleScale);
    collect({Channel::Tau, Channel::TauRec, Channel::TauExt, Channel::TauTotal, Channel::TauFx,
             Channel::TauDet, Channel::TauWall, Channel::TauVib});
    fit(rect(PlotKind::Torque)->axis(QCPAxis::atLeft), lo, hi, kMinSpan[1]);
    collect({Channel::VRef});
    fit(rect(PlotKind::Reference)->axis(QCPAxis::atLeft), lo, hi,
        kMinSpan[2] * units.scale(Channel::VRef));
    collect({Channel::PRef});
    fit(rect(PlotKind::Reference)->axis(QCPAxis::atRight), lo, hi,
        kMinSpan[2] * units.scale(Channel::PRef));
}

void PlotFrame::fitTickCounts()
{
    for (QCPAxisRect *r : m_rects) {
        const int ticks = std::clamp(r->height() / kTickSpacing, 2, 5);
        for (QCPAxis *y : {r->axis(QCPAxis::atLeft), r->axis(QCPAxis::atRight)}) {
            if (y->ticker()->tickCount() != ticks)
                y->ticker()->setTickCount(ticks);
        }
    }
}

void PlotFrame::setWideLegends(bool wide)
{
    const int width = wide ? m_wideLegendWidth : kLegendWidth;
    for (QCPLegend *legend : m_legends) {
        legend->setMinimumSize(width, 0);
        legend->setMaximumSize(width, QWIDGETSIZE_MAX);
    }
}

bool PlotFrame::isBandKey(const QCPAbstractPlottable *plottable) const
{
    return plottable == m_deadZoneKey || plottable == m_notchKey;
}

std::optional<Channel> PlotFrame::channelOf(const QCPAbstractPlottable *plottable) const
{
    for (Channel channel : kAllChannels) {
        if (graph(channel) == plottable)
            return channel;
    }
    return std::nullopt;
}

void PlotFrame::updateLegends(const SampleBuffer *source, qsizetype index,
                              const DisplayUnits &units, bool bandsVisible)
{
    for (Channel channel : kAllChannels) {
        QCPGraph *g = graph(channel);
        QString name = channelLabel(channel);
        if (source && index >= 0 && g->visible())
            name += u"  " % units.format(channel, source->value(channel, index));
        g->setName(name);
    }
    for (QCPLegend *legend : m_legends) {
        for (int k = 0; k < legend->itemCount(); ++k) {
            auto *item = qobject_cast<QCPPlottableLegendItem *>(legend->item(k));
            if (!item)
                continue;
            const QCPAbstractPlottable *p = item->plottable();
            const bool on = isBandKey(p) ? bandsVisible : p->visible();
            item->setTextColor(on ? legend->parentPlot()->palette().color(QPalette::Text)
                                  : plottheme::kHiddenLegendText);
        }
    }
}

} // namespace hatpic
