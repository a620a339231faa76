#include "passivityobserver.h"

#include "model/passivity.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hatpic::analysis {

namespace {

//! At most this many points of E per window: a lookback exact to window/100, bounded memory
//! whatever the sample rate.
constexpr int kPointsPerWindow = 100;

} // namespace

std::vector<std::string> validate(const PassivitySettings &s)
{
    std::vector<std::string> errors;
    const auto check = [&](const char *name, double value, bool ok, const char *rule) {
        if (std::isfinite(value) && ok)
            return;
        std::ostringstream out;
        out << name << ": must be finite and " << rule << ", got " << value;
        errors.push_back(out.str());
    };
    check("window", s.window, s.window > 0, "> 0 s");
    check("approach", s.approach, s.approach >= 0, ">= 0 s");
    check("threshold", s.threshold, s.threshold > 0, "> 0 J");
    check("contactTorque", s.contactTorque, s.contactTorque > 0, "> 0 N·m");
    check("hold", s.hold, s.hold >= 0, ">= 0 s");
    check("maxGap", s.maxGap, s.maxGap > 0, "> 0 s");
    return errors;
}

PassivityObserver::PassivityObserver(const PassivitySettings &settings)
    : m_settings(validate(settings).empty() ? settings : PassivitySettings{})
{}

void PassivityObserver::reset()
{
    *this = PassivityObserver(m_settings);
}

void PassivityObserver::add(double t, double tauExt, double omega, double tauPc, double reserve,
                            double theta)
{
    if (!std::isfinite(t) || !std::isfinite(tauExt) || !std::isfinite(omega)) {
        ++m_state.invalid;
        m_havePrevious = false; // the next step spans the skipped one: not integrated
        return;
    }
    ++m_state.samples;
    const double power = tauExt * omega; // [W]: > 0 while τ_ext pushes the way the knob moves
    // The controller's power: −τ_pc·ω = β·ω² ≥ 0, what it takes out of the knob [W].
    const bool reported = std::isfinite(tauPc);
    const double controllerPower = reported ? -tauPc * omega : 0.0;
    if (m_havePrevious) {
        const double dt = t - m_previousT;
        if (dt > 0 && dt <= m_settings.maxGap) {
            m_state.energy += 0.5 * (m_previousPower + power) * dt;
            m_state.dissipated += 0.5 * (m_previousControllerPower + controllerPower) * dt;
        } else {
            ++m_state.gaps;
            if (dt < 0) { // another clock (a reconnected device): nothing of the old one holds
                m_history.clear();
                m_lastContactT = -std::numeric_limits<double>::infinity();
                m_lastGeneratingT = -std::numeric_limits<double>::infinity();
            }
        }
    }
    m_havePrevious = true;
    m_previousT = t;
    m_previousPower = power;
    m_previousControllerPower = controllerPower;

    if (reported) {
        m_state.controllerReported = true;
        m_state.controllerTorque = tauPc;
        if (tauPc != 0)
            m_lastDampingT = t;
        // β = −τ_pc/ω where ω says anything; the peak over the last hold, so a reading does
        // not flicker with each cycle's ω.
        const double beta = std::abs(omega) > 1e-9 ? std::max(0.0, -tauPc / omega) : 0.0;
        if (beta >= m_state.dampingCoefficient || t - m_dampingPeakT > m_settings.hold) {
            m_state.dampingCoefficient = beta;
            m_dampingPeakT = t;
        }
    }
    m_state.reserve = std::isfinite(reserve) ? reserve : std::numeric_limits<double>::quiet_NaN();
    m_state.damping = t - m_lastDampingT <= m_settings.hold;

    // A contact begins when |τ_ext| first exceeds contactTorque, and ends once it has stayed
    // below for a whole window (a knob bouncing off a wall stays in one contact). Its first
    // `approach` seconds are not judged; E when they end is what the rest is measured from.
    if (std::abs(tauExt) > m_settings.contactTorque) {
        if (t - m_lastContactT > m_settings.window) {
            m_contactStartT = t;
            m_contactStartEnergy = m_state.energy; // nothing stored in the contact yet
            m_approachOver = false;
        }
        m_lastContactT = t;
    }
    m_state.inContact = t - m_lastContactT <= m_settings.window;
    if (m_state.inContact && !m_approachOver && t - m_contactStartT >= m_settings.approach) {
        // What the approach gave is excused, what it took is not: a passive wall still never
        // gives back more than it took since the contact began.
        m_contactStartEnergy = std::max(m_contactStartEnergy, m_state.energy);
        m_approachOver = true;
    }

    if (m_history.empty() || t - m_history.back().t >= m_settings.window / kPointsPerWindow)
        m_history.push_back({t, m_state.energy});
    // Keep the newest point at or before t − window (the front), and everything after it.
    while (m_history.size() >= 2 && m_history[1].t <= t - m_settings.window)
        m_history.pop_front();
    const double windowAgo = m_history.front().energy;

    m_state.generated = m_state.inContact && m_approachOver
                            ? m_state.energy - std::max(windowAgo, m_contactStartEnergy)
                            : 0.0;
    m_state.generating = m_state.inContact && m_state.generated > m_settings.threshold;
    if (m_state.generating)
        m_lastGeneratingT = t;
    m_state.warning = t - m_lastGeneratingT <= m_settings.hold;
    m_state.time = t;
    judgeRest(t, theta, reported && tauPc != 0);
}

void PassivityObserver::judgeRest(double t, double theta, bool damped)
{
    // At rest as the device's tank judges it (model/passivity.h): within the still band of
    // where the knob stopped, for the rest time. Then how often the controller damped it there,
    // averaged over about a second.
    constexpr double kShareTime = 1.0; //!< [s]
    const double h = std::isfinite(m_stillT) ? t - m_stillT : 0.0;
    m_stillT = t;
    m_still.update(theta, h);
    m_state.atRest = m_still.stillFor(passivity::kRestTime); // a NaN θ restarts the clock
    if (!m_state.atRest) {
        m_state.restDampedShare = 0;
        m_restT = std::numeric_limits<double>::quiet_NaN();
    } else {
        const double dt = std::isfinite(m_restT) ? std::clamp(t - m_restT, 0.0, kShareTime) : 0.0;
        m_state.restDampedShare +=
            ((damped ? 1.0 : 0.0) - m_state.restDampedShare) * dt / kShareTime;
        m_restT = t;
    }
    m_state.dampedAtRest = m_state.atRest && m_state.restDampedShare > kDampedAtRestShare;
}

} // namespace hatpic::analysis
