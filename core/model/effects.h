// Haptic effects (effects.md): virtual detents, end stops and vibration cues, rendered by the
// device on top of model.md inside the control cycle, at the measured angle.
//
// Plain C++20. The torques are templates so that the ESP32 (float) and the host (double)
// evaluate one implementation.
#pragma once

#include "params.h"

#include <array>
#include <cmath>
#include <numbers>
#include <string_view>
#include <vector>

namespace hatpic {

//! The effect block, in wire order (effects.md § 2). Defaults render nothing.
struct EffectParams
{
    double detent_strength = 0.0;        //!< A: detent torque amplitude [N·m]
    double detent_spacing = 0.2;         //!< s: distance between rest positions [rad]
    double detent_range = 0.0;           //!< R: |e| up to which detents act; 0 = off [rad]
    double wall_min = -std::numbers::pi; //!< lower end stop, relative to θ0 [rad]
    double wall_max = std::numbers::pi;  //!< upper end stop, relative to θ0 [rad]
    double wall_stiffness = 0.0;         //!< K_w [N·m/rad]
    double wall_damping = 0.0;           //!< B_w [N·m·s/rad]

    static constexpr int kFieldCount = 7;

    double field(int index) const;          //!< by wire index 0…6; NaN outside
    void setField(int index, double value); //!< by wire index; ignored outside

