#include "plots/plotpanel.h"

#include "plots/logging.h"
#include "plots/plotoverlays.h"
#include "plots/qcp.h"
#include "plots/samplecsvwriter.h"

#include <QFileInfo>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace hatpic {

namespace {

static_assert(PlotPanel::kPlotCount == PlotOverlays::kPlotCount);

//! Smallest span autoscale shows, so that a resting signal is not magnified into noise.
constexpr std::array<double, PlotPanel::kPlotCount> kMinSpan{0.02, 0.01, 0.01}; // SI

constexpr int kLegendWidth = 200; //!< [px], fixed so that changing values do not reflow

} // namespace

PlotPanel::PlotPanel(QWidget *parent) : QWidget(parent)
{
    m_plot = new QCustomPlot(this);
    m_plot->setObjectName(QStringLiteral("plots"));
    m_plot->setMouseTracking(true);
    m_plot->installEventFilter(this);
    m_plot->setNoAntialiasingOnDrag(true);
    m_plot->setPlottingHint(QCP::phFastPolylines, true);
    m_plot->setFocusPolicy(Qt::ClickFocus); // so Space pauses after a click on the plots
    m_plot->setMinimumHeight(300);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    buildPlots();

    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &PlotPanel::repaintIfNeeded);
    setRepaintRate(kDefaultRepaintHz);
    m_timer->start();
    m_rateClock.start();
}

PlotPanel::~PlotPanel() = default;

void PlotPanel::buildPlots()
{
    m_plot->plotLayout()->clear();
    auto *margins = new QCPMarginGroup(m_plot);
    for (int i = 0; i < kPlotCount; ++i) {
        auto *rect = new QCPAxisRect(m_plot);
        rect->setupFullAxesBox(false);
        rect->axis(QCPAxis::atTop)->setVisible(false);
        rect->axis(QCPAxis::atRight)->setVisible(false);
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
        rect->axis(QCPAxis::atLeft)->setNumberFormat(QStringLiteral("gb"));
        rect->axis(QCPAxis::atRight)->setNumberFormat(QStringLiteral("gb"));
        rect->setRangeZoomFactor(0.85);
        m_plot->plotLayout()->addElement(i, 0, rect);
        m_rects[i] = rect;

        // The legend sits at the top of a column beside its plot; a filler takes the rest.
        auto *column = new QCPLayoutGrid;
        m_plot->plotLayout()->addElement(i, 1, column);
        auto *legend = new QCPLegend;
        column->addElement(0, 0, legend);
        column->addElement(1, 0, new QCPLayoutElement(m_plot));
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

        QCPAxis *x = rect->axis(QCPAxis::atBottom);
        connect(x, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this,
                [this, i] { onXRangeChanged(i); });
        for (QCPAxis *y : {rect->axis(QCPAxis::atLeft), rect->axis(QCPAxis::atRight)})
            connect(y, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this,
                    [this] { m_replotNeeded = true; });
        if (i + 1 < kPlotCount) {
            x->setTickLabels(false);
            rect->setAutoMargins(QCP::msLeft | QCP::msRight | QCP::msTop);
            rect->setMargins(QMargins(0, 0, 0, 6));
        }
    }
    m_plot->plotLayout()->setColumnStretchFactor(0, 1);
    m_plot->plotLayout()->setColumnStretchFactor(1, 0.01);
    m_plot->plotLayout()->setColumnSpacing(0);
    m_plot->plotLayout()->setRowSpacing(0);

    addGraph(Channel::Theta, Plot::Angle, QColor(21, 101, 192), false);
    addGraph(Channel::Omega, Plot::Angle, QColor(0, 151, 167), true);
    addGraph(Channel::Tau, Plot::Torque, QColor(97, 97, 97), false);
    addGraph(Channel::TauRec, Plot::Torque, QColor(21, 101, 192), false);
    addGraph(Channel::TauExt, Plot::Torque, QColor(46, 125, 50), false);
    addGraph(Channel::TauTotal, Plot::Torque, QColor(230, 81, 0), false);
    addGraph(Channel::VRef, Plot::Reference, QColor(123, 31, 162), false);
    addGraph(Channel::PRef, Plot::Reference, QColor(0, 121, 107), true);
    graph(Channel::Omega)->setVisible(false);

    m_overlays = std::make_unique<PlotOverlays>(m_plot, m_rects);

    QCPAxisRect *angle = axisRect(Plot::Angle);
    auto makeKey = [&](const QString &name, const QColor &color) {
        auto *key = new QCPGraph(angle->axis(QCPAxis::atBottom), angle->axis(QCPAxis::atLeft));
        key->setName(name);
        key->setPen(Qt::NoPen);
        key->setBrush(QColor(color.red(), color.green(), color.blue(), 140));
        key->removeFromLegend();
        key->addToLegend(legend(Plot::Angle));
        return key;
    };
    m_deadZoneKey = makeKey(tr("dead zone ±Q_dz"), PlotOverlays::kDeadZoneColor);
    m_notchKey = makeKey(tr("notch band ±N"), PlotOverlays::kNotchColor);
    // Room below the text: the legend clips each item to its rect, which would cut the "_".
    for (QCPLegend *legend : m_legends) {
        for (int k = 0; k < legend->itemCount(); ++k)
            legend->item(k)->setMargins(QMargins(2, 1, 2, 3));
    }

    connect(m_plot, &QCustomPlot::legendClick, this,
            [this](QCPLegend *legend, QCPAbstractLegendItem *item, QMouseEvent *) {
                onLegendClick(legend, item);
            });
    connect(m_plot, &QCustomPlot::mouseMove, this, [this](QMouseEvent *event) {
        const QPointF pos = event->position();
        for (QCPAxisRect *rect : m_rects) {
            if (rect->rect().contains(pos.toPoint())) {
                setCursorTime(rect->axis(QCPAxis::atBottom)->pixelToCoord(pos.x()));
                return;
            }
        }
        setCursorTime(std::nullopt);
    });

    // Ranges that make sense before any data arrive (autoscale takes over with the data).
    axisRect(Plot::Angle)->axis(QCPAxis::atLeft)->setRange(-0.5, 0.5);
    axisRect(Plot::Angle)->axis(QCPAxis::atRight)->setRange(-2, 2);
    axisRect(Plot::Torque)->axis(QCPAxis::atLeft)->setRange(-0.1, 0.1);
    axisRect(Plot::Reference)->axis(QCPAxis::atLeft)->setRange(-0.5, 0.5);
    axisRect(Plot::Reference)->axis(QCPAxis::atRight)->setRange(-0.5, 0.5);
    updateLabels();
    updateBands();
    updateInteractions();
    applyXRange(0, m_window);
}

