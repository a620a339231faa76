// The table `hatpicctl curve` prints: K_rec(θ) and τ_rec(θ) over a grid of angles.
#pragma once

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

//! "theta,K_rec,tau_rec\n"
QByteArray curveHeader();
//! One CSV row for angle θ with the profile's device parameters (θ0 from them).
QByteArray curveRow(const DeviceParams &params, double theta);

} // namespace hatpic::cli
