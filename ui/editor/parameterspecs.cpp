#include "editor/parameterspecs.h"

#include "model/paramtable.h"

#include <QCoreApplication>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("hatpic::ParameterSpecs", text);
}

QString text(std::string_view s)
{
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

//! The table's facts (model/paramtable.h) for one field; the caller adds what only a form
//! needs: the explanation, slider range and steps. The tooltip ends with the valid range.
template<typename Params>
ParameterField::Spec fromTable(const FieldSpec<Params> &f, double low, double high,
                               const char *explanation)
{
    ParameterField::Spec s;
    s.key = text(f.name);
    s.symbol = text(f.symbol);
    s.meaning = QCoreApplication::translate("hatpic::ParameterSpecs", f.label.data());
    s.unit = text(f.unit);
    s.toolTip = tr(explanation) + u"<br>" + tr("Valid: %1.").arg(text(rangeText(f)));
    s.minimum = low;
    s.maximum = high;
    // A bound the rule excludes is no value to clamp to (N > 0): typing beyond it is refused.
    s.minimumExclusive = f.lower.present && !f.lower.inclusive && low == f.lower.value;
    s.maximumExclusive = f.upper.present && !f.upper.inclusive && high == f.upper.value;
    s.angle = f.angle;
    return s;
}

ParameterField::Spec deviceSpec(int index, const char *explanation)
{
    const NumericRange r = numericRange(index);
    return fromTable(kDeviceFields[std::size_t(index)], r.low, r.high, explanation);
}

ParameterField::Spec hostSpec(const HostFieldSpec &f, const char *explanation)
{
    return fromTable(f, f.lower.value, f.upper.value, explanation);
}

// The table's short labels, marked for translation (QT_TRANSLATE_NOOP's job).
[[maybe_unused]] const char *const kLabels[] = {
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "inertia"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "damping"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "outer stiffness (minimum)"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "notch stiffness (maximum)"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "notch half-width"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "dead-zone half-width"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "center angle"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "max. reference velocity"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "actuator torque limit"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "detent strength"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "detent spacing"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "detent range"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "lower end stop"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "upper end stop"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "wall stiffness"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "wall damping"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "amplitude"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "frequency"),
    QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "duration"),
};

//! An upper bound given when validating (tau_limit) is not a number of the table: the spin
//! box goes up to the largest tau_limit there can be.
double spinMaximum(const FieldBound &upper)
{
    return upper.external ? kHostFields[1].upper.value : upper.value;
}

template<typename Params>
ParameterField::Spec tableSpec(const FieldSpec<Params> &f, const char *explanation)
{
    return fromTable(f, f.lower.value, spinMaximum(f.upper), explanation);
}

} // namespace

QList<ParameterField::Spec> deviceFieldSpecs()
{
    QList<ParameterField::Spec> specs;

    ParameterField::Spec s = deviceSpec(
        0, QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                             "Virtual <b>inertia</b> of the admittance filter (the paper's naming: "
                             "D_adm is the inertia, M_adm the damping). More inertia makes the "
                             "knob feel heavier and slower to get moving."));
    s.sliderMin = 1e-6;
    s.sliderMax = 1.0;
    s.logSlider = true;
    s.relativeStep = true;
    s.step = 1e-5;
    specs << s;

    s = deviceSpec(1, QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                        "Virtual <b>damping</b> of the admittance filter (the "
                                        "paper's naming: M_adm is the damping, D_adm the "
                                        "inertia). More damping makes the knob feel viscous and "
                                        "stops it ringing."));
    s.sliderMin = 1e-5;
    s.sliderMax = 10.0;
    s.logSlider = true;
    s.relativeStep = true;
    s.step = 1e-3;
    specs << s;

    s = deviceSpec(2, QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                        "Re-centering stiffness far from center, |θ−θ0| ≥ 2N. "
                                        "Between N and 2N the stiffness falls linearly from "
                                        "K_max to K_min."));
    s.sliderMin = 0.0;
    s.sliderMax = 5.0;
    s.step = 0.01;
    specs << s;

    s = deviceSpec(3, QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                        "Re-centering stiffness in the notch band Q_dz ≤ |θ−θ0| "
                                        "≤ N. Also sets ω_n and ζ below."));
    s.sliderMin = 0.0;
    s.sliderMax = 5.0;
    s.step = 0.01;
    specs << s;

    s = deviceSpec(4, QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                        "Half-width of the notch band: K_max holds up to "
                                        "|θ−θ0| = N, then falls to K_min at 2N."));
    s.sliderMin = 0.0;
    s.sliderMax = s.maximum;
    s.step = 0.005;
    specs << s;

    s = deviceSpec(5, QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                        "No re-centering torque while |θ−θ0| < Q_dz. At Q_dz the "
                                        "stiffness jumps to K_max: that jump is the notch the "
                                        "hand feels."));
    s.sliderMin = 0.0;
    s.sliderMax = 0.5;
    s.step = 0.001;
    specs << s;

    s = deviceSpec(6, QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                        "Idle angle the knob is pulled back to (absolute knob "
                                        "angle)."));
    s.sliderMin = s.minimum;
    s.sliderMax = s.maximum;
    s.step = 0.01;
    specs << s;

    return specs;
}

