// What the stiffness view's tests share (tst_stiffnessview, tst_stiffnesseffects): edits as the
// parameter editor makes them, a graph's points and its plot's title, and parameter sets.
#pragma once

#include "model/params.h"
#include "plots/axistitle.h"
#include "plots/qcp.h"
#include "tuning/tuningmodel.h"

#include <QPointF>
#include <QString>
#include <QVector>

namespace hatpic::test {

// Edits as the parameter editor does: the view follows the model.
inline void editParams(TuningModel &tuning, const DeviceParams &params)
{
    Tuning t = tuning.edited();
    t.device = params;
    tuning.setEdited(t);
}

//! The title of the plot `graph` is drawn in (level, in its corner).
inline QString title(const QCPGraph *graph)
{
    const QCPItemText *text = cornerTitle(graph->valueAxis()->axisRect());
    return text ? text->text() : QString();
}

inline QVector<QPointF> points(const QCPGraph *graph)
{
    QVector<QPointF> out;
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
        out << QPointF(it->key, it->value);
    return out;
}

inline DeviceParams params(double kMin, double kMax, double n, double qdz, double theta0)
{
    DeviceParams p;
    p.K_min = kMin;
    p.K_max = kMax;
    p.N = n;
    p.Q_dz = qdz;
    p.theta0 = theta0;
    return p;
}

//! K_min = K_max = k, no dead zone: τ_rec = −k·(θ − θ0).
inline DeviceParams linear(double k, double theta0 = 0)
{
    return params(k, k, 0.2, 0, theta0);
}

} // namespace hatpic::test
