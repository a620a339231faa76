#include "plots/fadingtrail.h"

#include "plots/qcp.h"
#include "plots/samplebuffer.h"

#include <algorithm>

namespace hatpic {

FadingTrail::FadingTrail(QCPAxis *x, QCPAxis *y, const QColor &colour, const QString &name)
{
    for (int i = 0; i < kPieces; ++i) {
        auto *curve = new QCPCurve(x, y);
        QColor c = colour;
        c.setAlpha(kOldestAlpha + (255 - kOldestAlpha) * i / (kPieces - 1));
        // 1 px: the fast cosmetic stroke (docs/performance.md); the newest piece stands out.
        curve->setPen(QPen(c, i == kPieces - 1 ? 2.0 : 1.0));
        curve->setName(name);
        curve->setSelectable(QCP::stNone);
        if (i + 1 < kPieces)
            curve->removeFromLegend();
        m_pieces[i] = curve;
    }
}

void FadingTrail::setFromBuffer(const SampleBuffer &source, double t0, double t1, Channel xChannel,
                                double xScale, Channel yChannel, double yScale)
{
    const qsizetype first = source.lowerBound(t0);
    const qsizetype last = source.upperBound(t1);
    const qsizetype n = std::max<qsizetype>(last - first, 0);
    const qsizetype stride = std::max<qsizetype>(1, (n + kMaxPoints - 1) / kMaxPoints);
    QVector<QCPCurveData> points;
    points.reserve(n / stride + 1);
    for (qsizetype i = first; i < last; i += stride)
        points.append(QCPCurveData(double(points.size()), source.value(xChannel, i) * xScale,
                                   source.value(yChannel, i) * yScale));
    if (n > 0 && (last - 1 - first) % stride != 0) // the newest sample always ends the path
        points.append(QCPCurveData(double(points.size()), source.value(xChannel, last - 1) * xScale,
                                   source.value(yChannel, last - 1) * yScale));
    m_points = points.size();
    // Equal shares of the points per piece; each piece also takes the next one's first point so
    // the path has no breaks between them.
    for (int i = 0; i < kPieces; ++i) {
        const qsizetype from = m_points * i / kPieces;
        const qsizetype to = std::min(m_points, m_points * (i + 1) / kPieces + 1);
        m_pieces[i]->data()->set(points.mid(from, std::max<qsizetype>(to - from, 0)), true);
    }
}

void FadingTrail::clear()
{
    for (QCPCurve *curve : m_pieces)
        curve->data()->clear();
    m_points = 0;
}

void FadingTrail::setLayer(const QString &layer)
{
    for (QCPCurve *curve : m_pieces)
        curve->setLayer(layer);
}

} // namespace hatpic
