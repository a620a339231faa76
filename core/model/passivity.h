// The passivity controller (passivity.md): a one-port time-domain passivity observer and
// controller with an energy tank, run by the device core in its control cycle. It watches the
// energy the feedback port (τ_ext) delivers to the knob and, when the port has given back more
// than it absorbed, adds just enough damping to the admittance filter to take the excess out.
//
// Plain C++20, no Qt: the ESP32 (float) and the host (double) run the one implementation.
#pragma once

#include "params.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace hatpic {

//! The controller's tuning, in wire order (passivity.md, "Parameters"). The defaults turn it
//! on; they were chosen with the stability map and confirmed on the real teleoperation loop
//! (docs/teleop.md § The stability map, "Choosing the tank").
struct PassivityParams
{
    double pc_damping_max = 0.7;  //!< β_max [N·m·s/rad]; 0 turns the controller off
    double pc_reserve_max = 0.15; //!< R_max, the most the tank holds [J]

    static constexpr int kFieldCount = 2;

    double field(int index) const;          //!< by wire index 0…1; NaN outside
    void setField(int index, double value); //!< by wire index; ignored outside

    //! β_max = 0: the controller off (the default R_max kept).
    static constexpr PassivityParams off() { return {0.0, PassivityParams{}.pc_reserve_max}; }
    //! Whether the controller runs at all (β_max > 0).
    bool enabled() const { return pc_damping_max > 0; }

    friend bool operator==(const PassivityParams &, const PassivityParams &) = default;
};

std::string_view passivityFieldName(int index);
int passivityFieldIndex(std::string_view name);

//! Every violated rule of the table (finite, 0 … 1), in table order.
std::vector<Violation> validate(const PassivityParams &params);
//! Index of the first violating field (the device's reject reply), or -1; allocation-free.
int firstViolatingField(const PassivityParams &params);
//! The block as it travels (float32 fields, moved inward where rounding left a bound).
PassivityParams roundedForWire(const PassivityParams &params);
//! True when both blocks are the same float32 fields.
bool sameOnWire(const PassivityParams &a, const PassivityParams &b);
//! tidyDeviceParams() (params.h) for the passivity block.
PassivityParams tidyPassivityParams(const PassivityParams &params);

//! The tank's level, rest and fade (passivity.md, "Per control cycle", as docs/model.md § 6
//! states it): fixed by the model, not tuned per device. Chosen with the stability map over
//! hands of 0.03 … 0.1 N·m, three contacts each, at 0 … 0.5 s one-way (docs/teleop.md).
namespace passivity {
//! The port is closed (in contact) while |τ_ext| is above this [N·m]: a robot leaving a wall
//! reports a force that decays toward 0 without reaching it.
inline constexpr double kContactTorque = 0.002;
//! The level's floor: what a contact may give back undamped beyond the hand's own work [J].
inline constexpr double kLevelFloor = 0.010;
//! The knob is still while its angle stays within this of where it stopped [rad]: three
//! encoder counts (one is 1.53 mrad), more than a resting knob's flicker of one.
inline constexpr double kStillBand = 0.0046;
//! Once the knob rests (still for kRestTime), where it stopped follows the centre of its
//! flicker with this time constant [s]: a rest first seen at the edge of its flicker, or one
//! that creeps by a count as the loop settles, stays a rest; a motion of more than the band
//! does not. Before the rest the anchor stays put, so a slow motion is not taken for a rest.
inline constexpr double kAnchorTime = 4.0;
//! Still this long with the hand let go and no contact, the tank is armed again [s].
inline constexpr double kLetGoTime = 0.5;
//! The hand has let go when it holds the knob with at most this [N·m].
inline constexpr double kLetGoTorque = 0.01;
//! The port gives energy back when τ_ext·ω is above this [W]: a contact's motion, not the
//! load noise of a knob at rest.
inline constexpr double kGivingPower = 0.005;
//! Still this long in contact, the knob rests: its damping starts to fade [s].
inline constexpr double kRestTime = 1.0;
//! At rest the most damping falls from β_max to 0 over this [s].
inline constexpr double kFadeTime = 2.0;
//! In contact and moving, what the port absorbed stays credited for about this long: the
//! reserve leaks with this time constant [s], so a slow swing that gives back what it took
//! a while ago is damped too.
inline constexpr double kLeakTime = 0.5;
} // namespace passivity

