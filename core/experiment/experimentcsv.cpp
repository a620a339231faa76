#include "experimentcsv.h"

#include "telemetry/numbertext.h"

#include <cmath>

namespace hatpic {

QByteArray experimentCsv(const ExperimentResult &r)
{
    QString out;
    switch (r.plan.kind) {
    case ExperimentKind::Step: {
        // The measured response from the step on, and the ideal model's at the same time.
        out = QStringLiteral("t_s,theta,tau_ext,model_theta\n");
        for (const Sample &s : r.samples) {
            const double t = s.t_s - r.stepAt;
            if (t < -r.plan.settle / 4 || t > r.plan.duration)
                continue;
            const auto index =
                static_cast<qsizetype>(std::llround((r.idealStepAt + t) * r.sampleRate));
            const QString model = index >= 0 && index < r.ideal.size()
                                      ? compactNumberText(r.ideal[index].theta)
                                      : QString();
            out += compactNumberText(t) + u',' + compactNumberText(s.theta) + u',' +
                   compactNumberText(s.tau_ext) + u',' + model + u'\n';
        }
        break;
    }
    case ExperimentKind::Frequency:
        out = QStringLiteral("frequency_hz,magnitude,phase,model_magnitude,model_phase\n");
        for (const analysis::FrequencyPoint &p : r.points) {
            const std::complex<double> model = analysis::modelGain(r.params, p.frequency);
            out += compactNumberText(p.frequency) + u',' + compactNumberText(p.magnitude) + u',' +
                   compactNumberText(p.phase) + u',' + compactNumberText(std::abs(model)) + u',' +
                   compactNumberText(std::arg(model)) + u'\n';
        }
        break;
    case ExperimentKind::Spectrum:
        out = QStringLiteral("frequency_hz,theta,theta_db,tau,tau_db\n");
        for (std::size_t k = 0; k < r.thetaSpectrum.frequency.size(); ++k) {
            out += compactNumberText(r.thetaSpectrum.frequency[k]) + u',' +
                   compactNumberText(r.thetaSpectrum.amplitude[k]) + u',' +
                   compactNumberText(r.thetaSpectrum.magnitudeDb[k]) + u',' +
                   compactNumberText(r.tauSpectrum.amplitude[k]) + u',' +
                   compactNumberText(r.tauSpectrum.magnitudeDb[k]) + u'\n';
        }
        break;
    }
    return out.toUtf8();
}

} // namespace hatpic
