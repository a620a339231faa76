#include "stiffness/staticcurves.h"

#include "model/staticcurve.h"
#include "model/stiffness.h"

#include "plots/palette.h"
#include "plots/qcp.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

QCPItemStraightLine *verticalLine(QCustomPlot *plot, QCPAxisRect *rect, const QPen &pen)
{
    auto *line = new QCPItemStraightLine(plot);
    line->setClipAxisRect(rect);
    line->setClipToAxisRect(true);
    for (QCPItemPosition *p : {line->point1, line->point2}) {
        p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        p->setTypeY(QCPItemPosition::ptAxisRectRatio);
        p->setAxisRect(rect);
    }
    line->setPen(pen);
    line->setVisible(false);
    return line;
}

} // namespace

EffectMarks::EffectMarks(QCustomPlot *plot, QCPAxisRect *torque, QCPAxisRect *stiffness,
                         bool device)
{
    const QColor colour = palette::channel(Channel::TauFx);
    m_rest = plot->addGraph(torque->axis(QCPAxis::atBottom), torque->axis(QCPAxis::atLeft));
    m_rest->setName(
        device ? QCoreApplication::translate("hatpic::StiffnessView", "device's rest positions")
               : QCoreApplication::translate("hatpic::StiffnessView", "rest positions"));
    m_rest->setLineStyle(QCPGraph::lsNone);
    m_rest->setPen(QPen(colour, 1.5));
    // Edited: filled; the device's: hollow, a little larger, so both read where they coincide.
    m_rest->setScatterStyle(device ? QCPScatterStyle(QCPScatterStyle::ssCircle, colour, 9)
                                   : QCPScatterStyle(QCPScatterStyle::ssDisc, colour, 6));
    m_rest->removeFromLegend();
    m_rest->setVisible(false);
    const QPen wallPen(colour, 1.5, device ? Qt::DashLine : Qt::SolidLine);
    for (int i = 0; i < 4; ++i)
        m_walls[std::size_t(i)] = verticalLine(plot, i < 2 ? torque : stiffness, wallPen);
}

void EffectMarks::update(const DeviceParams &params, const std::optional<EffectParams> &effects,
                         double lo, double hi, double scale)
{
    QVector<double> keys;
    QVector<double> values;
    WallAngles walls;
    if (effects) {
        for (double theta : detentRestPositions(*effects, params.theta0, lo, hi)) {
            keys << theta * scale;
            values << staticTorque(params, *effects, theta);
        }
        walls = wallAngles(*effects, params.theta0, lo, hi);
    }
    m_rest->setData(keys, values, true);
    m_rest->setVisible(!keys.isEmpty());
    const std::optional<double> at[] = {walls.low, walls.high};
    for (std::size_t i = 0; i < m_walls.size(); ++i) {
        const std::optional<double> &theta = at[i % 2];
        QCPItemStraightLine *line = m_walls[i];
        line->setVisible(theta.has_value());
        if (theta) {
            line->point1->setCoords(*theta * scale, 0);
            line->point2->setCoords(*theta * scale, 1);
        }
    }
}

QVector<double> staticCurveAngles(const DeviceParams &p, double center, double halfWidth,
                                  const EffectParams &effects, int uniformSamples)
{
    const int n = std::max(uniformSamples, 2);
    QVector<double> x;
    x.reserve(n + 16);
    const double lo = center - halfWidth;
    const double hi = center + halfWidth;
    for (int i = 0; i + 1 < n; ++i)
        x << lo + (hi - lo) * i / (n - 1);
    x << hi; // exactly, not lo + (hi − lo)
    auto add = [&](double theta) {
        if (std::isfinite(theta) && theta >= lo && theta <= hi)
            x << theta;
    };
    for (double sign : {-1.0, 1.0}) {
        add(p.theta0 + sign * p.Q_dz);
        if (p.Q_dz > 0 && std::isfinite(p.Q_dz)) {
            // The jump at the dead-zone edge: the first angle in the notch band and the last
            // one in the dead zone, adjacent doubles, so the jump is drawn vertical. (θ0 ± Q_dz
            // itself may round to either side.)
            const double outward = sign * std::numeric_limits<double>::infinity();
            double notch = p.theta0 + sign * p.Q_dz;
            for (int i = 0; i < 8 && stiffnessZone(p, notch) == StiffnessZone::DeadZone; ++i)
                notch = std::nextafter(notch, outward);
            double inside = std::nextafter(notch, p.theta0);
            for (int i = 0; i < 8 && stiffnessZone(p, inside) != StiffnessZone::DeadZone; ++i)
                inside = std::nextafter(inside, p.theta0);
            add(notch);
            add(inside);
        }
        add(p.theta0 + sign * p.N);
        add(p.theta0 + sign * 2.0 * p.N);
    }
    add(p.theta0);
    for (double theta : effectSampleAngles(effects, p.theta0, lo, hi))
        x << theta;
    std::sort(x.begin(), x.end());
    x.erase(std::unique(x.begin(), x.end()), x.end());
    return x;
}

QVector<double> EffectMarks::wallKeys() const
{
    QVector<double> keys;
    for (std::size_t i = 0; i < 2; ++i) {
        if (m_walls[i]->visible())
            keys << m_walls[i]->point1->key();
    }
    std::sort(keys.begin(), keys.end());
    return keys;
}

} // namespace hatpic
