#include "controller.h"

#include "protocol/messages.h"

#include <algorithm>
#include <cmath>

namespace hatpic::fw {

template<typename T>
Controller<T>::Controller(const Config &config, Actuator<T> &actuator)
    : m_config(config), m_actuator(actuator)
{
    m_period = 1.0 / config.rateHz;
    m_periodUs = std::uint32_t(std::llround(1e6 * m_period));
    m_tauLimit = T(config.tauLimit);
    m_h = T(m_period);
    m_tank.configure(m_passivity);
}

template<typename T> bool Controller<T>::start(const DeviceParams &params, std::uint32_t nowUs)
{
    setParams(params);
    m_lastFeedbackUs = nowUs;
    T theta{};
    if (!m_actuator.start(theta))
        return false;
    m_filter = {theta, T(0)};
    m_measured = {theta, T(0), T(0)};
    m_record.theta = theta;
    m_tank.fill(); // passivity.md: the tank starts armed at start and after a reset
    m_record.pc_reserve = m_tank.reserve();
    return true;
}

template<typename T> void Controller<T>::setParams(const DeviceParams &params)
{
    m_params = params;
    m_shape = StiffnessShape<T>::from(params);
    m_stepper = AdmittanceStepper<T>(AdmittanceCoefficients::compute(params, m_period));
    m_dAdm = T(params.D_adm);
    m_mAdm = T(params.M_adm);
}

template<typename T> void Controller<T>::setEffects(const EffectParams &effects)
{
    m_effects = effects;
    m_fx = EffectShape<T>::from(effects);
}

template<typename T> void Controller<T>::setPassivity(const PassivityParams &passivity)
{
    m_passivity = passivity;
    m_tank.configure(passivity);
}

template<typename T> void Controller<T>::vibrate(const Vibration &cue)
{
    m_cue.amplitude = T(cue.amplitude);
    m_cue.frequency = T(cue.frequency);
    m_cue.duration = T(cue.duration);
    m_cue.running = false;
    m_cue.pending = cue.amplitude != 0 && cue.duration > 0;
}

template<typename T> void Controller<T>::setFeedback(T tauExt, std::uint32_t atUs)
{
    m_feedback = tauExt;
    m_lastFeedbackUs = atUs;
    m_stale = false;
}

template<typename T> void Controller<T>::busError()
{
    ++m_busErrors;
    if (++m_consecutiveErrors >= kMaxConsecutiveBusErrors && !m_faulted) {
        m_faulted = true;
        m_actuator.disable();
    }
}

template<typename T> const CycleRecord<T> &Controller<T>::cycle(std::uint32_t nowUs)
{
    // 1. Measure; a failed read holds the last measurement and commands nothing new.
    bool measured = false;
    if (!m_faulted) {
        measured = m_actuator.measure(m_measured);
        if (measured)
            m_consecutiveErrors = 0;
        else
            busError();
    }

    // 2. τ_rec, τ_total and flags at the measured θ (model.md § 2); τ_ext is 0 when stale.
    // What this cycle renders stays in force until the next cycle, one period on: τ_ext is
    // stale when it would then be older than the watchdog, so it never outlives it, at any
    // rate (at 1 kHz: from the cycle 200 ms after the arrival). Signed difference: feedback
    // may be stamped after this cycle's time (it arrived between cycles); the latch keeps a
    // stale flag up once the difference wraps.
    if (m_config.watchdogUs > 0 && !m_stale)
        m_stale = std::int32_t(nowUs - m_lastFeedbackUs) >
                  std::int32_t(m_config.watchdogUs) - std::int32_t(m_periodUs);
    CycleRecord<T> &r = m_record;
    r.t_us = nowUs;
    r.theta = m_measured.theta;
    r.omega = m_measured.omega;
    r.tau = m_measured.tau;
    r.tau_rec = recenteringTorque(m_shape, r.theta);
    r.tau_ext = m_stale ? T(0) : m_feedback;
    const T e = r.theta - m_shape.theta0;
    r.tau_fx = detentTorque(m_fx, e) + wallTorque(m_fx, e, r.omega);
    if (m_cue.pending) { // t_start is the first cycle after VIBRATE arrived
        m_cue.pending = false;
        m_cue.running = true;
        m_cue.startUs = nowUs;
    }
    if (m_cue.running) {
        const T since = T(std::int32_t(nowUs - m_cue.startUs)) * T(1e-6);
        if (since < m_cue.duration)
            r.tau_fx += vibrationTorque(m_cue.amplitude, m_cue.frequency, m_cue.duration, since);
        else
            m_cue.running = false;
    }
    const T sum = r.tau_rec + r.tau_fx + r.tau_ext;
    r.tau_total = std::clamp(sum, -m_tauLimit, m_tauLimit);
    r.flags = v2::zoneFlag(stiffnessZone(m_shape, r.theta));
    if (std::abs(sum) > m_tauLimit)
        r.flags |= v2::kFlagSaturated;
    if (m_stale)
        r.flags |= v2::kFlagFeedbackStale;
    if (m_faulted)
        r.flags |= v2::kFlagTorqueOff;

    // 3–4. The filter advances its own state with u = −τ + τ_total; its position is the goal.
    // The passivity controller (passivity.md) watches the energy τ_ext delivers at the
    // filter's rate and, when the port has given back more than it absorbed, steps the filter
    // with the damping M_adm + β (the exact discretisation with α = (M_adm + β)/D_adm). With
    // β = 0 the step is the very one without it, bit for bit.
    r.tau_pc = T(0);
    r.pc_reserve = m_tank.reserve();
    if (measured) {
        // The port's energy is booked on the τ_ext the knob can render (the torque limit); the
        // tank's level follows the hand's work against the knob's centre.
        const auto pc = m_tank.step(std::clamp(r.tau_ext, -m_tauLimit, m_tauLimit), m_filter.omega,
                                    m_h, r.theta - m_shape.theta0, r.tau);
        r.tau_pc = pc.tauPc;
        r.pc_reserve = pc.reserve;
        const T u = -r.tau + r.tau_total;
        if (pc.beta > T(0)) {
            m_filter =
                AdmittanceStepper<T>::computeIn(m_dAdm, m_mAdm + pc.beta, m_h).step(m_filter, u);
        } else {
            m_filter = m_stepper.step(m_filter, u);
        }
        if (!m_actuator.command(m_filter.theta, m_filter.omega))
            busError();
    }
    return r;
}

template class Controller<float>;
template class Controller<double>;

} // namespace hatpic::fw
