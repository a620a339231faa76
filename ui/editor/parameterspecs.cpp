#include "editor/parameterspecs.h"

#include <QCoreApplication>

#include <numbers>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("hatpic::ParameterSpecs", text);
}

constexpr double kPi = std::numbers::pi;

} // namespace

QList<ParameterField::Spec> deviceFieldSpecs()
{
    QList<ParameterField::Spec> specs;

    ParameterField::Spec s;
    s.key = u"D_adm"_s;
    s.symbol = u"D_adm"_s;
    s.meaning = tr("inertia");
    s.unit = u"kg·m²"_s;
    s.toolTip = tr("Virtual <b>inertia</b> of the admittance filter (the paper's naming: D_adm is "
                   "the inertia, M_adm the damping). More inertia makes the knob feel heavier and "
                   "slower to get moving.<br>Valid: 1e-6 ≤ D_adm ≤ 1.");
    s.minimum = 1e-6;
    s.maximum = 1.0;
    s.sliderMin = 1e-6;
    s.sliderMax = 1.0;
    s.logSlider = true;
    s.relativeStep = true;
    s.step = 1e-5;
    specs << s;

    s = {};
    s.key = u"M_adm"_s;
    s.symbol = u"M_adm"_s;
    s.meaning = tr("damping");
    s.unit = u"N·m·s/rad"_s;
    s.toolTip = tr("Virtual <b>damping</b> of the admittance filter (the paper's naming: M_adm is "
                   "the damping, D_adm the inertia). More damping makes the knob feel viscous "
                   "and stops it ringing.<br>Valid: 0 < M_adm ≤ 10.");
    s.minimum = 0.0;
    s.maximum = 10.0;
    s.sliderMin = 1e-5;
    s.sliderMax = 10.0;
    s.logSlider = true;
    s.relativeStep = true;
    s.step = 1e-3;
    specs << s;

    s = {};
    s.key = u"K_min"_s;
    s.symbol = u"K_min"_s;
    s.meaning = tr("outer stiffness (minimum)");
    s.unit = u"N·m/rad"_s;
    s.toolTip = tr("Re-centering stiffness far from center, |θ−θ0| ≥ 2N. Between N and 2N the "
                   "stiffness falls linearly from K_max to K_min.<br>Valid: 0 ≤ K_min ≤ K_max.");
    s.minimum = 0.0;
    s.maximum = 50.0;
    s.sliderMin = 0.0;
    s.sliderMax = 5.0;
    s.step = 0.01;
    specs << s;

    s = {};
    s.key = u"K_max"_s;
    s.symbol = u"K_max"_s;
    s.meaning = tr("notch stiffness (maximum)");
    s.unit = u"N·m/rad"_s;
    s.toolTip = tr("Re-centering stiffness in the notch band Q_dz ≤ |θ−θ0| ≤ N. Also sets ω_n "
                   "and ζ below.<br>Valid: 0 ≤ K_max ≤ 50.");
    s.minimum = 0.0;
    s.maximum = 50.0;
    s.sliderMin = 0.0;
    s.sliderMax = 5.0;
    s.step = 0.01;
    specs << s;

    s = {};
    s.key = u"N"_s;
    s.symbol = u"N"_s;
    s.meaning = tr("notch half-width");
    s.unit = u"rad"_s;
    s.toolTip = tr("Half-width of the notch band: K_max holds up to |θ−θ0| = N, then falls to "
                   "K_min at 2N.<br>Valid: 0 < N ≤ π/2.");
    s.minimum = 0.0;
    s.maximum = kPi / 2;
    s.sliderMin = 0.0;
    s.sliderMax = kPi / 2;
    s.step = 0.005;
    s.angle = true;
    specs << s;

    s = {};
    s.key = u"Q_dz"_s;
    s.symbol = u"Q_dz"_s;
    s.meaning = tr("dead-zone half-width");
    s.unit = u"rad"_s;
    s.toolTip = tr("No re-centering torque while |θ−θ0| < Q_dz. At Q_dz the stiffness jumps to "
                   "K_max: that jump is the notch the hand feels.<br>Valid: 0 ≤ Q_dz < N.");
    s.minimum = 0.0;
    s.maximum = kPi / 2;
    s.sliderMin = 0.0;
    s.sliderMax = 0.5;
    s.step = 0.001;
    s.angle = true;
    specs << s;

    s = {};
    s.key = u"theta0"_s;
    s.symbol = u"θ0"_s;
    s.meaning = tr("center angle");
    s.unit = u"rad"_s;
    s.toolTip = tr("Idle angle the knob is pulled back to (absolute knob angle)."
                   "<br>Valid: −π ≤ θ0 ≤ π.");
    s.minimum = -kPi;
    s.maximum = kPi;
    s.sliderMin = -kPi;
    s.sliderMax = kPi;
    s.step = 0.01;
    s.angle = true;
    specs << s;

    return specs;
}

ParameterField::Spec vMaxSpec()
{
    ParameterField::Spec s;
    s.key = u"v_max"_s;
    s.symbol = u"v_max"_s;
    s.meaning = tr("max. reference velocity");
    s.unit = u"m/s"_s;
    s.toolTip = tr("Host side only, never sent to the device: v_ref = clamp(v_max/2 · (θ−θ0), "
                   "±v_max). Unit follows the mode (m/s or rad/s).<br>Valid: 0 < v_max ≤ 100.");
    s.minimum = 0.0;
    s.maximum = 100.0;
    s.sliderMin = 0.01;
    s.sliderMax = 100.0;
    s.logSlider = true;
    s.relativeStep = true;
    s.step = 0.1;
    return s;
}

ParameterField::Spec tauLimitSpec()
{
    ParameterField::Spec s;
    s.key = u"tau_limit"_s;
    s.symbol = u"tau_limit"_s;
    s.meaning = tr("actuator torque limit");
    s.unit = u"N·m"_s;
    s.toolTip = tr("Largest torque the actuator renders (STS3032: 0.44 N·m); the device clips "
                   "|τ_total| to it. Connected devices report their own value."
                   "<br>Valid: 0 < tau_limit ≤ 10.");
    s.minimum = 0.0;
    s.maximum = 10.0;
    s.sliderMin = 0.0;
    s.sliderMax = 2.0;
    s.step = 0.01;
    return s;
}

} // namespace hatpic