void PlotPanel::addGraph(Channel channel, Plot plot, const QColor &color, bool rightAxis)
{
    QCPAxisRect *rect = axisRect(plot);
    QCPAxis *y = rect->axis(rightAxis ? QCPAxis::atRight : QCPAxis::atLeft);
    auto *g = new QCPGraph(rect->axis(QCPAxis::atBottom), y);
    g->setName(channelLabel(channel));
    // 1 px: Qt draws it with its fast cosmetic stroker; a wider pen is outlined and filled
    // as a polygon, which doubled the cost of a frame (docs/performance.md).
    g->setPen(QPen(color, 1.0));
    g->setAdaptiveSampling(false); // the Decimator already reduced the data to the pixels
    g->removeFromLegend();
    g->addToLegend(legend(plot));
    m_graphs[channelIndex(channel)] = g;
}

void PlotPanel::setSource(const SampleBuffer *buffer)
{
    m_source = buffer;
    m_dataDirty = true;
}

const SampleBuffer *PlotPanel::drawSource() const
{
    return m_paused ? &m_frozen : m_source;
}

void PlotPanel::setWindowLength(double seconds)
{
    if (!(seconds > 0) || seconds == m_window)
        return;
    m_window = seconds;
    const double end = viewEnd();
    applyXRange(end - m_window, end);
    m_dataDirty = true;
}

void PlotPanel::setFollowLatest(bool follow)
{
    m_follow = follow;
    updateInteractions();
    m_dataDirty = true;
}

void PlotPanel::setViewEnd(double t)
{
    applyXRange(t - m_window, t);
    m_dataDirty = true;
}

double PlotPanel::viewStart() const
{
    return m_rects[0]->axis(QCPAxis::atBottom)->range().lower;
}

