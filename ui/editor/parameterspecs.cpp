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
};

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

} // namespace hatpic
