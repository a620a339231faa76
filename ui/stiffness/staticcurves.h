// The haptic effects on the stiffness view, for one parameter set (the edited one or the
// device's): the detents' rest positions as markers on its static torque curve, and its walls
// as vertical lines across both plots, in τ_fx's colour (solid for the edited set, dashed for
// the device's, as their curves). The maths is core/model/staticcurve.h.
#pragma once

#include "model/effects.h"
#include "model/params.h"

#include <QVector>

#include <array>
#include <optional>

class QCPAxisRect;
class QCPGraph;
class QCPItemStraightLine;
class QCustomPlot;

namespace hatpic {

//! Sorted sample angles [rad] over center ± halfWidth (StiffnessView::sampleAngles): an even
//! grid of `uniformSamples`, every breakpoint of `params` with the dead zone's jump, and the
//! angles that resolve `effects` (effectSampleAngles).
QVector<double> staticCurveAngles(const DeviceParams &params, double center, double halfWidth,
                                  const EffectParams &effects, int uniformSamples);

class EffectMarks
{
public:
    //! Adds its (empty) graph and lines to `plot`; the plot owns and deletes them.
    EffectMarks(QCustomPlot *plot, QCPAxisRect *torque, QCPAxisRect *stiffness, bool device);

    //! Marks the effects of `params` + `effects` within [lo, hi] [rad]; θ keys are multiplied
    //! by `scale` (the axis' unit). nullopt hides every mark.
    void update(const DeviceParams &params, const std::optional<EffectParams> &effects, double lo,
                double hi, double scale);

    //! The rest positions: one scatter point per detent on the static torque curve.
    QCPGraph *restPositions() const { return m_rest; }
    //! The walls' keys shown (θ0 + wall_min, θ0 + wall_max, in the axis' unit), sorted.
    QVector<double> wallKeys() const;
    //! The wall lines: lower and upper wall in the torque plot, then in the stiffness plot.
    const std::array<QCPItemStraightLine *, 4> &wallLines() const { return m_walls; }

private:
    QCPGraph *m_rest = nullptr;
    std::array<QCPItemStraightLine *, 4> m_walls{};
};

} // namespace hatpic
