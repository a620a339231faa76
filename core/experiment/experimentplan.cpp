#include "experimentplan.h"

#include "analysis/frequencyresponse.h"
#include "model/derived.h"
#include "model/paramtable.h"
#include "telemetry/numbertext.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace hatpic {

namespace {

constexpr double kMinSettle = 0.1; //!< shortest default transient [s]
constexpr double kMaxSettle = 2.0; //!< longest default transient [s]
constexpr int kDefaultPoints = 8;
constexpr double kLowestFactor = 0.1; //!< default band: bandwidth × 0.1 …
constexpr double kHighestFactor = 3;  //!< … × 3

QString number(double v)
{
    return compactNumberText(v);
}

// A plan's length as people read it: tenths of a second ("130.3 s"), never 17 digits.
QString seconds(double v)
{
    return QString::number(v, 'f', 1) + u" s";
}

} // namespace

QString experimentKindName(ExperimentKind kind)
{
    switch (kind) {
    case ExperimentKind::Step:
        return QStringLiteral("step");
    case ExperimentKind::Frequency:
        return QStringLiteral("bode");
    case ExperimentKind::Spectrum:
        return QStringLiteral("spectrum");
    }
    return {};
}

double modelSettlingEstimate(const DeviceParams &params)
{
    if (!(params.K_max > 0))
        return std::numeric_limits<double>::infinity();
    const DerivedFigures figures = deriveFigures(params, HostParams{});
    const double omegaN = figures.omega_n;
    const double zeta = figures.zeta;
    const double slowest = zeta < 1 ? zeta * omegaN : omegaN * (zeta - std::sqrt(zeta * zeta - 1));
    return 4 / slowest;
}

ExperimentPlan ExperimentPlan::defaults(ExperimentKind kind, const DeviceParams &params)
{
    ExperimentPlan plan;
    plan.kind = kind;
    const double settle = std::clamp(modelSettlingEstimate(params), kMinSettle, kMaxSettle);
    const double band = params.N - params.Q_dz;
    switch (kind) {
    case ExperimentKind::Step:
        plan.settle = 2 * settle; // from the center through the dead zone, then at rest
        plan.duration = 2 * settle;
        plan.tauFrom = params.K_max * (params.Q_dz + 0.25 * band);
        plan.tauTo = params.K_max * (params.Q_dz + 0.75 * band);
        break;
    case ExperimentKind::Frequency: {
        plan.settle = settle;
        plan.offset = params.K_max * (params.Q_dz + 0.5 * band);
        plan.amplitude = params.K_max * 0.25 * band;
        const double bandwidth = analysis::modelBandwidth(params);
        const double lo = std::isfinite(bandwidth) ? kLowestFactor * bandwidth : 1;
        const double hi =
            std::min(kMaxFrequency, std::isfinite(bandwidth) ? kHighestFactor * bandwidth : 10.0);
        for (int i = 0; i < kDefaultPoints; ++i)
            plan.frequencies.append(lo * std::pow(hi / lo, double(i) / (kDefaultPoints - 1)));
        break;
    }
    case ExperimentKind::Spectrum:
        plan.settle = 0;
        plan.duration = 2;
        break;
    }
    return plan;
}

