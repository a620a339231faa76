#include "plots/plotoverlays.h"

#include "plots/eventmarkers.h"
#include "plots/palette.h"
#include "plots/qcp.h"

#include <QFontMetrics>

#include <cmath>

namespace hatpic {

namespace {

const QColor kCenterColor(90, 90, 90);
const QColor kCursorColor(40, 40, 40, 160);

} // namespace

PlotOverlays::PlotOverlays(QCustomPlot *plot, const std::array<QCPAxisRect *, kPlotCount> &rects)
    : m_plot(plot), m_rects(rects)
{
    // The cursor is redrawn with everything else, so its layer needs no paint buffer of its
    // own: one buffer fewer to clear at each replot and to blend at each paint.
    m_plot->layer(QStringLiteral("overlay"))->setMode(QCPLayer::lmLogical);
    m_plot->addLayer(QStringLiteral("bands"), m_plot->layer(QStringLiteral("grid")),
                     QCustomPlot::limBelow);

    // Bands and the center line span the angle plot's width (axis-rect ratio in x).
    QCPAxisRect *angle = m_rects[0];
    auto place = [angle](QCPItemPosition *position, double ratioX) {
        position->setAxes(angle->axis(QCPAxis::atBottom), angle->axis(QCPAxis::atLeft));
        position->setAxisRect(angle);
        position->setTypeX(QCPItemPosition::ptAxisRectRatio);
        position->setTypeY(QCPItemPosition::ptPlotCoords);
        position->setCoords(ratioX, 0);
    };
    auto makeBand = [&](const QColor &color) {
        auto *band = new QCPItemRect(m_plot);
        band->setLayer(QStringLiteral("bands"));
        band->setClipAxisRect(angle);
        band->setPen(Qt::NoPen);
        band->setBrush(color);
        place(band->topLeft, 0);
        place(band->bottomRight, 1);
        return band;
    };
    m_deadZone = makeBand(palette::kDeadZone);
    m_notch = {makeBand(palette::kNotch), makeBand(palette::kNotch)};
    m_centerLine = new QCPItemLine(m_plot);
    m_centerLine->setLayer(QStringLiteral("bands"));
    m_centerLine->setClipAxisRect(angle);
    m_centerLine->setPen(QPen(kCenterColor, 1, Qt::DashLine));
    place(m_centerLine->start, 0);
    place(m_centerLine->end, 1);

    for (int i = 0; i < kPlotCount; ++i) {
        m_cursorLines[i] = verticalLine(i, "overlay");
        m_cursorLines[i]->setPen(QPen(kCursorColor, 1));
        m_cursorLines[i]->setVisible(false);
    }
    m_cursorLabel = new QCPItemText(m_plot);
    m_cursorLabel->setLayer(QStringLiteral("overlay"));
    m_cursorLabel->setClipToAxisRect(false);
    m_cursorLabel->position->setAxes(angle->axis(QCPAxis::atBottom), angle->axis(QCPAxis::atLeft));
    m_cursorLabel->position->setAxisRect(angle);
    m_cursorLabel->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
    m_cursorLabel->setPositionAlignment(Qt::AlignHCenter | Qt::AlignBottom);
    m_cursorLabel->setBrush(QColor(255, 255, 255, 220));
    m_cursorLabel->setPadding(QMargins(3, 1, 3, 1));
    m_cursorLabel->setVisible(false);
    setBands(std::nullopt, 1.0, true);
}

QCPItemStraightLine *PlotOverlays::verticalLine(int plot, const char *layer)
{
    QCPAxisRect *rect = m_rects[plot];
    auto *line = new QCPItemStraightLine(m_plot);
    line->setLayer(QString::fromLatin1(layer));
    line->setClipAxisRect(rect);
    for (QCPItemPosition *p : {line->point1, line->point2}) {
        p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        p->setAxisRect(rect);
        p->setTypeY(QCPItemPosition::ptAxisRectRatio);
    }
    line->point1->setCoords(0, 0);
    line->point2->setCoords(0, 1);
    return line;
}

void PlotOverlays::setBands(const std::optional<DeviceParams> &params, double scale, bool showBands)
{
    const bool bands = params.has_value() && showBands;
    m_deadZone->setVisible(bands);
    for (QCPItemRect *band : m_notch)
        band->setVisible(bands);
    m_centerLine->setVisible(params.has_value());
    if (!params)
        return;
    const double c = params->theta0 * scale;
    const double q = params->Q_dz * scale;
    const double n = params->N * scale;
    auto setBand = [](QCPItemRect *band, double lo, double hi) {
        band->topLeft->setCoords(0, hi);
        band->bottomRight->setCoords(1, lo);
    };
    setBand(m_deadZone, c - q, c + q);
    setBand(m_notch[0], c - n, c - q);
    setBand(m_notch[1], c + q, c + n);
    m_centerLine->start->setCoords(0, c);
    m_centerLine->end->setCoords(1, c);
}

void PlotOverlays::setEvents(const QList<RecordingEvent> &events, const QFont &font)
{
    for (QCPAbstractItem *item : std::as_const(m_eventItems))
        m_plot->removeItem(item);
    m_eventItems.clear();
    m_eventLabels.clear();
    m_eventDetails.clear();
    QCPAxisRect *angle = m_rects[0];
    for (const EventMarker &event : groupEvents(events)) {
        for (int i = 0; i < kPlotCount; ++i) {
            QCPItemStraightLine *line = verticalLine(i, "bands");
            line->setPen(QPen(palette::kEvent, 1, Qt::DashDotLine));
            line->point1->setCoords(event.t_s, 0);
            line->point2->setCoords(event.t_s, 1);
            m_eventItems.append(line);
        }
        auto *label = new QCPItemText(m_plot);
        label->setLayer(QStringLiteral("bands"));
        label->setClipAxisRect(angle);
        label->position->setAxes(angle->axis(QCPAxis::atBottom), angle->axis(QCPAxis::atLeft));
        label->position->setAxisRect(angle);
        label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
        label->position->setCoords(event.t_s, 0);
        label->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
        label->setPadding(QMargins(3, 2, 3, 2));
        label->setColor(palette::kEvent);
        label->setText(event.label);
        label->setFont(font);
        m_eventItems.append(label);
        m_eventLabels.append(label);
        m_eventDetails.append(event.details);
    }
    fitEventLabels();
}

void PlotOverlays::fitEventLabels()
{
    QCPAxisRect *angle = m_rects[0];
    QCPAxis *x = angle->axis(QCPAxis::atBottom);
    for (QCPItemText *label : std::as_const(m_eventLabels)) {
        const double pixel = x->coordToPixel(label->position->coords().x());
        const QMargins padding = label->padding();
        const int width = QFontMetrics(label->font()).horizontalAdvance(label->text()) +
                          padding.left() + padding.right();
        const bool fitsRight = pixel + width <= angle->right();
        const bool fitsLeft = pixel - width >= angle->left();
        label->setPositionAlignment(Qt::AlignTop |
                                    (fitsRight || !fitsLeft ? Qt::AlignLeft : Qt::AlignRight));
    }
}

QString PlotOverlays::eventDetailsAt(const QPointF &pixel) const
{
    constexpr double kReach = 4; // [px] either side of a marker's line
    for (qsizetype i = 0; i < m_eventLabels.size(); ++i) {
        const QCPItemText *label = m_eventLabels[i];
        const QRectF box(label->topLeft->pixelPosition(), label->bottomRight->pixelPosition());
        if (box.normalized().contains(pixel))
            return m_eventDetails[i];
        const double t = label->position->coords().x();
        for (QCPAxisRect *rect : m_rects) {
            const double x = rect->axis(QCPAxis::atBottom)->coordToPixel(t);
            // By height only: a live marker's line is at the plot's right edge.
            const QRect r = rect->rect();
            if (pixel.y() >= r.top() && pixel.y() <= r.bottom() &&
                std::abs(pixel.x() - x) <= kReach)
                return m_eventDetails[i];
        }
    }
    return {};
}

void PlotOverlays::setCursor(std::optional<double> t)
{
    for (QCPItemStraightLine *line : m_cursorLines) {
        line->setVisible(t.has_value());
        if (t) {
            line->point1->setCoords(*t, 0);
            line->point2->setCoords(*t, 1);
        }
    }
    m_cursorLabel->setVisible(t.has_value());
    if (t) {
        m_cursorLabel->position->setCoords(*t, 0);
        m_cursorLabel->setText(QStringLiteral("t = %1 s").arg(*t, 0, 'f', 3));
    }
}

} // namespace hatpic
