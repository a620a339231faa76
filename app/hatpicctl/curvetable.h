// The table `hatpicctl curve` prints: K_rec(θ), τ_rec(θ) and the static effect torques τ_det(θ),
// τ_wall(θ) (ω = 0) over a grid of angles.
#pragma once

#include "model/effects.h"
#include "model/params.h"

#include <QByteArray>
#include <QString>
#include <QtGlobal>

#include <numbers>
#include <optional>

namespace hatpic::cli {

//! An inclusive grid of absolute angles [rad]: from, from + step, …, and always `to` itself.
struct AngleGrid
{
    static constexpr qint64 kMaxRows = 10'000'000;

    double from = -std::numbers::pi / 2; //!< [rad]
    double to = std::numbers::pi / 2;    //!< [rad]
    double step = 0.01;                  //!< [rad]

    //! Number of rows, or nullopt with one sentence in `error` (not finite, step ≤ 0,
    //! from > to, more than kMaxRows rows).
    std::optional<qint64> rowCount(QString *error) const;
    //! Angle of row i of `rows`: from + i·step (no accumulated error), the last row exactly `to`.
    double angle(qint64 i, qint64 rows) const;
};

//! "theta,K_rec,tau_rec,tau_det,tau_wall\n"
QByteArray curveHeader();
//! One CSV row for angle θ with the profile's device parameters (θ0 from them) and effects,
//! at rest (ω = 0: the walls' damping does not act).
QByteArray curveRow(const DeviceParams &params, const EffectParams &effects, double theta);

} // namespace hatpic::cli