void PlotPanel::setDataEnd(std::optional<double> t)
{
    if (t == m_dataEnd)
        return;
    m_dataEnd = t;
    m_dataDirty = true;
}

double PlotPanel::dataEdge() const
{
    return m_dataEnd ? std::min(*m_dataEnd, viewEnd()) : viewEnd();
}

double PlotPanel::viewEnd() const
{
    return m_rects[0]->axis(QCPAxis::atBottom)->range().upper;
}

void PlotPanel::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    if (paused) {
        m_frozen = m_source ? *m_source : SampleBuffer(1);
    } else {
        m_frozen = SampleBuffer(1); // give the memory back
    }
    m_paused = paused;
    updateInteractions();
    m_dataDirty = true;
    Q_EMIT pausedChanged(paused);
}

void PlotPanel::setAutoscale(bool on)
{
    if (on == m_autoscale)
        return;
    m_autoscale = on;
    updateInteractions();
    m_dataDirty = true;
    Q_EMIT autoscaleChanged(on);
}

void PlotPanel::setAngleInDegrees(bool degrees)
{
    if (degrees == m_units.degrees())
        return;
    // Fixed ranges keep showing the same quantities in the new unit.
    const DisplayUnits before = m_units;
    m_units.setDegrees(degrees);
    rescaleAxes(before);
    updateLabels();
    updateBands();
    m_dataDirty = true;
}

void PlotPanel::rescaleAxes(const DisplayUnits &before)
{
    auto rescale = [&](QCPAxis *axis, Channel channel) {
        const double factor = m_units.scale(channel) / before.scale(channel);
        if (factor != 1.0)
            axis->setRange(axis->range().lower * factor, axis->range().upper * factor);
    };
    rescale(axisRect(Plot::Angle)->axis(QCPAxis::atLeft), Channel::Theta);
    rescale(axisRect(Plot::Angle)->axis(QCPAxis::atRight), Channel::Omega);
    rescale(axisRect(Plot::Reference)->axis(QCPAxis::atLeft), Channel::VRef);
    rescale(axisRect(Plot::Reference)->axis(QCPAxis::atRight), Channel::PRef);
}

void PlotPanel::setDeviceParams(const std::optional<DeviceParams> &params)
{
    m_params = params;
    updateBands();
    m_dataDirty = true;
}

void PlotPanel::setHostParams(const HostParams &host)
{
    if (host.mode == m_units.mode())
        return;
    const DisplayUnits before = m_units;
    m_units.setMode(host.mode);
    rescaleAxes(before);
    updateLabels();
    m_dataDirty = true;
}

void PlotPanel::setChannelVisible(Channel channel, bool visible)
{
    QCPGraph *g = graph(channel);
    if (g->visible() == visible)
        return;
    g->setVisible(visible);
    if (!visible)
        g->data()->clear();
    if (channel == Channel::Omega)
        axisRect(Plot::Angle)->axis(QCPAxis::atRight)->setVisible(visible);
    updateLegendTexts();
    m_dataDirty = true;
    Q_EMIT channelVisibilityChanged(channel, visible);
}

bool PlotPanel::isChannelVisible(Channel channel) const
{
    return graph(channel)->visible();
}

void PlotPanel::setBandsVisible(bool visible)
{
    if (visible == m_bandsVisible)
        return;
    m_bandsVisible = visible;
    updateBands();
    updateLegendTexts();
    m_dataDirty = true;
    Q_EMIT bandsVisibilityChanged(visible);
}

void PlotPanel::setEvents(const QList<RecordingEvent> &events)
{
    m_events = events;
    rebuildEvents();
}

void PlotPanel::addEvent(const RecordingEvent &event)
{
    m_events.append(event);
    rebuildEvents();
}

void PlotPanel::rebuildEvents()
{
    m_overlays->setEvents(m_events, QFont(font().family(), std::max(font().pointSize() - 1, 7)));
    m_replotNeeded = true;
}

void PlotPanel::setCursorTime(std::optional<double> t)
{
    if (t == m_cursor)
        return;
    m_cursor = t;
    m_overlays->setCursor(m_cursor);
    updateLegendTexts();
    m_replotNeeded = true;
}

