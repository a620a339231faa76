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

//! What the table leaves to a form: how each field acts, in a tooltip's words.
struct Explanation
{
    std::string_view field; //!< the table's name
    const char *text;
};

constexpr Explanation kExplanations[] = {
    {"D_adm", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                "Virtual <b>inertia</b> of the admittance filter (the paper's "
                                "naming: D_adm is the inertia, M_adm the damping). More inertia "
                                "makes the knob feel heavier and slower to get moving.")},
    {"M_adm", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                "Virtual <b>damping</b> of the admittance filter (the paper's "
                                "naming: M_adm is the damping, D_adm the inertia). More damping "
                                "makes the knob feel viscous and stops it ringing.")},
    {"K_min", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                "Re-centering stiffness far from center, |θ−θ0| ≥ 2N. Between N "
                                "and 2N the stiffness falls linearly from K_max to K_min.")},
    {"K_max", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                "Re-centering stiffness in the notch band Q_dz ≤ |θ−θ0| ≤ N. "
                                "Also sets ω_n and ζ below.")},
    {"N", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                            "Half-width of the notch band: K_max holds up to |θ−θ0| = N, then "
                            "falls to K_min at 2N.")},
    {"Q_dz", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                               "No re-centering torque while |θ−θ0| < Q_dz. At Q_dz the "
                               "stiffness jumps to K_max: that jump is the notch the hand "
                               "feels.")},
    {"theta0", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                 "Idle angle the knob is pulled back to (absolute knob angle).")},
    {"v_max", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                "Host side only, never sent to the device: v_ref = "
                                "clamp(v_max/2 · (θ−θ0), ±v_max). Unit follows the mode (m/s "
                                "or rad/s).")},
    {"tau_limit", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                    "Largest torque the actuator renders (STS3032: 0.44 N·m); "
                                    "the device clips |τ_total| to it. Connected devices report "
                                    "their own value.")},
    {"detent_strength",
     QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                       "Torque of the <b>detents</b>: τ_det = −A·sin(2π·(θ−θ0)/s) pulls the "
                       "knob into rest positions θ0 + i·s. 0 turns detents off.")},
    {"detent_spacing",
     QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "Distance between two detent rest positions (one "
                                                 "click).")},
    {"detent_range", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                       "Detents act while |θ−θ0| ≤ R_det (at R_det exactly "
                                       "still). 0 turns detents off.")},
    {"wall_min", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                   "Lower <b>end stop</b>, relative to θ0: below it a spring K_w "
                                   "pushes the knob back. −π: no wall.")},
    {"wall_max", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                   "Upper <b>end stop</b>, relative to θ0: beyond it a spring "
                                   "K_w pushes the knob back. π: no wall.")},
    {"wall_stiffness", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                         "Stiffness of the end stops. Too stiff a wall chatters: "
                                         "see the warnings below the fields.")},
    {"wall_damping", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                       "Damping of the end stops, only while the knob moves "
                                       "further in, so a wall never pulls the knob back.")},
    {"amplitude", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                    "Peak torque of the cue: τ_vib = a·sin(2π·f·t). 0.02–0.1 N·m "
                                    "are clearly felt.")},
    {"frequency", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs",
                                    "Frequency of the cue; below half the device's control "
                                    "rate.")},
    {"duration", QT_TRANSLATE_NOOP("hatpic::ParameterSpecs", "How long the cue lasts.")},
};

QString explanation(std::string_view field)
{
    for (const Explanation &e : kExplanations) {
        if (e.field == field)
            return tr(e.text);
    }
    return {};
}

//! The table's facts (model/paramtable.h) for field `f` of `table`, with the explanation as
//! tooltip, which ends with the valid range.
template<typename Params, std::size_t N>
ParameterField::Spec specOf(const FieldSpec<Params> &f,
                            const std::array<FieldSpec<Params>, N> &table)
{
    // No upper bound of its own: the cross rule's partner's (K_min ≤ K_max ≤ 50). One given when
    // validating (tau_limit): the largest tau_limit there can be.
    const FieldBound &upper =
        f.upper.present || f.cross.field < 0 ? f.upper : table[std::size_t(f.cross.field)].upper;
    const double high =
        upper.external ? fieldNamed(kHostFields, "tau_limit").upper.value : upper.value;

    ParameterField::Spec s;
    s.key = text(f.name);
    s.symbol = text(f.symbol);
    s.meaning = tr(f.label.data());
    s.unit = text(f.unit);
    s.toolTip = explanation(f.name) + u"<br>" + tr("Valid: %1.").arg(text(rangeText(f)));
    s.minimum = f.lower.value;
    s.maximum = high;
    // A bound the rule excludes is no value to clamp to (N > 0): typing beyond it is refused.
    s.minimumExclusive = f.lower.present && !f.lower.inclusive;
    s.maximumExclusive = f.upper.present && !f.upper.inclusive && high == f.upper.value;
    s.sliderMin = f.display.low;
    s.sliderMax = f.display.high;
    s.logSlider = f.display.decades;
    s.relativeStep = f.display.decades;
    s.step = f.display.step;
    s.angle = f.angle;
    return s;
}

template<typename Params, std::size_t N>
QList<ParameterField::Spec> specsOf(const std::array<FieldSpec<Params>, N> &table)
{
    QList<ParameterField::Spec> specs;
    for (const FieldSpec<Params> &f : table)
        specs << specOf(f, table);
    return specs;
}

} // namespace

QList<ParameterField::Spec> deviceFieldSpecs()
{
    return specsOf(kDeviceFields);
}

ParameterField::Spec vMaxSpec()
{
    ParameterField::Spec s = specOf(fieldNamed(kHostFields, "v_max"), kHostFields);
    s.unit = u"m/s"_s; // the editor shows the mode's unit (setUnit)
    return s;
}

ParameterField::Spec tauLimitSpec()
{
    return specOf(fieldNamed(kHostFields, "tau_limit"), kHostFields);
}

QList<ParameterField::Spec> effectFieldSpecs()
{
    return specsOf(kEffectFields);
}

QList<ParameterField::Spec> passivityFieldSpecs()
{
    return specsOf(kPassivityFields);
}

QList<ParameterField::Spec> vibrationFieldSpecs()
{
    QList<ParameterField::Spec> specs = specsOf(kVibrationFields);
    for (ParameterField::Spec &s : specs)
        s.key = u"vibrate_"_s + s.key; // object names apart from the effect fields
    return specs;
}

} // namespace hatpic
