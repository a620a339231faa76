#include "curvetable.h"

#include "console.h"

#include "model/stiffness.h"
#include "telemetry/numbertext.h"

#include <cmath>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

// A grid point closer than this (relative to the step) to `to` is `to` itself, so that
// 0…1 step 0.1 ends with 1 once rather than with 0.9999999999999999 and 1.
constexpr double kSameAngle = 1e-9;

} // namespace

std::optional<qint64> AngleGrid::rowCount(QString *error) const
{
    const auto fail = [error](const QString &sentence) -> std::optional<qint64> {
        if (error)
            *error = sentence;
        return std::nullopt;
    };
    if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(step))
        return fail(u"--from, --to and --step must be finite numbers."_s);
    if (step <= 0)
        return fail(u"--step must be above 0, got " + compactNumberText(step) + u'.');
    if (from > to) {
        return fail(u"--from (" + compactNumberText(from) + u") must not be above --to (" +
                    compactNumberText(to) + u").");
    }
    const double intervals = std::floor((to - from) / step + kSameAngle);
    if (!(intervals + 2 <= static_cast<double>(kMaxRows))) {
        return fail(u"The range gives more than " + QString::number(kMaxRows) +
                    u" rows; use a larger --step or a smaller range.");
    }
    const auto n = static_cast<qint64>(intervals);
    const double last = from + static_cast<double>(n) * step;
    const bool endsOnGrid = std::abs(to - last) <= kSameAngle * step || last > to;
    return endsOnGrid ? n + 1 : n + 2;
}

double AngleGrid::angle(qint64 i, qint64 rows) const
{
    if (i >= rows - 1)
        return to;
    return from + static_cast<double>(i) * step;
}

QByteArray curveHeader()
{
    return QByteArrayLiteral("theta,K_rec,tau_rec,tau_det,tau_wall\n");
}

QByteArray curveRow(const DeviceParams &params, const EffectParams &effects, double theta)
{
    const double e = theta - params.theta0;
    return compactNumberText(theta).toLatin1() + ',' +
           compactNumberText(recenteringStiffness(params, theta)).toLatin1() + ',' +
           compactNumberText(recenteringTorque(params, theta)).toLatin1() + ',' +
           compactNumberText(detentTorque(effects, e)).toLatin1() + ',' +
           compactNumberText(wallTorque(effects, e, 0.0)).toLatin1() + '\n';
}

} // namespace hatpic::cli