void PlotPanel::updateLabels()
{
    const QString angleUnit = m_units.unit(Channel::Theta);
    axisRect(Plot::Angle)->axis(QCPAxis::atLeft)->setLabel(tr("θ [%1]").arg(angleUnit));
    axisRect(Plot::Angle)
        ->axis(QCPAxis::atRight)
        ->setLabel(tr("ω [%1]").arg(m_units.unit(Channel::Omega)));
    axisRect(Plot::Torque)->axis(QCPAxis::atLeft)->setLabel(tr("torque [N·m]"));
    axisRect(Plot::Reference)
        ->axis(QCPAxis::atLeft)
        ->setLabel(tr("v_ref [%1]").arg(m_units.unit(Channel::VRef)));
    QCPAxis *p = axisRect(Plot::Reference)->axis(QCPAxis::atRight);
    p->setLabel(tr("p_ref [%1]").arg(m_units.unit(Channel::PRef)));
    p->setVisible(true);
    p->setTickLabels(true);
    axisRect(Plot::Reference)->axis(QCPAxis::atBottom)->setLabel(tr("time [s]"));
    updateLegendTexts();
}

void PlotPanel::updateBands()
{
    m_overlays->setBands(m_params, m_units.scale(Channel::Theta), m_bandsVisible);
}

void PlotPanel::updateInteractions()
{
    const bool dragX = !followsLatest();
    const bool dragY = !m_autoscale;
    m_plot->setInteractions(dragX || dragY ? QCP::iRangeDrag | QCP::iRangeZoom
                                           : QCP::Interactions());
    for (QCPAxisRect *rect : m_rects) {
        QList<QCPAxis *> horizontal;
        QList<QCPAxis *> vertical;
        if (dragX)
            horizontal << rect->axis(QCPAxis::atBottom);
        if (dragY)
            vertical << rect->axis(QCPAxis::atLeft) << rect->axis(QCPAxis::atRight);
        rect->setRangeDragAxes(horizontal, vertical);
        rect->setRangeZoomAxes(horizontal, vertical);
        Qt::Orientations orientations;
        if (dragX)
            orientations |= Qt::Horizontal;
        if (dragY)
            orientations |= Qt::Vertical;
        rect->setRangeDrag(orientations);
        rect->setRangeZoom(orientations);
    }
}

void PlotPanel::applyXRange(double start, double end)
{
    m_settingRange = true;
    for (QCPAxisRect *rect : m_rects)
        rect->axis(QCPAxis::atBottom)->setRange(start, end);
    m_settingRange = false;
    m_replotNeeded = true;
}

void PlotPanel::onXRangeChanged(int plotIndex)
{
    if (m_settingRange)
        return;
    // The user dragged or zoomed one plot: the others follow, the data is decimated again.
    const QCPRange range = m_rects[plotIndex]->axis(QCPAxis::atBottom)->range();
    applyXRange(range.lower, range.upper);
    m_dataDirty = true;
}

void PlotPanel::setRepaintRate(double hz)
{
    m_timer->setInterval(std::max(1, static_cast<int>(std::lround(1000.0 / std::max(hz, 1.0)))));
}

double PlotPanel::repaintRate() const
{
    return 1000.0 / m_timer->interval();
}

qsizetype PlotPanel::pointCount(Channel channel) const
{
    return graph(channel)->data()->size();
}

void PlotPanel::repaintIfNeeded()
{
    const SampleBuffer *src = drawSource();
    const bool newData = src && (src != m_drawnSource || src->generation() != m_drawnGeneration);
    if (newData)
        m_dataDirty = true;
    if (!m_dataDirty && !m_replotNeeded) {
        logRate();
        return;
    }
    if (followsLatest() && src && !src->isEmpty()) {
        // Until the data fill the window, the window starts at the first sample (a sweep
        // from the left); then it scrolls with the newest one.
        const double end = std::max(src->lastTime(), src->firstTime() + m_window);
        applyXRange(end - m_window, end);
    }
    QElapsedTimer clock;
    clock.start();
    if (m_dataDirty)
        rebuildData();
    m_stats.lastDecimateMs = clock.nsecsElapsed() / 1e6;
    if (m_autoscale)
        autoscaleAxes();
    updateLegendTexts();
    m_overlays->fitEventLabels();
    clock.restart();
    m_plot->replot(QCustomPlot::rpQueuedRefresh);
    m_laidOutSize = m_plot->size();
    m_stats.lastReplotMs = clock.nsecsElapsed() / 1e6;
    ++m_stats.replots;
    m_replotNeeded = false;
    Q_EMIT repainted();
    logRate();
}

