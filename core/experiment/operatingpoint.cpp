#include "operatingpoint.h"

#include "firmware/sts3032.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hatpic {

namespace {

QString mrad(double rad)
{
    return QString::number(rad * 1e3, 'f', 1) + QStringLiteral(" mrad");
}

QString band(const DeviceParams &p)
{
    return QStringLiteral("%1–%2 rad").arg(p.Q_dz, 0, 'g', 3).arg(p.N, 0, 'g', 3);
}

//! |θ − θ0| within the notch band [Q_dz, N], with half a count of slack either side.
bool inBand(double e, const DeviceParams &p)
{
    const double slack = encoderCount() / 2;
    return std::abs(e) >= p.Q_dz - slack && std::abs(e) <= p.N + slack;
}

//! The mean θ over samples whose device time lies in [from, to); NaN when none.
double meanTheta(const QList<Sample> &samples, double from, double to)
{
    double sum = 0;
    int n = 0;
    for (const Sample &s : samples) {
        if (s.t_s >= from && s.t_s < to) {
            sum += s.theta;
            ++n;
        }
    }
    return n ? sum / n : std::nan("");
}

QString outsideBand(const QString &when, double e, const DeviceParams &p)
{
    return QStringLiteral("The knob was at θ − θ0 = %1 rad %2, outside the notch band (%3) where "
                          "the model's figures apply: they are not the model's.")
        .arg(e, 0, 'f', 3)
        .arg(when, band(p));
}

} // namespace

double encoderCount()
{
    return 2 * std::numbers::pi / fw::sts::kTicksPerRev;
}

QStringList operatingPointWarnings(const ExperimentKind kind, const DeviceTuning &tuning)
{
    QStringList out;
    if (kind == ExperimentKind::Spectrum || !tuning.effects || !tuning.params)
        return out;
    const EffectParams &fx = *tuning.effects;
    const DeviceParams &p = *tuning.params;
    if (fx.detent_strength > 0 && fx.detent_range > 0)
        out.append(QStringLiteral("Detents are on (%1 N·m every %2 rad): they hold the knob "
                                  "where the model has no detent, so its figures will not "
                                  "apply. Turn them off in Effects for a measurement.")
                       .arg(fx.detent_strength, 0, 'g', 3)
                       .arg(fx.detent_spacing, 0, 'g', 3));
    if (fx.wall_stiffness > 0 && (fx.wall_min > -p.N || fx.wall_max < p.N))
        out.append(QStringLiteral("An end stop lies inside the notch band (±%1 rad): the "
                                  "knob may hit it during the run.")
                       .arg(p.N, 0, 'g', 3));
    return out;
}

QStringList operatingPointCaveats(const ExperimentResult &r)
{
    QStringList out;
    const ExperimentPlan &plan = r.plan;
    const DeviceParams &p = r.params;
    if (plan.kind == ExperimentKind::Spectrum || r.samples.isEmpty())
        return out;

    double tauChange = 0; // the experiment's own swing of τ_ext [N·m]
    if (plan.kind == ExperimentKind::Step) {
        tauChange = std::abs(plan.tauTo - plan.tauFrom);
        // The levels of the step's metrics: before it, and the tail after it.
        const double before = r.stepMeasured.initial - p.theta0;
        const double after = r.stepMeasured.final - p.theta0;
        if (std::isfinite(before) && !inBand(before, p))
            out.append(outsideBand(QStringLiteral("before the step"), before, p));
        else if (std::isfinite(after) && !inBand(after, p))
            out.append(outsideBand(QStringLiteral("after the step"), after, p));
        const double moved = std::abs(r.stepMeasured.final - r.stepMeasured.initial);
        if (std::isfinite(moved) && moved < kMinResponseCounts * encoderCount())
            out.append(QStringLiteral("The step moved the knob %1 encoder counts (%2), too few "
                                      "to fit ω_n and ζ: something held it (a detent, an end "
                                      "stop, a hand) or the step is too small.")
                           .arg(std::lround(moved / encoderCount()))
                           .arg(mrad(moved)));
    } else {
        tauChange = 2 * plan.amplitude;
        // The middle of the sines: the mean angle over the analysed stretches.
        double sum = 0;
        int n = 0;
        for (const SineSegment &seg : plan.segments()) {
            const double m = meanTheta(r.samples, r.clock.deviceTime(seg.analyseFrom),
                                       r.clock.deviceTime(seg.analyseTo));
            if (std::isfinite(m)) {
                sum += m;
                ++n;
            }
        }
        if (n && !inBand(sum / n - p.theta0, p))
            out.append(outsideBand(QStringLiteral("on average"), sum / n - p.theta0, p));
        if (!r.points.empty()) {
            // The slowest sine moves the knob most: its swing in counts.
            const double swing = 2 * r.points.front().magnitude * plan.amplitude;
            if (swing < kMinResponseCounts * encoderCount())
                out.append(QStringLiteral("The slowest sine moved the knob %1 encoder counts "
                                          "(%2) peak to peak, too few to measure a gain: "
                                          "something held it or the amplitude is too small.")
                               .arg(std::lround(swing / encoderCount()))
                               .arg(mrad(swing)));
        }
    }
    double fx = 0;
    for (const Sample &s : r.samples)
        fx = std::max(fx, std::abs(s.tau_fx));
    if (fx > kMaxEffectsShare * tauChange)
        out.append(QStringLiteral("The haptic effects (detents, end stops) pushed with up to "
                                  "%1 N·m during the run, against the experiment's %2 N·m: the "
                                  "model's figures leave them out.")
                       .arg(fx, 0, 'f', 3)
                       .arg(tauChange, 0, 'f', 3));
    return out;
}

} // namespace hatpic
