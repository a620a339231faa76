#include "experimentresult.h"

#include "experiment/idealresponse.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hatpic {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr qsizetype kMinPointSamples = 8; //!< fewer in a sine's window: no point

struct StepSeries
{
    double stepAt = kNaN;
    std::vector<double> t;     //!< since the step [s]
    std::vector<double> theta; //!< [rad]
    double initial = kNaN;     //!< θ at rest before the step [rad]
};

//! The step in the τ_ext column of `samples` (times in `samples`' own clock): the first sample
//! at or after `searchFrom` on the new level's side of the midpoint; the response runs until
//! τ_ext leaves that side again.
StepSeries stepSeries(const ExperimentPlan &plan, const QList<Sample> &samples, double searchFrom,
                      double settle)
{
    StepSeries out;
    const double mid = (plan.tauFrom + plan.tauTo) / 2;
    const double sign = plan.tauTo > plan.tauFrom ? 1.0 : -1.0;
    qsizetype first = -1;
    for (qsizetype i = 0; i < samples.size(); ++i) {
        if (samples[i].t_s >= searchFrom && sign * (samples[i].tau_ext - mid) > 0) {
            first = i;
            break;
        }
    }
    if (first < 0)
        return out;
    out.stepAt = samples[first].t_s;
    double sum = 0;
    int count = 0;
    for (qsizetype i = first - 1; i >= 0 && samples[i].t_s >= out.stepAt - settle / 4; --i) {
        sum += samples[i].theta;
        ++count;
    }
    out.initial = count > 0 ? sum / count : samples[first].theta;
    for (qsizetype i = first; i < samples.size() && sign * (samples[i].tau_ext - mid) > 0; ++i) {
        out.t.push_back(samples[i].t_s - out.stepAt);
        out.theta.push_back(samples[i].theta);
    }
    return out;
}

void analyseStep(ExperimentResult &r)
{
    const ExperimentPlan &plan = r.plan;
    const StepSeries measured =
        stepSeries(plan, r.samples, r.clock.deviceTime(plan.settle / 2), plan.settle);
    if (measured.t.empty()) {
        r.problem = QStringLiteral("No step appears in the device's τ_ext column: the device did "
                                   "not apply the feedback (it ignores τ_ext, or it did not "
                                   "reach it).");
        r.unmeasured = true;
        return;
    }
    r.stepAt = measured.stepAt;
    r.stepMeasured = analysis::stepMetrics(measured.t, measured.theta, measured.initial,
                                           analysis::tailMean(measured.theta));
    r.fitMeasured = analysis::fitSecondOrderStep(measured.t, measured.theta);
    if (!r.fitMeasured.ok)
        r.problem = QString::fromStdString(r.fitMeasured.problem);

    if (r.sampleRate > 0) {
        r.ideal = idealResponse(plan, r.params, r.tauLimit, r.sampleRate);
        const StepSeries ideal = stepSeries(plan, r.ideal, plan.settle / 2, plan.settle);
        if (!ideal.t.empty()) {
            r.idealStepAt = ideal.stepAt;
            r.stepIdeal = analysis::stepMetrics(ideal.t, ideal.theta, ideal.initial,
                                                analysis::tailMean(ideal.theta));
            r.fitIdeal = analysis::fitSecondOrderStep(ideal.t, ideal.theta);
        }
    }
}

void analyseFrequency(ExperimentResult &r)
{
    r.modelBandwidth = analysis::modelBandwidth(r.params);
    QStringList missing;
    for (const SineSegment &segment : r.plan.segments()) {
        std::vector<double> t, u, y;
        const double from = r.clock.deviceTime(segment.analyseFrom);
        const double to = r.clock.deviceTime(segment.analyseTo + ExperimentPlan::kGuard / 2);
        for (const Sample &s : r.samples) {
            if (s.t_s >= from && s.t_s <= to) {
                t.push_back(s.t_s);
                u.push_back(s.tau_ext);
                y.push_back(s.theta);
            }
        }
        const std::size_t n = analysis::wholePeriods(t, segment.frequency);
        if (n < static_cast<std::size_t>(kMinPointSamples)) {
            missing.append(QString::number(segment.frequency, 'g', 4) + u" Hz");
            continue;
        }
        r.points.push_back(analysis::frequencyPoint(std::span(t).first(n), std::span(u).first(n),
                                                    std::span(y).first(n), segment.frequency));
    }
    analysis::unwrapPhase(r.points);
    r.bandwidth = analysis::measuredBandwidth(r.points);
    if (!missing.isEmpty()) {
        r.problem = u"Too few samples to measure " + missing.join(u", ") +
                    u": the device stopped streaming, or streams too slowly for them.";
        r.unmeasured = true;
    }
}

} // namespace