//! A running sum of T that keeps what each addition's rounding loses (Kahan): a float reserve
//! then books changes far below its own step (about 4e-9 J near 0.05 J), in float alone, as the
//! ESP32's FPU computes (no software double in the control cycle: scripts/check-firmware).
template<typename T> class CompensatedSum
{
public:
    void add(T x)
    {
        const T y = x - m_lost;
        const T sum = m_sum + y;
        m_lost = (sum - m_sum) - y;
        m_sum = sum;
    }
    //! A new value: what was lost before no longer applies.
    void set(T value)
    {
        m_sum = value;
        m_lost = T(0);
    }
    T value() const { return m_sum; }

private:
    T m_sum{};
    T m_lost{}; //!< what the last additions lost, taken back from the next
};

//! Whether the knob is still, as the device's tank and the host's observer both judge it: its
//! angle within passivity::kStillBand of where it stopped (an anchor that follows the centre
//! of a resting knob's flicker, passivity::kAnchorTime), and for how long.
template<typename T> class StillClock
{
public:
    //! One observation of the angle `x` [rad], `h` [s] after the last; a non-finite x starts
    //! over. Returns how long the knob has been still [s].
    T update(T x, T h)
    {
        if (!std::isfinite(x) || !std::isfinite(h) ||
            !(std::abs(x - m_anchor) <= T(passivity::kStillBand))) {
            m_anchor = x;
            m_still = T(0);
        } else {
            m_still = std::min(m_still + h, T(kCap)); // long past every threshold
            if (stillFor(T(passivity::kRestTime)))
                m_anchor += (x - m_anchor) * std::min(T(1), h / T(passivity::kAnchorTime));
        }
        return m_still;
    }
    T still() const { return m_still; }
    //! Compared with a time that sums periods: half a microsecond of rounding slack.
    bool stillFor(T seconds) const { return m_still >= seconds - T(kTimeSlack); }

private:
    //! Sums of periods compared with a time: half a microsecond of rounding slack [s].
    static constexpr double kTimeSlack = 5e-7;
    //! How long a still knob's time is counted, so that a float sum never stops growing [s].
    static constexpr double kCap = 60;

    T m_anchor = std::numeric_limits<T>::quiet_NaN(); //!< where the knob stopped [rad]
    T m_still{};                                      //!< how long it has stayed there [s]
};