QString ExperimentPlan::check(double tauLimit) const
{
    auto finiteIn = [](double v, double lo, double hi) {
        return std::isfinite(v) && v >= lo && v <= hi;
    };
    if (!finiteIn(settle, 0, kMaxDuration))
        return u"The settling time must be 0 to " + number(kMaxDuration) + u" s, got " +
               number(settle) + u" s.";
    if (kind != ExperimentKind::Frequency && !(finiteIn(duration, 0, kMaxDuration) && duration > 0))
        return u"The duration must be above 0 and at most " + number(kMaxDuration) + u" s, got " +
               number(duration) + u" s.";
    switch (kind) {
    case ExperimentKind::Step:
        for (double tau : {tauFrom, tauTo}) {
            if (!std::isfinite(tau) || !atMostAsDeviceFloat(std::abs(tau), tauLimit))
                return u"A step level must lie within the torque limit ±" + number(tauLimit) +
                       u" N·m, got " + number(tau) + u" N·m.";
        }
        if (tauFrom == tauTo)
            return QStringLiteral("The step must change the torque: its two levels are equal.");
        // τ_ext travels as a 32-bit float: levels that round to one float are no step.
        if (static_cast<float>(tauFrom) == static_cast<float>(tauTo))
            return u"The step must change the torque: its levels " + number(tauFrom) + u" and " +
                   number(tauTo) + u" N·m are one and the same 32-bit float, as τ_ext travels.";
        break;
    case ExperimentKind::Frequency:
        if (!std::isfinite(offset) || !(amplitude > 0) || !std::isfinite(amplitude) ||
            !atMostAsDeviceFloat(std::abs(offset) + amplitude, tauLimit))
            return u"The sine (offset " + number(offset) + u" N·m, amplitude " + number(amplitude) +
                   u" N·m) must have an amplitude above 0 and stay within the torque limit ±" +
                   number(tauLimit) + u" N·m.";
        // τ_ext travels as a 32-bit float: a sine its rounding flattens excites nothing.
        if (static_cast<float>(offset + amplitude) == static_cast<float>(offset) ||
            static_cast<float>(offset - amplitude) == static_cast<float>(offset))
            return u"The sine's amplitude " + number(amplitude) +
                   u" N·m is lost around its offset " + number(offset) +
                   u" N·m in the 32-bit float τ_ext travels as; give a larger amplitude.";
        if (frequencies.isEmpty() || frequencies.size() > kMaxFrequencies)
            return u"A frequency response needs 1 to " + QString::number(kMaxFrequencies) +
                   u" frequencies, got " + QString::number(frequencies.size()) + u'.';
        if (cycles < 1 || cycles > kMaxCycles)
            return u"The cycles per frequency must be 1 to " + QString::number(kMaxCycles) +
                   u", got " + QString::number(cycles) + u'.';
        for (qsizetype i = 0; i < frequencies.size(); ++i) {
            if (!(frequencies[i] > 0) || !(frequencies[i] <= kMaxFrequency))
                return u"Each frequency must be above 0 and at most " + number(kMaxFrequency) +
                       u" Hz, got " + number(frequencies[i]) + u" Hz.";
            // Its measured periods alone must fit in the longest plan.
            if (!(cycles / frequencies[i] <= kMaxDuration))
                return u"Each frequency must be at least " +
                       QString::number(cycles / kMaxDuration, 'g', 3) + u" Hz, so that its " +
                       QString::number(cycles) + u" measured periods fit in the " +
                       number(kMaxDuration) + u" s an experiment may last, got " +
                       number(frequencies[i]) + u" Hz.";
            if (i > 0 && !(frequencies[i] > frequencies[i - 1]))
                return QStringLiteral("The frequencies must ascend, each one above the last.");
        }
        break;
    case ExperimentKind::Spectrum:
        if (!(duration >= kMinSpectrumDuration))
            return u"A spectrum needs a duration of at least " + number(kMinSpectrumDuration) +
                   u" s (a resolution of " + number(1 / kMinSpectrumDuration) + u" Hz), got " +
                   number(duration) + u" s.";
        break;
    }
    if (!(totalDuration() <= kMaxDuration))
        return u"The experiment would last " + seconds(totalDuration()) + u", more than " +
               number(kMaxDuration) + u" s; shorten it.";
    return {};
}

QList<SineSegment> ExperimentPlan::segments() const
{
    QList<SineSegment> out;
    double t = settle; // the bias alone first
    for (double f : frequencies) {
        SineSegment s;
        s.frequency = f;
        s.start = t;
        s.analyseFrom = t + settle + kGuard;
        s.analyseTo = s.analyseFrom + cycles / f;
        s.end = s.analyseTo + kGuard;
        out.append(s);
        t = s.end;
    }
    return out;
}

double ExperimentPlan::totalDuration() const
{
    switch (kind) {
    case ExperimentKind::Step:
    case ExperimentKind::Spectrum:
        return settle + duration;
    case ExperimentKind::Frequency: {
        const QList<SineSegment> s = segments();
        return s.isEmpty() ? settle : s.last().end;
    }
    }
    return 0;
}

double ExperimentPlan::tauExt(double t) const
{
    if (t < 0 || t >= totalDuration())
        return 0;
    switch (kind) {
    case ExperimentKind::Step:
        return t < settle ? tauFrom : tauTo;
    case ExperimentKind::Frequency:
        for (const SineSegment &s : segments()) {
            if (t >= s.start && t < s.end)
                return offset +
                       amplitude * std::sin(2 * std::numbers::pi * s.frequency * (t - s.start));
        }
        return offset;
    case ExperimentKind::Spectrum:
        return 0;
    }
    return 0;
}

} // namespace hatpic