void ClockMap::add(double planTime, double offset)
{
    if (m_points.size() < kMaxPoints)
        m_points.emplace_back(planTime, offset);
}

double ClockMap::deviceTime(double planTime) const
{
    double best = -std::numeric_limits<double>::infinity();
    double overall = best;
    for (const auto &[p, offset] : m_points) {
        overall = std::max(overall, offset);
        if (std::abs(p - planTime) <= kWindow)
            best = std::max(best, offset);
    }
    if (m_points.empty())
        return planTime;
    return planTime + (std::isfinite(best) ? best : overall);
}

void spectraOf(const QList<Sample> &samples, analysis::Spectrum &theta, analysis::Spectrum &tau)
{
    std::vector<double> t, th, ta;
    for (const Sample &s : samples) {
        t.push_back(s.t_s);
        th.push_back(s.theta);
        ta.push_back(s.tau);
    }
    const double rate = analysis::sampleRate(t);
    theta = analysis::amplitudeSpectrum(th, rate);
    tau = analysis::amplitudeSpectrum(ta, rate);
}

QString runHandText(RunHand hand)
{
    switch (hand) {
    case RunHand::SimulatedIdle:
        return QStringLiteral("idle (simulated)");
    case RunHand::User:
        break;
    }
    return QStringLiteral("the user's (real device)");
}

ExperimentResult analyseExperiment(const ExperimentPlan &plan, const QList<Sample> &samples,
                                   const ClockMap &clock, const DeviceParams &params,
                                   double tauLimit)
{
    ExperimentResult r;
    r.plan = plan;
    r.params = params;
    r.tauLimit = tauLimit;
    HostParams host;
    host.tau_limit = tauLimit;
    r.figures = deriveFigures(params, host);
    r.samples = samples;
    r.clock = clock;
    r.stepAt = r.idealStepAt = r.bandwidth = r.modelBandwidth = kNaN;
    std::vector<double> t;
    t.reserve(static_cast<std::size_t>(samples.size()));
    for (const Sample &s : samples)
        t.push_back(s.t_s);
    r.sampleRate = analysis::sampleRate(t);
    switch (plan.kind) {
    case ExperimentKind::Step:
        analyseStep(r);
        break;
    case ExperimentKind::Frequency:
        analyseFrequency(r);
        break;
    case ExperimentKind::Spectrum: {
        QList<Sample> window;
        const double from = clock.deviceTime(plan.settle);
        const double to = clock.deviceTime(plan.totalDuration());
        for (const Sample &s : samples) {
            if (s.t_s >= from && s.t_s < to)
                window.append(s);
        }
        // The window holds duration · rate samples: a boundary that falls on a sample (in
        // floating point, or with the device's clock a little uneven) must not add one.
        if (window.size() > 2) {
            const double dt = (window.last().t_s - window.first().t_s) / double(window.size() - 1);
            const auto expected = qsizetype(std::llround(plan.duration / dt));
            if (dt > 0 && expected >= 2 && window.size() > expected)
                window.resize(expected);
        }
        spectraOf(window, r.thetaSpectrum, r.tauSpectrum);
        if (r.thetaSpectrum.frequency.empty()) {
            r.problem = u"Too few samples for a spectrum: " + QString::number(window.size()) +
                        u" in the " + QString::number(plan.duration, 'g', 3) + u" s recorded.";
            r.unmeasured = true;
        }
        break;
    }
    }
    return r;
}

} // namespace hatpic
