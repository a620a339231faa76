#include "experimenttext.h"

#include "telemetry/numbertext.h"

#include <cmath>
#include <numbers>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

QString figure(double value, int decimals)
{
    return std::isfinite(value) ? QString::number(value, 'f', decimals) : u"–"_s;
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
    QString out = row(u"figure"_s, u"measured"_s, u"model"_s);
    out += row(u"omega_n [rad/s]"_s, figure(r.fitMeasured.omegaN, 2), figure(r.figures.omega_n, 2));
    out += row(u"zeta"_s, figure(r.fitMeasured.zeta, 3), figure(r.figures.zeta, 3));
    out += row(u"rise time [s]"_s, figure(r.stepMeasured.riseTime, 4),
               figure(r.stepIdeal.riseTime, 4));
    out += row(u"overshoot [%]"_s, figure(100 * r.stepMeasured.overshoot, 1),
               figure(100 * r.stepIdeal.overshoot, 1));
    out += row(u"settling time [s]"_s, figure(r.stepMeasured.settlingTime, 4),
               figure(r.stepIdeal.settlingTime, 4));
    out += row(u"step in theta [rad]"_s, figure(r.fitMeasured.gain, 4),
               figure((r.plan.tauTo - r.plan.tauFrom) / r.params.K_max, 4));
    out += row(u"fit rms [rad]"_s, figure(r.fitMeasured.rmsResidual, 5), QString());
    return out;
}

QString bodeReport(const ExperimentResult &r)
{
    QString out = u"frequency [Hz]"_s.leftJustified(16) + u"|H| [dB]"_s.rightJustified(10) +
                  u"model"_s.rightJustified(10) + u"phase [deg]"_s.rightJustified(13) +
                  u"model"_s.rightJustified(10) + u'\n';
    for (const analysis::FrequencyPoint &p : r.points) {
        const std::complex<double> model = analysis::modelGain(r.params, p.frequency);
        out += figure(p.frequency, 2).leftJustified(16) +
               figure(20 * std::log10(p.magnitude), 2).rightJustified(10) +
               figure(20 * std::log10(std::abs(model)), 2).rightJustified(10) +
               figure(degrees(p.phase), 1).rightJustified(13) +
               figure(degrees(std::arg(model)), 1).rightJustified(10) + u'\n';
    }
    out += u"(|H| = |theta/tau_ext| in dB re 1 rad/(N·m))\n";
    out += row(u"bandwidth [Hz]"_s, figure(r.bandwidth, 2), figure(r.modelBandwidth, 2));
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
        out += peakLine(u"theta"_s, r.thetaSpectrum, u"rad"_s);
        out += peakLine(u"tau"_s, r.tauSpectrum, u"N·m"_s);
        break;
    }
    out += u"hand: " + runHandText(r.hand) + u'\n'; // what else held the knob
    return out;
}

} // namespace hatpic::cli
