#include "plots/measurecursors.h"

#include "plots/palette.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"

#include <QKeyEvent>
#include <QMouseEvent>

#include <algorithm>
#include <cmath>

namespace hatpic {

namespace {

constexpr int kStepBig = 10; //!< pixels per Shift+arrow

QString signedText(double value, const QString &formatted)
{
    // DisplayUnits::format writes "−" for negatives; a rise gets its "+".
    return value > 0 ? u'+' % formatted : formatted;
}

} // namespace

MeasureCursors::MeasureCursors(PlotPanel *panel) : QObject(panel), m_panel(panel)
{
    QCustomPlot *plot = panel->customPlot();
    const std::array<PlotPanel::Plot, PlotPanel::kPlotCount> plots{
        PlotPanel::Plot::Angle, PlotPanel::Plot::Torque, PlotPanel::Plot::Reference};
    for (int c = 0; c < kCount; ++c) {
        const QPen pen(palette::kMeasure, 1.5, c == 0 ? Qt::SolidLine : Qt::DashLine);
        for (PlotPanel::Plot p : plots) {
            QCPAxisRect *rect = panel->axisRect(p);
            auto *line = new QCPItemStraightLine(plot);
            line->setLayer(QStringLiteral("overlay"));
            line->setClipAxisRect(rect);
            line->setPen(pen);
            line->setSelectable(false);
            for (QCPItemPosition *pos : {line->point1, line->point2}) {
                pos->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
                pos->setAxisRect(rect);
                pos->setTypeY(QCPItemPosition::ptAxisRectRatio);
            }
            line->setVisible(false);
            m_lines[c] << line;
        }
    }
    auto label = [&](QCPAxisRect *rect) {
        auto *text = new QCPItemText(plot);
        text->setLayer(QStringLiteral("overlay"));
        text->setClipAxisRect(rect);
        text->position->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        text->position->setAxisRect(rect);
        text->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
        text->setPositionAlignment(Qt::AlignHCenter | Qt::AlignTop);
        text->setColor(palette::kMeasure);
        text->setBrush(QColor(255, 255, 255, 230));
        text->setPen(QPen(palette::kMeasure, 1));
        text->setPadding(QMargins(4, 1, 4, 1));
        QFont font = panel->font();
        font.setBold(true);
        text->setFont(font);
        text->setVisible(false);
        return text;
    };
    for (int c = 0; c < kCount; ++c)
        m_names[c] = label(panel->axisRect(PlotPanel::Plot::Angle));
    m_dt = label(panel->axisRect(PlotPanel::Plot::Torque));
}

void MeasureCursors::setEnabled(bool on)
{
    if (on == m_enabled)
        return;
    m_enabled = on;
    if (on) {
        const double t0 = m_panel->viewStart();
        const double t1 = std::min(m_panel->viewEnd(), m_panel->dataEnd().value_or(INFINITY));
        const double span = t1 - t0;
        for (int c = 0; c < kCount; ++c) {
            const bool inView = m_times[c] && *m_times[c] >= t0 && *m_times[c] <= t1;
            if (!inView)
                m_times[c] = snap(t0 + span * (c + 1) / 3.0);
        }
    }
    m_dragging = -1;
    updateItems();
    Q_EMIT changed();
}

std::optional<double> MeasureCursors::snap(double t) const
{
    if (!std::isfinite(t))
        return std::nullopt;
    const SampleBuffer *src = m_panel->shownSource();
    if (!src || src->isEmpty())
        return t;
    return src->time(src->nearest(t));
}

void MeasureCursors::setTime(int which, double t)
{
    if (which < 0 || which >= kCount)
        return;
    const std::optional<double> snapped = snap(t);
    if (!snapped || snapped == m_times[which])
        return;
    m_times[which] = snapped;
    updateItems();
    Q_EMIT changed();
}

void MeasureCursors::setActive(int which)
{
    if (which >= 0 && which < kCount)
        m_active = which;
}

std::optional<MeasureCursors::Readout> MeasureCursors::readout() const
{
    const SampleBuffer *src = m_panel->shownSource();
    if (!m_enabled || !src || src->isEmpty() || !m_times[0] || !m_times[1])
        return std::nullopt;
    const qsizetype ia = src->nearest(*m_times[0]);
    const qsizetype ib = src->nearest(*m_times[1]);
    Readout r;
    r.tA = src->time(ia);
    r.tB = src->time(ib);
    r.dt = r.tB - r.tA;
    const DisplayUnits &units = m_panel->units();
    for (Channel channel : kAllChannels) {
        if (!m_panel->isChannelVisible(channel))
            continue;
        const double scale = units.scale(channel);
        Delta d{channel, src->value(channel, ia) * scale, src->value(channel, ib) * scale, 0};
        d.delta = d.b - d.a;
        r.deltas << d;
    }
    return r;
}

QString MeasureCursors::dtText() const
{
    const std::optional<Readout> r = readout();
    if (!r)
        return {};
    QString text = tr("Δt = %1 s").arg(r->dt, 0, 'f', 3);
    if (std::abs(r->dt) > 0)
        text += tr(" (1/Δt = %1 Hz)").arg(1.0 / std::abs(r->dt), 0, 'g', 3);
    return text.replace(u'-', u'−');
}

void MeasureCursors::nameGraphs() const
{
    const std::optional<Readout> r = readout();
    if (!r)
        return;
    const DisplayUnits &units = m_panel->units();
    for (const Delta &d : r->deltas) {
        // format() takes SI: undo the display scale it applies again.
        const QString value = units.format(d.channel, d.delta / units.scale(d.channel));
        m_panel->graph(d.channel)->setName(channelLabel(d.channel) % tr(" Δ ") %
                                           signedText(d.delta, value));
    }
}

void MeasureCursors::updateItems()
{
    for (int c = 0; c < kCount; ++c) {
        const bool shown = m_enabled && m_times[c].has_value();
        for (QCPItemStraightLine *line : std::as_const(m_lines[c])) {
            line->setVisible(shown);
            if (shown) {
                line->point1->setCoords(*m_times[c], 0);
                line->point2->setCoords(*m_times[c], 1);
            }
        }
        m_names[c]->setVisible(shown);
        if (shown) {
            m_names[c]->position->setCoords(*m_times[c], 0);
            m_names[c]->setText(c == 0 ? QStringLiteral("A") : QStringLiteral("B"));
        }
    }
    const QString dt = dtText();
    m_dt->setVisible(!dt.isEmpty());
    if (!dt.isEmpty()) {
        m_dt->position->setCoords((*m_times[0] + *m_times[1]) / 2, 0);
        m_dt->setText(dt);
    }
}

std::optional<double> MeasureCursors::timeAtPixel(double x) const
{
    const QCPAxis *axis = m_panel->axisRect(PlotPanel::Plot::Angle)->axis(QCPAxis::atBottom);
    return axis->pixelToCoord(x);
}

bool MeasureCursors::onPress(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return false;
    const QPointF pos = event->position();
    const QCPAxis *axis = m_panel->axisRect(PlotPanel::Plot::Angle)->axis(QCPAxis::atBottom);
    bool inPlot = false;
    for (PlotPanel::Plot p :
         {PlotPanel::Plot::Angle, PlotPanel::Plot::Torque, PlotPanel::Plot::Reference})
        inPlot = inPlot || m_panel->axisRect(p)->rect().contains(pos.toPoint());
    if (!inPlot)
        return false;
    // Grab the nearer line within reach; else a click places A (Shift: B).
    int grab = -1;
    double best = kGrabPixels + 1;
    for (int c = 0; c < kCount; ++c) {
        if (!m_times[c])
            continue;
        const double distance = std::abs(axis->coordToPixel(*m_times[c]) - pos.x());
        if (distance <= kGrabPixels && distance < best) {
            grab = c;
            best = distance;
        }
    }
    if (grab < 0)
        grab = event->modifiers().testFlag(Qt::ShiftModifier) ? 1 : 0;
    m_dragging = grab;
    m_active = grab;
    if (const std::optional<double> t = timeAtPixel(pos.x()); t && best > kGrabPixels)
        setTime(grab, *t);
    return true;
}

void MeasureCursors::step(int direction, int pixels)
{
    const SampleBuffer *src = m_panel->shownSource();
    if (!m_times[m_active] || !src || src->isEmpty())
        return;
    const QCPAxis *axis = m_panel->axisRect(PlotPanel::Plot::Angle)->axis(QCPAxis::atBottom);
    const double perPixel =
        axis->range().size() / std::max(1, m_panel->axisRect(PlotPanel::Plot::Angle)->width());
    const double now = *m_times[m_active];
    qsizetype index = src->nearest(now + direction * pixels * perPixel);
    if (src->time(index) == now) // less than a sample per pixel: one sample at least
        index = std::clamp<qsizetype>(src->nearest(now) + direction, 0, src->size() - 1);
    setTime(m_active, src->time(index));
}

bool MeasureCursors::onKey(int key, bool shift)
{
    switch (key) {
    case Qt::Key_A:
        setActive(0);
        return true;
    case Qt::Key_B:
        setActive(1);
        return true;
    case Qt::Key_Left:
    case Qt::Key_Right:
        step(key == Qt::Key_Left ? -1 : 1, shift ? kStepBig : 1);
        return true;
    default:
        return false;
    }
}

bool MeasureCursors::handleEvent(QEvent *event)
{
    if (!m_enabled)
        return false;
    switch (event->type()) {
    case QEvent::MouseButtonPress:
        return onPress(static_cast<QMouseEvent *>(event));
    case QEvent::MouseMove:
        if (m_dragging >= 0) {
            if (const std::optional<double> t =
                    timeAtPixel(static_cast<QMouseEvent *>(event)->position().x()))
                setTime(m_dragging, *t);
            return false; // the hover cursor follows too
        }
        return false;
    case QEvent::MouseButtonRelease:
        if (m_dragging >= 0) {
            m_dragging = -1;
            return true;
        }
        return false;
    case QEvent::KeyPress: {
        auto *key = static_cast<QKeyEvent *>(event);
        const Qt::KeyboardModifiers mods = key->modifiers() & ~Qt::KeypadModifier;
        if (mods != Qt::NoModifier && mods != Qt::ShiftModifier)
            return false;
        return onKey(key->key(), mods == Qt::ShiftModifier);
    }
    default:
        return false;
    }
}

} // namespace hatpic
