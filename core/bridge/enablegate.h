// The enable switch (a dead man, ros.md § Enable switch): whether the knob drives the robot now,
// from the enable topic (std_msgs/Bool) and the local switch (the tuner's), and the reference
// the robot sees across a release. Plain C++, no middleware, no Qt; the caller holds the lock.
#pragma once

#include "model/axes.h"

#include <array>

namespace hatpic::bridge {

class EnableGate
{
public:
    //! `topic`: an enable topic is configured. Without one only the local switch counts and it
    //! starts engaged; with one the gate starts released and engages on the first true.
    //! `timeout` [s]: with a topic, released when no message came for this long.
    EnableGate(bool topic = false, double timeout = 0.5);

    //! A message on the enable topic at `now` [s, monotonic].
    void received(bool value, double now);
    //! The local switch (the tuner's key or toggle); engaged by default.
    void setLocal(bool engaged) { m_local = engaged; }
    bool local() const { return m_local; }

    //! Whether the knob drives the robot at `now`: the local switch, and (with a topic) a true
    //! received less than `timeout` ago.
    bool engaged(double now) const;

    //! The reference position to publish for knob `knob`'s (0 = knob 1) `pRef` when the gate
    //! is `engaged`: held while released; on engaging again it re-anchors, so that the published
    //! reference goes on from where it was held, without a jump, and follows the knob's motion
    //! from there. Each knob keeps its own.
    double reference(double pRef, bool engaged, int knob = 0);
    //! The offset subtracted from knob `knob`'s p_ref now (0 until the first re-anchoring).
    double offset(int knob = 0) const { return m_knobs[std::size_t(knob)].offset; }

private:
    bool m_topic;
    double m_timeout;
    bool m_local = true;
    bool m_value = false;        //!< the last message's value
    double m_lastMessage = -1e9; //!< when it came [s]
    struct Knob
    {
        bool wasEngaged = true; //!< at the last reference()
        double offset = 0;      //!< published p_ref = device's p_ref − offset
        double held = 0;        //!< the published p_ref while released
        bool started = false;   //!< reference() has been called
    };
    std::array<Knob, kMaxAxes> m_knobs{};
};

} // namespace hatpic::bridge