ParameterField::Spec vMaxSpec()
{
    ParameterField::Spec s = hostSpec(
        kHostFields[0],
        QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                          "Host side only, never sent to the device: v_ref = clamp(v_max/2 · "
                          "(θ−θ0), ±v_max). Unit follows the mode (m/s or rad/s)."));
    s.unit = u"m/s"_s; // the editor shows the mode's unit (setUnit)
    s.sliderMin = 0.01;
    s.sliderMax = 100.0;
    s.logSlider = true;
    s.relativeStep = true;
    s.step = 0.1;
    return s;
}

ParameterField::Spec tauLimitSpec()
{
    ParameterField::Spec s = hostSpec(
        kHostFields[1],
        QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                          "Largest torque the actuator renders (STS3032: 0.44 N·m); the device "
                          "clips |τ_total| to it. Connected devices report their own value."));
    s.sliderMin = 0.0;
    s.sliderMax = 2.0;
    s.step = 0.01;
    return s;
}

QList<ParameterField::Spec> effectFieldSpecs()
{
    const char *const explanations[] = {
        QT_TRANSLATE_NOOP(
            "hatpic::ParameterSpecs",
            "Torque of the <b>detents</b>: τ_det = −A·sin(2π·(θ−θ0)/s) pulls the knob "
            "into rest positions θ0 + i·s. 0 turns detents off."),
        QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                          "Distance between two detent rest positions (one click)."),
        QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                          "Detents act while |θ−θ0| ≤ R_det (at R_det exactly still). 0 turns "
                          "detents off."),
        QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                          "Lower <b>end stop</b>, relative to θ0: below it a spring K_w pushes "
                          "the knob back. −π: no wall."),
        QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                          "Upper <b>end stop</b>, relative to θ0: beyond it a spring K_w pushes "
                          "the knob back. π: no wall."),
        QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                          "Stiffness of the end stops. Too stiff a wall chatters: see the "
                          "warnings below the fields."),
        QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                          "Damping of the end stops, only while the knob moves further in, so "
                          "a wall never pulls the knob back."),
    };
    // Practical slider ranges: a clearly felt detent is 0.02–0.1 N·m on the STS3032, and a
    // wall stiffer than about 2.5 N·m/rad bounces there (docs/effects.md).
    const struct
    {
        double sliderMin, sliderMax, step;
    } ranges[] = {{0.0, 0.44, 0.005},
                  {0.01, 1.0, 0.01},
                  {0.0, paramtable::kPi, 0.01},
                  {-paramtable::kPi, 0.0, 0.01},
                  {0.0, paramtable::kPi, 0.01},
                  {0.0, 10.0, 0.05},
                  {0.0, 0.1, 0.001}};
    QList<ParameterField::Spec> specs;
    for (int i = 0; i < EffectParams::kFieldCount; ++i) {
        ParameterField::Spec s = tableSpec(kEffectFields[std::size_t(i)], explanations[i]);
        s.sliderMin = ranges[i].sliderMin;
        s.sliderMax = ranges[i].sliderMax;
        s.step = ranges[i].step;
        specs << s;
    }
    return specs;
}

QList<ParameterField::Spec> vibrationFieldSpecs()
{
    const char *const explanations[] = {
        QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                          "Peak torque of the cue: τ_vib = a·sin(2π·f·t). 0.02–0.1 N·m are "
                          "clearly felt."),
        QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                          "Frequency of the cue; below half the device's control rate."),
        QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "How long the cue lasts."),
    };
    const struct
    {
        double sliderMin, sliderMax, step;
    } ranges[] = {{0.0, 0.44, 0.005}, {1.0, 500.0, 1.0}, {0.0, 2.0, 0.05}};
    QList<ParameterField::Spec> specs;
    for (std::size_t i = 0; i < kVibrationFields.size(); ++i) {
        ParameterField::Spec s = tableSpec(kVibrationFields[i], explanations[i]);
        s.key = u"vibrate_"_s + s.key; // object names apart from the effect fields
        s.sliderMin = ranges[i].sliderMin;
        s.sliderMax = ranges[i].sliderMax;
        s.step = ranges[i].step;
        specs << s;
    }
    return specs;
}

} // namespace hatpic