    friend bool operator==(const EffectParams &, const EffectParams &) = default;
};

//! A vibration cue (VIBRATE): τ_vib = a·sin(2π·f·(t − t_start)) for d seconds.
struct Vibration
{
    double amplitude = 0; //!< a [N·m]; 0 stops a running cue
    double frequency = 0; //!< f [Hz]
    double duration = 0;  //!< d [s]
    friend bool operator==(const Vibration &, const Vibration &) = default;
};

std::string_view effectFieldName(int index);
int effectFieldIndex(std::string_view name);

//! Every violated rule of effects.md § 2 (detent_strength ≤ tau_limit [N·m]), in table order.
std::vector<Violation> validate(const EffectParams &effects, double tauLimit);
//! Index of the first violating field (the device's reject reply), or -1; allocation-free.
int firstViolatingField(const EffectParams &effects, double tauLimit);
//! Every violated rule of VIBRATE (effects.md § 2): a ≤ tau_limit, f < controlRate/2.
std::vector<Violation> validate(const Vibration &vibration, double tauLimit, double controlRate);
//! Index (0 a, 1 f, 2 d) of the first violating VIBRATE field, or -1; allocation-free.
int firstViolatingField(const Vibration &vibration, double tauLimit, double controlRate);

//! The block as it travels in SET_EFFECTS: each field rounded to float32, moved one float
//! inward where rounding alone would leave a bound it satisfied (the defaults ±π are not
//! floats: float(π) > π). detent_strength's bound is `tauLimit` [N·m].
EffectParams roundedForWire(const EffectParams &effects, double tauLimit);
//! True when both blocks are the same float32 fields (what "in sync" means for a read-back).
bool sameOnWire(const EffectParams &a, const EffectParams &b);
//! tidyDeviceParams() (params.h) for the effect block.
EffectParams tidyEffectParams(const EffectParams &effects);

//! The torque-relevant fields in the scalar type that evaluates them.
template<typename T> struct EffectShape
{
    T A{}, s{T(1)}, R{}, wallMin{}, wallMax{}, Kw{}, Bw{};
    T twoPiOverS{}; //!< 2π/s [1/rad], computed once

    static EffectShape from(const EffectParams &p)
    {
        EffectShape e;
        e.A = T(p.detent_strength);
        e.s = T(p.detent_spacing);
        e.R = T(p.detent_range);
        e.wallMin = T(p.wall_min);
        e.wallMax = T(p.wall_max);
        e.Kw = T(p.wall_stiffness);
        e.Bw = T(p.wall_damping);
        e.twoPiOverS = T(2.0 * std::numbers::pi / p.detent_spacing);
        return e;
    }
};

//! τ_det = −A·sin(2π·e/s) when A > 0 and |e| ≤ R; 0 otherwise [N·m]. e = θ − θ0 [rad].
template<typename T> T detentTorque(const EffectShape<T> &fx, T e)
{
    if (!(fx.A > T(0)) || !(std::abs(e) <= fx.R))
        return T(0);
    return -fx.A * std::sin(fx.twoPiOverS * e);
}

//! τ_wall (effects.md § 1): a spring beyond the wall, plus damping only while moving further
//! in, so the wall never pulls the knob back in [N·m]. e [rad], ω [rad/s].
template<typename T> T wallTorque(const EffectShape<T> &fx, T e, T omega)
{
    T beyond = T(0);
    if (e > fx.wallMax)
        beyond = e - fx.wallMax;
    else if (e < fx.wallMin)
        beyond = e - fx.wallMin;
    if (beyond == T(0))
        return T(0);
    const T spring = -fx.Kw * beyond;
    return omega * beyond > T(0) ? spring - fx.Bw * omega : spring;
}

//! τ_vib = a·sin(2π·f·τ) for 0 ≤ τ < d, τ = time since the cue started [s]; 0 otherwise.
template<typename T> T vibrationTorque(T amplitude, T frequency, T duration, T since)
{
    if (!(since >= T(0)) || !(since < duration))
        return T(0);
    return amplitude * std::sin(T(2 * std::numbers::pi) * frequency * since);
}

inline double detentTorque(const EffectParams &p, double e)
{
    return detentTorque(EffectShape<double>::from(p), e);
}
inline double wallTorque(const EffectParams &p, double e, double omega)
{
    return wallTorque(EffectShape<double>::from(p), e, omega);
}

//! What may go wrong with an effect block on this knob (effects.md § 4); the figures say by how
//! much, a tuning UI says it in words.
enum class EffectWarning {
    WallNotPassive,          //!< K_w·h/2 > b: the wall may chatter
    DetentsNotPassive,       //!< (A·2π/s)·h/2 > b: the detents may chatter
    WallAboveServo,          //!< K_w above the servo's limit: the wall is likely to bounce
    DetentsAboveServo,       //!< A·2π/s above the servo's limit: the detents are likely to buzz
    DetentsStifferThanNotch, //!< A·2π/s > K_max: near θ0 the detents set the feel
};

//! Figures a tuning UI shows for an effect block (effects.md § 4).
struct EffectFigures
{
    double detentPeakStiffness = 0; //!< A·2π/s: the detents' stiffness at a rest position [N·m/rad]
    double wallPassivityMargin =
        0; //!< b − K_w·h/2 (Colgate & Schenkel): < 0 may chatter [N·m·s/rad]
    bool detentsStifferThanNotch = false; //!< A·2π/s > K_max
    //! b − (A·2π/s)·h/2: the passivity check with the detents' peak stiffness [N·m·s/rad]
    double detentPassivityMargin = 0;
    double servoLimit = 0; //!< servoStiffnessLimit() at servo::kPositionLoopHz [N·m/rad]
    //! The rules the block breaks, in this order; only for effects that are on (detents:
    //! detentsActive(); walls with a stiffness and a bound inside ±π).
    std::vector<EffectWarning> warnings;
};

//! @param physicalDamping b, the device's own viscous damping [N·m·s/rad]
//! @param period h, the control period [s]
EffectFigures deriveEffectFigures(const EffectParams &effects, const DeviceParams &device,
                                  double physicalDamping, double period);

//! The stiffest spring the servo's position loop follows on the device's virtual inertia:
//! D_adm·(2π·f)², with f the loop's natural frequency [Hz] (docs/effects.md, "When a wall or a
//! detent chatters"). A wall, or detents whose peak stiffness A·2π/s is above it, bounce.
double servoStiffnessLimit(const DeviceParams &device, double servoBandwidthHz);

} // namespace hatpic