void PlotPanel::repaintNow()
{
    m_dataDirty = true;
    repaintIfNeeded();
}

void PlotPanel::rebuildData()
{
    const SampleBuffer *src = drawSource();
    m_drawnSource = src;
    m_drawnGeneration = src ? src->generation() : 0;
    m_dataDirty = false;
    // The axis rects are laid out by replot(); until the first replot at the current widget
    // size, the widget width is a safe upper bound of the plot width.
    const int pixels = m_laidOutSize == m_plot->size() ? m_rects[0]->width() : m_plot->width();
    m_decimator.setPixels(std::max(pixels, 100));
    const double t0 = viewStart();
    const double t1 = dataEdge();
    m_stats.lastPoints = 0;
    for (Channel channel : kAllChannels) {
        QCPGraph *g = graph(channel);
        m_ranges[channelIndex(channel)] = {};
        if (!g->visible() || !src) {
            g->data()->clear();
            continue;
        }
        m_points = QVector<QCPGraphData>(); // the graph shares the previous vector
        m_ranges[channelIndex(channel)] =
            m_decimator.run(*src, channel, t0, t1, m_units.scale(channel), m_points);
        g->data()->set(m_points, true);
        m_stats.lastPoints += m_points.size();
    }
}

void PlotPanel::autoscaleAxes()
{
    auto fit = [](QCPAxis *axis, double lo, double hi, double minSpan) {
        if (!(lo <= hi))
            return;
        if (hi - lo < minSpan) {
            const double mid = (lo + hi) / 2;
            lo = mid - minSpan / 2;
            hi = mid + minSpan / 2;
        }
        const double margin = 0.06 * (hi - lo);
        // Hysteresis: keep the current range while it holds the data with a margin and is not
        // much wider, so the axes do not breathe with every repaint.
        const QCPRange current = axis->range();
        if (current.lower <= lo - margin && current.upper >= hi + margin &&
            current.size() < 1.6 * (hi - lo + 2 * margin))
            return;
        axis->setRange(lo - 2 * margin, hi + 2 * margin);
    };
    auto collect = [this](std::initializer_list<Channel> channels, double &lo, double &hi) {
        lo = std::numeric_limits<double>::infinity();
        hi = -lo;
        for (Channel channel : channels) {
            const DecimationResult &r = m_ranges[channelIndex(channel)];
            if (r.hasValues && isChannelVisible(channel)) {
                lo = std::min(lo, r.min);
                hi = std::max(hi, r.max);
            }
        }
    };
    const double angleScale = m_units.scale(Channel::Theta);
    double lo;
    double hi;
    collect({Channel::Theta}, lo, hi);
    if (m_params && m_bandsVisible && lo <= hi) {
        // Keep the notch band in sight so the operator sees where the knob is relative to it.
        lo = std::min(lo, (m_params->theta0 - m_params->N) * angleScale);
        hi = std::max(hi, (m_params->theta0 + m_params->N) * angleScale);
    }
    fit(axisRect(Plot::Angle)->axis(QCPAxis::atLeft), lo, hi, kMinSpan[0] * angleScale);
    collect({Channel::Omega}, lo, hi);
    fit(axisRect(Plot::Angle)->axis(QCPAxis::atRight), lo, hi, 0.1 * angleScale);
    collect({Channel::Tau, Channel::TauRec, Channel::TauExt, Channel::TauTotal}, lo, hi);
    fit(axisRect(Plot::Torque)->axis(QCPAxis::atLeft), lo, hi, kMinSpan[1]);
    collect({Channel::VRef}, lo, hi);
    fit(axisRect(Plot::Reference)->axis(QCPAxis::atLeft), lo, hi,
        kMinSpan[2] * m_units.scale(Channel::VRef));
    collect({Channel::PRef}, lo, hi);
    fit(axisRect(Plot::Reference)->axis(QCPAxis::atRight), lo, hi,
        kMinSpan[2] * m_units.scale(Channel::PRef));
}

