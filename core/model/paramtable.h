// The parameter table: every fact about each parameter in one place — name, symbol, unit, meaning,
// bounds and cross-field rule, tuning range and step, wire index — read by validation, wire
// rounding, the JSON of profiles and recordings, the editor, the CLI's tables and the docs' test.
// Defaults live in the structs' member initializers (params.h), which the table points to.
//
// Plain C++20, constexpr: the device core reads it too.
#pragma once

#include "effects.h"
#include "params.h"
#include "passivity.h"

#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>

namespace hatpic {

//! The one comparison against a bound the device holds as float32 — tau_limit, for
//! detent_strength, a vibration's amplitude and an experiment's τ_ext: `value` is within it
//! when the float32 it travels as is at most the bound's float32. So 0.44 is within a device's
//! tau_limit 0.4399999976158142 (both are 0.44f), as the device itself finds. NaN never is.
inline bool atMostAsDeviceFloat(double value, double bound)
{
    // double → float is undefined beyond the float range: there a value is ±infinity.
    const auto single = [](double v) {
        constexpr double kMax = std::numeric_limits<float>::max();
        constexpr float kInf = std::numeric_limits<float>::infinity();
        return v > kMax ? kInf : v < -kMax ? -kInf : static_cast<float>(v); // NaN stays NaN
    };
    return single(value) <= single(bound);
}

//! One end of a field's range. `symbol` is set where the bound is not a short decimal
//! ("π/2"); messages then give both, e.g. "must be ≤ π/2 (1.5707963267948966)".
struct FieldBound
{
    bool present = false;
    double value = 0;
    bool inclusive = true;
    std::string_view symbol;
    //! The value is given when validating (tau_limit, a float32 of the device's), and compared
    //! with atMostAsDeviceFloat().
    bool external = false;
};

//! A rule against another field of the same set: value ≤ other (or < when strict).
struct CrossRule
{
    int field = -1; //!< index of the other field, -1 = none
    bool strict = false;
};

//! How a person sets the value: the range it is usually tuned in (a slider's, narrower than the
//! valid one) and the step a click moves it by [the field's unit].
struct FieldDisplay
{
    double low = 0;
    double high = 1;
    double step = 0.01;
    bool decades = false; //!< spans decades: a log scale, steps relative to the value
};

template<typename Params> struct FieldSpec
{
    std::string_view name;    //!< key in files, CLI and protocol docs: "K_min"
    std::string_view symbol;  //!< what a person reads: "K_min", "θ0"
    std::string_view unit;    //!< SI unit: "N·m/rad"
    std::string_view label;   //!< short meaning for a form: "notch stiffness (maximum)"
    std::string_view meaning; //!< one-line meaning: "maximum (notch) re-centering stiffness"
    double Params::*member;
    FieldBound lower;
    FieldBound upper;
    CrossRule cross;
    bool angle = false; //!< an angle: user interfaces may show degrees
    FieldDisplay display;
};

using DeviceFieldSpec = FieldSpec<DeviceParams>;
using HostFieldSpec = FieldSpec<HostParams>;

namespace paramtable {
inline constexpr double kPi = 3.14159265358979323846;
constexpr FieldBound atLeast(double v, std::string_view symbol = {})
{
    return {true, v, true, symbol};
}
constexpr FieldBound above(double v)
{
    return {true, v, false, {}};
}
constexpr FieldBound atMost(double v, std::string_view symbol = {})
{
    return {true, v, true, symbol};
}
//! ≤ a value known only when validating (tau_limit).
constexpr FieldBound atMostExternal(std::string_view symbol)
{
    return {true, 0, true, symbol, true};
}
} // namespace paramtable

//! The device's fields in ParamBlock (wire) order: the index is the wire index (model.md § 1).
inline constexpr std::array<DeviceFieldSpec, DeviceParams::kFieldCount> kDeviceFields = {{
    {"D_adm",
     "D_adm",
     "kg·m²",
     "inertia",
     "virtual inertia of the admittance filter",
     &DeviceParams::D_adm,
     paramtable::atLeast(1e-6),
     paramtable::atMost(1.0),
     {},
     false,
     {1e-6, 1.0, 1e-5, true}},
    {"M_adm",
     "M_adm",
     "N·m·s/rad",
     "damping",
     "virtual damping of the admittance filter",
     &DeviceParams::M_adm,
     paramtable::above(0.0),
     paramtable::atMost(10.0),
     {},
     false,
     {1e-5, 10.0, 1e-3, true}},
    {"K_min",
     "K_min",
     "N·m/rad",
     "outer stiffness (minimum)",
     "minimum re-centering stiffness",
     &DeviceParams::K_min,
     paramtable::atLeast(0.0),
     {},
     {3, false},
     false,
     {0.0, 5.0, 0.01}},
    {"K_max",
     "K_max",
     "N·m/rad",
     "notch stiffness (maximum)",
     "maximum (notch) re-centering stiffness",
     &DeviceParams::K_max,
     paramtable::atLeast(0.0),
     paramtable::atMost(50.0),
     {},
     false,
     {0.0, 5.0, 0.01}},
    {"N",
     "N",
     "rad",
     "notch half-width",
     "half-width of the notch band",
     &DeviceParams::N,
     paramtable::above(0.0),
     paramtable::atMost(paramtable::kPi / 2, "π/2"),
     {},
     true,
     {0.0, paramtable::kPi / 2, 0.005}},
    {"Q_dz",
     "Q_dz",
     "rad",
     "dead-zone half-width",
     "half-width of the dead zone",
     &DeviceParams::Q_dz,
     paramtable::atLeast(0.0),
     {},
     {4, true},
     true,
     {0.0, 0.5, 0.001}},
    {"theta0",
     "θ0",
     "rad",
     "center angle",
     "center (idle) angle",
     &DeviceParams::theta0,
     paramtable::atLeast(-paramtable::kPi, "−π"),
     paramtable::atMost(paramtable::kPi, "π"),
     {},
     true,
     {-paramtable::kPi, paramtable::kPi, 0.01}},
}};

//! The host's numeric fields (model.md § 1); mode and ref_deadzone are not numbers.
inline constexpr std::array<HostFieldSpec, 2> kHostFields = {{
    {"v_max",
     "v_max",
     "m/s or rad/s",
     "max. reference velocity",
     "maximum reference velocity",
     &HostParams::v_max,
     paramtable::above(0.0),
     paramtable::atMost(100.0),
     {},
     false,
     {0.01, 100.0, 0.1, true}},
    {"tau_limit",
     "tau_limit",
     "N·m",
     "actuator torque limit",
     "actuator torque limit",
     &HostParams::tau_limit,
     paramtable::above(0.0),
     paramtable::atMost(10.0),
     {},
     false,
     {0.0, 2.0, 0.01}},
}};

using EffectFieldSpec = FieldSpec<EffectParams>;
using VibrationFieldSpec = FieldSpec<Vibration>;

//! The effect block's fields in wire order (effects.md § 2). detent_strength's upper bound is
//! the device's tau_limit. Tuning ranges: a clearly felt detent is 0.02–0.1 N·m on the STS3032,
//! and a wall stiffer than about 2.5 N·m/rad bounces there (docs/effects.md).
inline constexpr std::array<EffectFieldSpec, EffectParams::kFieldCount> kEffectFields = {{
    {"detent_strength",
     "A_det",
     "N·m",
     "detent strength",
     "torque amplitude of the detents",
     &EffectParams::detent_strength,
     paramtable::atLeast(0.0),
     paramtable::atMostExternal("tau_limit"),
     {},
     false,
     {0.0, 0.44, 0.005}},
    {"detent_spacing",
     "s_det",
     "rad",
     "detent spacing",
     "distance between detent rest positions",
     &EffectParams::detent_spacing,
     paramtable::atLeast(0.01),
     paramtable::atMost(paramtable::kPi, "π"),
     {},
     true,
     {0.01, 1.0, 0.01}},
    {"detent_range",
     "R_det",
     "rad",
     "detent range",
     "|θ−θ0| up to which detents act (0 = off)",
     &EffectParams::detent_range,
     paramtable::atLeast(0.0),
     paramtable::atMost(paramtable::kPi, "π"),
     {},
     true,
     {0.0, paramtable::kPi, 0.01}},
    {"wall_min",
     "wall_min",
     "rad",
     "lower end stop",
     "lower virtual end stop, relative to θ0",
     &EffectParams::wall_min,
     paramtable::atLeast(-paramtable::kPi, "−π"),
     paramtable::atMost(0.0),
     {},
     true,
     {-paramtable::kPi, 0.0, 0.01}},
    {"wall_max",
     "wall_max",
     "rad",
     "upper end stop",
     "upper virtual end stop, relative to θ0",
     &EffectParams::wall_max,
     paramtable::atLeast(0.0),
     paramtable::atMost(paramtable::kPi, "π"),
     {},
     true,
     {0.0, paramtable::kPi, 0.01}},
    {"wall_stiffness",
     "K_w",
     "N·m/rad",
     "wall stiffness",
     "stiffness of the end stops",
     &EffectParams::wall_stiffness,
     paramtable::atLeast(0.0),
     paramtable::atMost(50.0),
     {},
     false,
     {0.0, 10.0, 0.05}},
    {"wall_damping",
     "B_w",
     "N·m·s/rad",
     "wall damping",
     "damping of the end stops while moving further in",
     &EffectParams::wall_damping,
     paramtable::atLeast(0.0),
     paramtable::atMost(1.0),
     {},
     false,
     {0.0, 0.1, 0.001}},
}};

using PassivityFieldSpec = FieldSpec<PassivityParams>;

//! The passivity controller's fields in wire order (passivity.md, "Parameters"). Tuning
//! ranges: β_max 0.1 fails at 0.5 s one-way delay, 0.5 holds it but not with 20 % loss, 0.7
//! (the default) holds both; R_max caps the tank, whose level follows the hand's work
//! (model/passivity.h): 0.15 J covers the hardest impact a robot driven at v_max returns
//! through the knob (about 0.13 J), a smaller R_max damps such contacts earlier.
inline constexpr std::array<PassivityFieldSpec, PassivityParams::kFieldCount> kPassivityFields = {{
    {"pc_damping_max",
     "β_max",
     "N·m·s/rad",
     "passivity damping (max)",
     "most damping the passivity controller adds to the knob (0 = controller off)",
     &PassivityParams::pc_damping_max,
     paramtable::atLeast(0.0),
     paramtable::atMost(1.0),
     {},
     false,
     {0.0, 1.0, 0.01}},
    {"pc_reserve_max",
     "R_max",
     "J",
     "passivity reserve (max)",
     "most energy a contact may give back through the knob undamped (the tank's cap)",
     &PassivityParams::pc_reserve_max,
     paramtable::atLeast(0.0),
     paramtable::atMost(1.0),
     {},
     false,
     {0.0, 0.3, 0.005}},
}};

//! VIBRATE's fields (effects.md § 2); amplitude's upper bound is tau_limit, and the frequency
//! must also stay below half the control rate (checked on top of this table).
inline constexpr std::array<VibrationFieldSpec, 3> kVibrationFields = {{
    {"amplitude",
     "a",
     "N·m",
     "amplitude",
     "vibration amplitude",
     &Vibration::amplitude,
     paramtable::atLeast(0.0),
     paramtable::atMostExternal("tau_limit"),
     {},
     false,
     {0.0, 0.44, 0.005}},
    {"frequency",
     "f",
     "Hz",
     "frequency",
     "vibration frequency",
     &Vibration::frequency,
     paramtable::atLeast(1.0),
     paramtable::atMost(500.0),
     {},
     false,
     {1.0, 500.0, 1.0}},
    {"duration",
     "d",
     "s",
     "duration",
     "vibration duration",
     &Vibration::duration,
     paramtable::atLeast(0.0),
     paramtable::atMost(10.0),
     {},
     false,
     {0.0, 2.0, 0.05}},
}};

//! The field called `name`; a name the table lacks does not compile.
template<typename Params, std::size_t N>
consteval const FieldSpec<Params> &fieldNamed(const std::array<FieldSpec<Params>, N> &table,
                                              std::string_view name)
{
    const FieldSpec<Params> *found = nullptr;
    for (const FieldSpec<Params> &f : table) {
        if (f.name == name)
            found = &f;
    }
    return *found;
}

//! The field's single-field range as numbers, with a cross rule's partner's range standing
//! in for a missing upper bound (K_min ≤ K_max ≤ 50): what wire rounding must stay inside.
struct NumericRange
{
    double low;
    double high;
};
constexpr NumericRange numericRange(int index)
{
    const DeviceFieldSpec &s = kDeviceFields[std::size_t(index)];
    double high = s.upper.value;
    if (!s.upper.present && s.cross.field >= 0)
        high = kDeviceFields[std::size_t(s.cross.field)].upper.value;
    return {s.lower.value, high};
}

//! The valid range as a person reads it: "0 < N ≤ π/2", "0 ≤ Q_dz < N" (model.md § 1).
template<typename Params> std::string rangeText(const FieldSpec<Params> &spec);

} // namespace hatpic
