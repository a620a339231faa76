#include "experimenttext.h"

#include "telemetry/numbertext.h"

#include <cmath>
#include <numbers>

namespace hatpic::cli {

namespace {

QString figure(double value, int decimals)
{
    return std::isfinite(value) ? QString::number(value, 'f', decimals) : QStringLiteral("–");
}

QString row(const QString &name, const QString &measured, const QString &model)
{
    const QString line = name.leftJustified(22) + measured.rightJustified(12) +
                         (model.isEmpty() ? QString() : model.rightJustified(12));
    return line + u'\n';
}

double degrees(double rad)
{
    return rad * 180 / std::numbers::pi;
}

QString stepReport(const ExperimentResult &r)
{
    QString out =
        row(QStringLiteral("figure"), QStringLiteral("measured"), QStringLiteral("model"));
    out += row(QStringLiteral("omega_n [rad/s]"), figure(r.fitMeasured.omegaN, 2),
               figure(r.figures.omega_n, 2));
    out += row(QStringLiteral("zeta"), figure(r.fitMeasured.zeta, 3), figure(r.figures.zeta, 3));
    out += row(QStringLiteral("rise time [s]"), figure(r.stepMeasured.riseTime, 4),
               figure(r.stepIdeal.riseTime, 4));
    out += row(QStringLiteral("overshoot [%]"), figure(100 * r.stepMeasured.overshoot, 1),
               figure(100 * r.stepIdeal.overshoot, 1));
    out += row(QStringLiteral("settling time [s]"), figure(r.stepMeasured.settlingTime, 4),
               figure(r.stepIdeal.settlingTime, 4));
    out += row(QStringLiteral("step in theta [rad]"), figure(r.fitMeasured.gain, 4),
               figure((r.plan.tauTo - r.plan.tauFrom) / r.params.K_max, 4));
    out += row(QStringLiteral("fit rms [rad]"), figure(r.fitMeasured.rmsResidual, 5), QString());
    return out;
}

QString bodeReport(const ExperimentResult &r)
{
    QString out = QStringLiteral("frequency [Hz]").leftJustified(16) +
                  QStringLiteral("|H| [dB]").rightJustified(10) +
                  QStringLiteral("model").rightJustified(10) +
                  QStringLiteral("phase [deg]").rightJustified(13) +
                  QStringLiteral("model").rightJustified(10) + u'\n';
    for (const analysis::FrequencyPoint &p : r.points) {
        const std::complex<double> model = analysis::modelGain(r.params, p.frequency);
        out += figure(p.frequency, 2).leftJustified(16) +
               figure(20 * std::log10(p.magnitude), 2).rightJustified(10) +
               figure(20 * std::log10(std::abs(model)), 2).rightJustified(10) +
               figure(degrees(p.phase), 1).rightJustified(13) +
               figure(degrees(std::arg(model)), 1).rightJustified(10) + u'\n';
    }
    out += u"(|H| = |theta/tau_ext| in dB re 1 rad/(N·m))\n";
    out +=
        row(QStringLiteral("bandwidth [Hz]"), figure(r.bandwidth, 2), figure(r.modelBandwidth, 2));
    return out;
}

QString peakLine(const QString &name, const analysis::Spectrum &s, const QString &unit)
{
    // Above the lowest bins, which hold what is left of the slow drift.
    const analysis::SpectrumPeak peak = analysis::dominantPeak(s, 2 * s.resolution);
    if (!std::isfinite(peak.frequency))
        return name + u": no line (the signal is constant)\n";
    return name + u": strongest line " + figure(peak.frequency, 1) + u" Hz at " +
           figure(peak.magnitudeDb, 1) + u" dB re 1 " + unit + u" (amplitude " +
           QString::number(peak.amplitude, 'g', 3) + u' ' + unit + u")\n";
}

} // namespace

QString experimentReport(const ExperimentResult &r)
{
    QString out;
    switch (r.plan.kind) {
    case ExperimentKind::Step:
        out = stepReport(r);
        break;
    case ExperimentKind::Frequency:
        out = bodeReport(r);
        break;
    case ExperimentKind::Spectrum:
        out = u"samples: " +
              QString::number(std::llround(r.sampleRate / r.thetaSpectrum.resolution)) + u" at " +
              figure(r.sampleRate, 1) + u" Hz, resolution " +
              figure(r.thetaSpectrum.resolution, 3) + u" Hz\n";
        out += peakLine(QStringLiteral("theta"), r.thetaSpectrum, QStringLiteral("rad"));
        out += peakLine(QStringLiteral("tau"), r.tauSpectrum, QStringLiteral("N·m"));
        break;
    }
    out += u"hand: " + runHandText(r.hand) + u'\n'; // what else held the knob
    return out;
}

} // namespace hatpic::cli
