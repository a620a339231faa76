// The robot's wrench → the τ_ext the device renders (ros.md § Feedback). Plain C++: the
// network is untrusted, so a non-finite value or a wrench that stopped coming gives 0.
#pragma once

#include "model/axes.h"
#include "profile/bridgesettings.h"

#include <cstdint>
#include <limits>

namespace hatpic::bridge {

class WrenchFeedback
{
public:
    struct Counters
    {
        std::uint64_t received = 0;  //!< wrenches taken in
        std::uint64_t nonFinite = 0; //!< … whose component was NaN or ±Inf: τ_ext = 0
        std::uint64_t limited = 0;   //!< … whose gain · component exceeded the limit
        std::uint64_t stale = 0;     //!< times the last wrench grew older than staleAfter
    };

    explicit WrenchFeedback(const FeedbackSettings &settings = {}) : m_settings(settings) {}

    //! Gain, limit and staleness take effect at the next wrench or torqueAt().
    void setSettings(const FeedbackSettings &settings) { m_settings = settings; }
    const FeedbackSettings &settings() const { return m_settings; }

    //! The components fed back to knobs 2 … kMaxAxes (a board's), in order.
    using OtherKnobs = std::array<double, kMaxAxes - 1>;

    //! A wrench whose chosen component is `value` arrived at monotonic time `now` [s], with
    //! `others` for a board's other knobs. Returns τ_ext = clamp(gain · value, ±limit), or 0
    //! for a non-finite value [N·m]. Only knob 1's value is counted.
    double receive(double value, double now, const OtherKnobs &others = {});
    //! Knob 1 now feels another component of the same last wrench, whose value is `value`
    //! (the operator switched its axis): it keeps the wrench's time, and nothing is counted.
    void rechoose(double value) { m_lastValue = value; }
    //! τ_ext at monotonic time `now`: the last wrench's, or 0 once it is older than
    //! staleAfter (or when none came) [N·m].
    double torqueAt(double now);
    //! Every knob's τ_ext at `now`, knob 1's torqueAt() first: each of the last wrench's
    //! components mapped as knob 1's, all 0 once it is stale [N·m].
    AxisTorques torquesAt(double now);

    const Counters &counters() const { return m_counters; }
    double lastValue() const { return m_lastValue; } //!< last component received (NaN: none)
    bool isStale() const { return m_stale; }

private:
    double mapped(double value);

    FeedbackSettings m_settings;
    Counters m_counters;
    double m_lastValue = std::numeric_limits<double>::quiet_NaN();
    OtherKnobs m_otherValues{};
    double m_lastTime = 0;
    bool m_stale = true; //!< no wrench yet counts as stale, but is not counted
};

} // namespace hatpic::bridge
