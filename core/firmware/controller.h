// The control cycle of servo.md § 4 on the haptic model: measure, render τ_rec + τ_ext, advance
// the admittance filter, command the servo. One implementation for the ESP32 (T = float, its
// FPU's precision), hatpic-fw-host and the simulator (T = double).
//
// Plain C++20: no Qt, no OS calls, no exceptions, no allocation. Everything that depends only
// on the parameters and the period (K_rec's shape, e^{−αh} and the other step coefficients)
// is computed once per parameter change, in double; a cycle is a handful of T operations.
// Used from the control context only.
#pragma once

#include "firmware/actuator.h"
#include "model/admittance.h"
#include "model/effects.h"
#include "model/params.h"
#include "model/passivity.h"
#include "model/servo.h"
#include "model/stiffness.h"

#include <cstdint>

namespace hatpic::fw {

//! One control cycle as the device rendered it: the quantities TELEMETRY reports (a member for
//! each of model/cyclequantities.h) and τ_total.
template<typename T> struct CycleRecord
{
    std::uint32_t t_us = 0; //!< the cycle's time on the device clock [µs, wraps]
    T theta{};              //!< measured knob angle the cycle used [rad]
    T omega{};              //!< measured knob rate [rad/s]
    T tau{};                //!< measured interaction torque [N·m]
    T tau_rec{};            //!< −K_rec(θ)·(θ−θ0) for that θ [N·m]
    T tau_ext{};            //!< feedback rendered (0 when stale) [N·m]
    T tau_fx{};             //!< τ_det + τ_wall + τ_vib (effects.md § 1) [N·m]
    T tau_total{};          //!< τ_rec + τ_fx + τ_ext clamped to ±tau_limit [N·m]
    T tau_pc{};             //!< −β·ω: the passivity controller's torque (passivity.md) [N·m]
    T pc_reserve{};         //!< R, the passivity controller's energy reserve after the cycle [J]
    std::uint8_t flags = 0; //!< v2::kFlag* bits
};

template<typename T> class Controller
{
public:
    //! Consecutive failed bus transactions after which the torque goes off (servo.md § 1).
    static constexpr std::uint32_t kMaxConsecutiveBusErrors = 100;
    //! The feedback watchdog of protocol.md: a τ_ext is not in force longer than this after
    //! the SET_FEEDBACK that brought it [µs].
    static constexpr std::uint32_t kFeedbackWatchdogUs = 200000;

    struct Config
    {
        double rateHz = servo::kControlRateHz;          //!< control rate; period h = 1/rate [Hz]
        double tauLimit = 0.44;                         //!< |τ_total| limit [N·m]
        std::uint32_t watchdogUs = kFeedbackWatchdogUs; //!< feedback watchdog [µs]; 0 = none
    };

    Controller(const Config &config, Actuator<T> &actuator);

    //! Brings the actuator up and sets the filter's state to the present angle at rest.
    //! `params` (already valid) is in force from the first cycle; `nowUs` counts as a
    //! feedback arrival for the watchdog. False when the actuator does not answer.
    bool start(const DeviceParams &params, std::uint32_t nowUs);

    //! A new valid block, in force from the next cycle, whole.
    void setParams(const DeviceParams &params);
    //! A new valid effect block, in force from the next cycle.
    void setEffects(const EffectParams &effects);
    //! A new valid passivity block (passivity.md), in force from the next cycle. A smaller
    //! pc_reserve_max caps the reserve at once.
    void setPassivity(const PassivityParams &passivity);
    //! Starts a vibration cue at the next cycle, replacing a running one (a = 0 stops it).
    void vibrate(const Vibration &cue);
    //! The host's τ_ext [N·m], received at `atUs`; it feeds the watchdog.
    void setFeedback(T tauExt, std::uint32_t atUs);

    //! Runs one cycle at device time `nowUs`. On a bus error the previous measurement is held
    //! and the servo keeps its last command; after kMaxConsecutiveBusErrors in a row the
    //! torque goes off and stays off (faulted()).
    const CycleRecord<T> &cycle(std::uint32_t nowUs);

    const CycleRecord<T> &last() const { return m_record; }
    const DeviceParams &params() const { return m_params; }
    const EffectParams &effects() const { return m_effects; }
    const PassivityParams &passivity() const { return m_passivity; }
    double period() const { return m_period; }
    bool faulted() const { return m_faulted; }
    std::uint64_t busErrors() const { return m_busErrors; }

private:
    void busError();

    Config m_config;
    Actuator<T> &m_actuator;
    double m_period = 1e-3;          //!< [s]
    std::uint32_t m_periodUs = 1000; //!< the same, rounded [µs]
    T m_tauLimit{};
    T m_h{}; //!< the period in T [s]

    DeviceParams m_params;
    StiffnessShape<T> m_shape;
    AdmittanceStepper<T> m_stepper;   //!< the step without the passivity controller's damping
    T m_dAdm{}, m_mAdm{};             //!< D_adm, M_adm in T, for a step with M_adm + β
    BasicAdmittanceState<T> m_filter; //!< θ_f, ω_f: the filter's own state (servo.md § 4)
    //! Off until the device core sets its block: the legacy firmware's emulation has none.
    PassivityParams m_passivity = PassivityParams::off();
    PassivityTank<T> m_tank;
    EffectParams m_effects;
    EffectShape<T> m_fx = EffectShape<T>::from(EffectParams{});
    struct Cue
    {
        T amplitude{}, frequency{}, duration{};
        bool pending = false; //!< starts at the next cycle
        bool running = false;
        std::uint32_t startUs = 0; //!< t_start [µs]
    } m_cue;

    Measurement<T> m_measured;
    CycleRecord<T> m_record;
    T m_feedback{};
    std::uint32_t m_lastFeedbackUs = 0;
    //! Latched until the next feedback, so that a clock wrap cannot re-arm an old τ_ext.
    bool m_stale = false;

    std::uint32_t m_consecutiveErrors = 0;
    std::uint64_t m_busErrors = 0;
    bool m_faulted = false;
};

extern template class Controller<float>;
extern template class Controller<double>;

} // namespace hatpic::fw
