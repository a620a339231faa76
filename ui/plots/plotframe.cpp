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
constexpr double kCompactFontScale = 0.85; //!< a compact legend's font against the full one

//! A legend's margins, row spacing and its entries' margins, full or compact. Each entry keeps
//! room below its text: the legend clips an entry to its rect, which would cut the "_".
struct LegendLook
{
    QMargins margins;
    int rowSpacing;
    QMargins entry;
};
constexpr LegendLook kFullLook{{6, 8, 4, 4}, 2, {2, 1, 2, 3}};
constexpr LegendLook kCompactLook{{6, 2, 4, 2}, 0, {2, 0, 2, 2}};

//! The height [px] a legend of `entries` entries in `font` takes with `look`.
int legendHeight(qsizetype entries, const QFont &font, const LegendLook &look)
{
    if (entries == 0)
        return 0;
    const int line = QFontMetrics(font).height() + look.entry.top() + look.entry.bottom();
    return look.margins.top() + look.margins.bottom() + static_cast<int>(entries) * line +
           static_cast<int>(entries - 1) * look.rowSpacing;
}

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
    addGraph(Channel::TauPc, PlotKind::Torque, false);
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
        m_entries[static_cast<int>(PlotKind::Angle)].append(key);
        return key;
    };
    m_deadZoneKey = makeKey(tr("dead zone ±Q_dz"), palette::kDeadZone);
    m_notchKey = makeKey(tr("notch band ±N"), palette::kNotch);
    m_fullFont = m_legends[0]->font();
    fillLegends();

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
    m_entries[static_cast<int>(plot)].append(g);
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
             Channel::TauPc, Channel::TauDet, Channel::TauWall, Channel::TauVib});
    fit(rect(PlotKind::Torque)->axis(QCPAxis::atLeft), lo, hi, kMinSpan[1]);
    collect({Channel::VRef});
    fit(rect(PlotKind::Reference)->axis(QCPAxis::atLeft), lo, hi,
        kMinSpan[2] * units.scale(Channel::VRef));
    collect({Channel::PRef});
    fit(rect(PlotKind::Reference)->axis(QCPAxis::atRight), lo, hi,
        kMinSpan[2] * units.scale(Channel::PRef));
}

bool PlotFrame::fitTickCounts()
{
    bool changed = false;
    for (QCPAxisRect *r : m_rects) {
        const int ticks = std::clamp(r->height() / kTickSpacing, 2, 5);
        for (QCPAxis *y : {r->axis(QCPAxis::atLeft), r->axis(QCPAxis::atRight)}) {
            if (y->ticker()->tickCount() != ticks) {
                y->ticker()->setTickCount(ticks);
                changed = true;
            }
        }
    }
    return changed;
}

int PlotFrame::fullLegendsHeight() const
{
    // A full legend sets its row's height: each row keeps room for three y ticks as well, or
    // a tall legend would squeeze the other plots to a sliver.
    int height = 0;
    for (int i = 0; i < kPlotCount; ++i)
        height +=
            std::max(legendHeight(m_entries[i].size(), m_fullFont, kFullLook), 3 * kTickSpacing);
    // The time axis's labels sit under the last plot, beside no legend.
    return height + m_rects.back()->margins().bottom();
}

bool PlotFrame::fitLegends(int plotHeight)
{
    m_compact = plotHeight < fullLegendsHeight();
    return fillLegends();
}

bool PlotFrame::isShown(const QCPAbstractPlottable *p) const
{
    return isBandKey(p) ? m_bandsVisible : p->visible();
}

bool PlotFrame::fillLegends()
{
    quint64 members = m_compact ? 1 : 0;
    int bit = 1;
    for (const auto &entries : m_entries) {
        for (const QCPAbstractPlottable *p : entries) {
            if (!m_compact || isShown(p))
                members |= quint64{1} << bit;
            ++bit;
        }
    }
    if (members == m_filled)
        return false;
    m_filled = members;

    const LegendLook &look = m_compact ? kCompactLook : kFullLook;
    QFont font = m_fullFont;
    if (m_compact)
        font.setPointSizeF(font.pointSizeF() * kCompactFontScale);
    bit = 1;
    for (int i = 0; i < kPlotCount; ++i) {
        QCPLegend *legend = m_legends[i];
        legend->clearItems();
        legend->setFont(font);
        legend->setMargins(look.margins);
        legend->setRowSpacing(look.rowSpacing);
        for (QCPAbstractPlottable *p : m_entries[i]) {
            if (members & (quint64{1} << bit++))
                p->addToLegend(legend);
        }
        for (int k = 0; k < legend->itemCount(); ++k)
            legend->item(k)->setMargins(look.entry);
    }
    colourLegends();
    return true;
}

void PlotFrame::colourLegends()
{
    for (QCPLegend *legend : m_legends) {
        for (int k = 0; k < legend->itemCount(); ++k) {
            auto *item = qobject_cast<QCPPlottableLegendItem *>(legend->item(k));
            if (!item)
                continue;
            item->setTextColor(isShown(item->plottable())
                                   ? legend->parentPlot()->palette().color(QPalette::Text)
                                   : plottheme::kHiddenLegendText);
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
    m_bandsVisible = bandsVisible;
    if (!fillLegends()) // a series shown or hidden comes in or out of a compact legend
        colourLegends();
}

} // namespace hatpic