void PlotPanel::updateLegendTexts()
{
    const SampleBuffer *src = drawSource();
    qsizetype index = -1;
    if (src && !src->isEmpty()) {
        if (m_cursor) {
            index = src->nearest(*m_cursor);
        } else {
            const qsizetype end = src->upperBound(dataEdge());
            index = end > 0 && src->time(end - 1) >= viewStart() ? end - 1 : -1;
        }
    }
    for (Channel channel : kAllChannels) {
        QCPGraph *g = graph(channel);
        QString name = channelLabel(channel);
        if (index >= 0 && g->visible())
            name += u"  " % m_units.format(channel, src->value(channel, index));
        g->setName(name);
    }
    for (int i = 0; i < kPlotCount; ++i) {
        QCPLegend *legend = m_legends[i];
        for (int k = 0; k < legend->itemCount(); ++k) {
            auto *item = qobject_cast<QCPPlottableLegendItem *>(legend->item(k));
            if (!item)
                continue;
            const QCPAbstractPlottable *p = item->plottable();
            const bool on = (p == m_deadZoneKey || p == m_notchKey) ? m_bandsVisible : p->visible();
            item->setTextColor(on ? QColor(Qt::black) : QColor(160, 160, 160));
        }
    }
}

QString PlotPanel::readout() const
{
    const SampleBuffer *src = drawSource();
    if (!src || src->isEmpty())
        return {};
    qsizetype index;
    if (m_cursor) {
        index = src->nearest(*m_cursor);
    } else {
        const qsizetype end = src->upperBound(dataEdge());
        if (end == 0)
            return {};
        index = end - 1;
    }
    QStringList parts{QStringLiteral("t = %1 s").arg(src->time(index), 0, 'f', 3)};
    for (Channel channel : kAllChannels) {
        if (isChannelVisible(channel))
            parts << channelLabel(channel) % u" = " %
                         m_units.format(channel, src->value(channel, index));
    }
    return parts.join(QStringLiteral("; "));
}

void PlotPanel::onLegendClick(QCPLegend *, QCPAbstractLegendItem *item)
{
    auto *plottableItem = qobject_cast<QCPPlottableLegendItem *>(item);
    if (!plottableItem)
        return;
    QCPAbstractPlottable *p = plottableItem->plottable();
    if (p == m_deadZoneKey || p == m_notchKey) {
        setBandsVisible(!m_bandsVisible);
        return;
    }
    for (Channel channel : kAllChannels) {
        if (graph(channel) == p) {
            setChannelVisible(channel, !isChannelVisible(channel));
            return;
        }
    }
}

bool PlotPanel::exportImage(const QString &path, QString *error)
{
    repaintIfNeeded();
    const bool pdf = QFileInfo(path).suffix().compare(u"pdf", Qt::CaseInsensitive) == 0;
    const bool ok = pdf ? m_plot->savePdf(path) : m_plot->savePng(path);
    if (!ok && error)
        *error = tr("Could not write %1.").arg(path);
    return ok;
}

qsizetype PlotPanel::exportCsv(const QString &path, QString *error) const
{
    const SampleBuffer *src = drawSource();
    if (!src) {
        if (error)
            *error = tr("There is no data to export.");
        return -1;
    }
    return SampleCsvWriter::write(*src, viewStart(), dataEdge(), path, error);
}

bool PlotPanel::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_plot && event->type() == QEvent::Leave)
        setCursorTime(std::nullopt);
    return QWidget::eventFilter(watched, event);
}

void PlotPanel::logRate()
{
    const qint64 ms = m_rateClock.elapsed();
    if (ms < 5000)
        return;
    const double rate = (m_stats.replots - m_rateReplots) * 1000.0 / ms;
    qCDebug(lcPlots).nospace() << "repaint rate " << rate << " Hz; last decimate "
                               << m_stats.lastDecimateMs << " ms, replot " << m_stats.lastReplotMs
                               << " ms, " << m_stats.lastPoints << " points";
    m_rateReplots = m_stats.replots;
    m_rateClock.restart();
}

} // namespace hatpic