//! The law of one control cycle (passivity.md, "Per control cycle") with this project's tank,
//! rest and fade: the energy reserve R and the damping β it asks of the admittance filter. R is
//! a compensated sum (a float R alone would lose a cycle's change near R_max). Allocation-free,
//! no exceptions, T arithmetic only.
//!
//! - Level. What one contact may give back undamped is the hand's own work, the torque it holds
//!   the knob with times the knob's deflection, |τ|·|θ − θ0| (a rate-controlled robot meeting
//!   a wall pushes the knob back against the hand and returns about that much), plus
//!   passivity::kLevelFloor, at most R_max. The tank is armed at start and when the knob has
//!   rested let go with no contact; armed, R is kept at least at the level until the port
//!   gives energy back. A knob held still by the hand with no contact (waiting for a robot that
//!   bounced off the wall) is not armed: a contact is granted one level, and a loop that keeps
//!   bouncing is not refilled.
//! - Leak. In contact and moving, R leaks toward 0 (passivity::kLeakTime).
//! - Rest and fade. In contact and still for passivity::kRestTime, the most damping fades from
//!   β_max to 0 over passivity::kFadeTime, whatever deficit R carries; it is back at β_max as
//!   soon as the knob moves. A loop that rests on its own is then not damped at rest; one that
//!   cannot (its rest needs damping) moves again and is damped again, and says so (damping at
//!   rest, in the telemetry).
template<typename T> class PassivityTank
{
public:
    //! What one cycle decided.
    struct Step
    {
        T beta{};    //!< β_k, the extra damping for this cycle's admittance step [N·m·s/rad]
        T tauPc{};   //!< τ_pc,k = −β_k·ω_k [N·m]
        T reserve{}; //!< R_k [J]
    };

    //! A new block: β_max and R_max in force from the next cycle. A smaller R_max caps the
    //! reserve at once.
    void configure(const PassivityParams &params)
    {
        m_betaMax = T(params.pc_damping_max);
        m_reserveMax = T(params.pc_reserve_max);
        if (m_reserve.value() > m_reserveMax)
            m_reserve.set(m_reserveMax);
    }
    //! The tank armed at its level for a knob with no hand (the floor, at most R_max): at
    //! start and after a reset of the device.
    void fill()
    {
        m_reserve.set(level(T(0)));
        m_armed = true;
        m_fade = T(1);
        m_still = StillClock<T>();
    }

    //! One cycle with the feedback rendered `tauExt` [N·m] (after the watchdog and the torque
    //! limit), the filter's rate `omega` [rad/s], the period `h` [s], the knob's deflection
    //! θ − θ0 [rad] and the measured interaction torque τ [N·m] (the hand's, model.md § 2).
    //! Does nothing (β = 0, R holds) when off or when an input is not a number; β is 0 without
    //! τ_ext and at rest (ω²·h ≤ 1e-12).
    Step step(T tauExt, T omega, T h, T deflection, T tau)
    {
        Step s;
        s.reserve = m_reserve.value();
        if (!(m_betaMax > T(0)) || !std::isfinite(tauExt) || !std::isfinite(omega) ||
            !std::isfinite(h) || !std::isfinite(deflection) || !std::isfinite(tau))
            return s;
        const T hand = std::abs(tau);
        const T power = tauExt * omega; // > 0: the port gives energy to the knob
        m_still.update(deflection, h);
        const bool contact = std::abs(tauExt) > T(passivity::kContactTorque);
        if (!contact && m_still.stillFor(T(passivity::kLetGoTime)) &&
            hand <= T(passivity::kLetGoTorque))
            m_armed = true;
        else if (contact && power > T(passivity::kGivingPower))
            m_armed = false;
        if (m_armed) {
            const T lvl = level(hand * std::abs(deflection));
            if (m_reserve.value() < lvl)
                m_reserve.set(lvl);
        }
        const bool rests = contact && m_still.stillFor(T(passivity::kRestTime));
        m_fade = rests ? std::max(T(0), m_fade - h / T(passivity::kFadeTime)) : T(1);
        if (tauExt != T(0)) {
            const T w2h = omega * omega * h;
            m_reserve.add(-power * h); // R*
            const T candidate = m_reserve.value();
            T beta{};
            if (candidate < T(0) && w2h > T(1e-12)) {
                beta = std::min(m_betaMax * m_fade, -candidate / w2h);
                m_reserve.add(beta * w2h);
            }
            if (m_reserve.value() > m_reserveMax)
                m_reserve.set(m_reserveMax);
            if (contact && !rests && m_reserve.value() > T(0))
                m_reserve.add(-m_reserve.value() * h / T(passivity::kLeakTime));
            s.beta = beta;
            s.tauPc = -beta * omega;
        }
        s.reserve = m_reserve.value();
        return s;
    }

    T reserve() const { return m_reserve.value(); }
    //! Whether a contact's level is kept (since start or the knob's last rest let go).
    bool armed() const { return m_armed; }
    //! How much of β_max the controller may add now: 1, falling to 0 while the knob rests in
    //! contact.
    T fade() const { return m_fade; }

private:
    //! The tank's level for the hand's work [J]: the floor plus that work, at most R_max.
    T level(T handWork) const
    {
        return std::min(m_reserveMax, T(passivity::kLevelFloor) + handWork);
    }

    T m_betaMax{};               //!< [N·m·s/rad]
    T m_reserveMax{};            //!< [J]
    CompensatedSum<T> m_reserve; //!< R [J]
    bool m_armed = true;
    T m_fade = T(1);       //!< the share of β_max in force
    StillClock<T> m_still; //!< of the deflection θ − θ0
};

} // namespace hatpic
