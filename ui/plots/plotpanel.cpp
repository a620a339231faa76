#include "plots/plotpanel.h"

#include "plots/logging.h"
#include "plots/measurecursors.h"
#include "plots/plotframe.h"
#include "plots/plotghost.h"
#include "plots/plotoverlays.h"
#include "plots/plottheme.h"
#include "plots/qcp.h"
#include "plots/samplecsvwriter.h"

#include <QTimer>
#include <QToolTip>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace hatpic {

PlotPanel::PlotPanel(QWidget *parent) : QWidget(parent)
{
    m_plot = new QCustomPlot(this);
    m_plot->setObjectName(QStringLiteral("plots"));
    m_plot->setMouseTracking(true);
    m_plot->installEventFilter(this);
    m_plot->setNoAntialiasingOnDrag(true);
    m_plot->setPlottingHint(QCP::phFastPolylines, true);
    m_plot->setFocusPolicy(Qt::ClickFocus); // so Space pauses after a click on the plots
    m_plot->setMinimumHeight(kMinPlotsHeight);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    buildPlots();
    plottheme::follow(m_plot);

    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &PlotPanel::repaintIfNeeded);
    setRepaintRate(kDefaultRepaintHz);
    m_timer->start();
}

PlotPanel::~PlotPanel() = default;

void PlotPanel::buildPlots()
{
    m_frame = std::make_unique<PlotFrame>(m_plot);
    for (int i = 0; i < kPlotCount; ++i) {
        QCPAxisRect *rect = m_frame->rects()[i];
        QCPAxis *x = rect->axis(QCPAxis::atBottom);
        connect(x, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this,
                [this, i] { onXRangeChanged(i); });
        for (QCPAxis *y : {rect->axis(QCPAxis::atLeft), rect->axis(QCPAxis::atRight)})
            connect(y, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this,
                    [this] { m_replotNeeded = true; });
    }
    // After every layout: as many y ticks as each plot's height holds, and legends that fit
    // beside their plots (issue 27: a bottom panel squeezed the plots until tick labels printed
    // over each other and legend entries clipped). Ticks and legends are laid out before this
    // signal, so a change is drawn by one more replot.
    connect(m_plot, &QCustomPlot::afterLayout, this, [this] {
        const bool ticks = m_frame->fitTickCounts();
        const bool legends = m_frame->fitLegends(m_plot->height());
        if (ticks || legends)
            m_plot->replot(QCustomPlot::rpQueuedReplot);
    });
    m_overlays = std::make_unique<PlotOverlays>(m_plot, m_frame->rects());
    m_ghost = std::make_unique<PlotGhost>(*m_frame);
    m_measure = new MeasureCursors(this);
    connect(m_measure, &MeasureCursors::changed, this, [this] {
        m_frame->setWideLegends(m_measure->isEnabled());
        updateLegendTexts();
        m_replotNeeded = true;
    });

    connect(
        m_plot, &QCustomPlot::legendClick, this,
        [this](QCPLegend *, QCPAbstractLegendItem *item, QMouseEvent *) { onLegendClick(item); });
    connect(m_plot, &QCustomPlot::mouseMove, this, [this](QMouseEvent *event) {
        const QPointF pos = event->position();
        const QString details = m_overlays->eventDetailsAt(pos);
        if (!details.isEmpty())
            QToolTip::showText(event->globalPosition().toPoint(), details, m_plot);
        for (QCPAxisRect *rect : m_frame->rects()) {
            if (rect->rect().contains(pos.toPoint())) {
                setCursorTime(rect->axis(QCPAxis::atBottom)->pixelToCoord(pos.x()));
                return;
            }
        }
        setCursorTime(std::nullopt);
    });
    updateLabels();
    updateBands();
    updateInteractions();
    applyXRange(0, m_window);
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
    return m_frame->rects()[0]->axis(QCPAxis::atBottom)->range().lower;
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
    return m_frame->rects()[0]->axis(QCPAxis::atBottom)->range().upper;
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
    m_frame->rescaleAxes(before, m_units);
    updateLabels();
    updateBands();
    m_dataDirty = true;
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
    m_frame->rescaleAxes(before, m_units);
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
    m_frame->setAxisLabels(m_units);
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
    for (QCPAxisRect *rect : m_frame->rects()) {
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
    for (QCPAxisRect *rect : m_frame->rects())
        rect->axis(QCPAxis::atBottom)->setRange(start, end);
    m_settingRange = false;
    m_replotNeeded = true;
}

void PlotPanel::onXRangeChanged(int plotIndex)
{
    if (m_settingRange)
        return;
    // The user dragged or zoomed one plot: the others follow, the data is decimated again.
    const QCPRange range = m_frame->rects()[plotIndex]->axis(QCPAxis::atBottom)->range();
    applyXRange(range.lower, range.upper);
    m_dataDirty = true;
}

void PlotPanel::setRepaintRate(double hz)
{
    m_timer->setInterval(std::max(1, static_cast<int>(std::lround(1000.0 / std::max(hz, 1.0)))));
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
    if (followsLatest())
        m_latency.drawn(); // every live sample arrived so far is in this frame
    else
        m_latency.discard(); // paused: they are not shown
    m_stats.lastDecimateMs = clock.nsecsElapsed() / 1e6;
    if (m_autoscale)
        m_frame->autoscale(m_ranges, m_units, m_bandsVisible ? m_params : std::nullopt);
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
    const int pixels =
        m_laidOutSize == m_plot->size() ? m_frame->rects()[0]->width() : m_plot->width();
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
    m_ghost->rebuild(*m_frame, m_decimator, t0, t1, m_units);
}

void PlotPanel::setOverlaySource(const SampleBuffer *buffer)
{
    m_ghost->setSource(buffer);
    m_dataDirty = true;
    m_replotNeeded = true;
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
    m_frame->updateLegends(src, index, m_units, m_bandsVisible);
    m_measure->nameGraphs(); // Δ between the measuring cursors, when they are on
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

void PlotPanel::onLegendClick(QCPAbstractLegendItem *item)
{
    auto *plottableItem = qobject_cast<QCPPlottableLegendItem *>(item);
    if (!plottableItem)
        return;
    const QCPAbstractPlottable *p = plottableItem->plottable();
    if (m_frame->isBandKey(p))
        setBandsVisible(!m_bandsVisible);
    else if (const std::optional<Channel> channel = m_frame->channelOf(p))
        setChannelVisible(*channel, !isChannelVisible(*channel));
}

bool PlotPanel::exportImage(const QString &path, QString *error)
{
    return exportImage(path, PlotImageOptions{m_plot->size(), 1.0, {}}, error);
}

bool PlotPanel::exportImage(const QString &path, const PlotImageOptions &options, QString *error)
{
    repaintIfNeeded();
    return writePlotImage(m_plot, path, options, error);
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
    if (watched == m_plot && event->type() == QEvent::Paint)
        m_latency.painted(sampleClockNs());
    if (watched == m_plot && event->type() == QEvent::Leave)
        setCursorTime(std::nullopt);
    if (watched == m_plot && m_measure && m_measure->handleEvent(event)) // (built after)
        return true;
    return QWidget::eventFilter(watched, event);
}

} // namespace hatpic
