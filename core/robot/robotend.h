// The robot's end of the teleoperation loop, one step of h at a time (robot.md): the twist's
// component arriving through the inbound fault channel, the stale rule, the model's step, and
// the estimated wrench every 1/rate going out through the outbound fault channel. Plain C++ on
// a clock the caller supplies: hatpic-robot-sim runs it on the host's monotonic clock
// (core/robotsim), the in-process loop (core/teleop) on virtual time. `Wrench` is what goes
// back: a ROS message there, a plain force here.
#pragma once

#include "robot/linkfaults.h"
#include "robot/robotmodel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace hatpic::robot {

//! What one step of the robot's end needs besides its clock.
struct RobotEndSettings
{
    RobotParams robot;
    LinkFaults faults;       //!< both directions: the twist in, the wrench out
    std::uint64_t seed = 1;  //!< inbound seed; the outbound channel's is seed + 1
    double rateHz = 200;     //!< wrenches per second (≤ 1000: one per step) [Hz]
    double staleAfter = 0.5; //!< v_ref = 0 once the last twist is this old [s]
};

template<typename Wrench> class RobotEnd
{
public:
    explicit RobotEnd(const RobotEndSettings &settings)
        : m_settings(settings), m_model(settings.robot), m_inbound(settings.faults, settings.seed),
          m_outbound(settings.faults, settings.seed + 1),
          m_stepsPerOutput(std::max(1, int(std::lround(1000.0 / settings.rateHz))))
    {}

    //! A twist whose followed component is `v` [m/s] left the knob's side at `t` [s].
    void twistSent(double v, double t) { m_inbound.send(v, t); }

    //! One step at time `t` [s]: delivers the twists due, steps the model, and every
    //! 1/rate sends `make(model)` back; hands every wrench due at `t` to `deliver`. True when
    //! this step sent a wrench.
    template<typename Make, typename Deliver> bool step(double t, Make &&make, Deliver &&deliver)
    {
        m_inbound.deliverDue(t, [&](double v) {
            m_vRef = std::isfinite(v) ? v : 0.0; // a non-finite component is no reference
            m_lastTwistAt = t;
            ++m_twistsIn;
        });
        m_stale = m_lastTwistAt < 0 || t - m_lastTwistAt > m_settings.staleAfter;
        m_model.step(vRef());
        const bool output = ++m_steps % std::uint64_t(m_stepsPerOutput) == 0;
        if (output)
            m_outbound.send(make(std::as_const(m_model)), t);
        m_outbound.deliverDue(t, deliver);
        return output;
    }

    const RobotModel &model() const { return m_model; }
    double vRef() const { return m_stale ? 0.0 : m_vRef; } //!< the reference in force [m/s]
    bool stale() const { return m_stale; }
    std::uint64_t twistsIn() const { return m_twistsIn; }
    //! Lost or overflowed on purpose, both directions.
    std::uint64_t dropped() const
    {
        return m_inbound.counters().lost + m_inbound.counters().overflow +
               m_outbound.counters().lost + m_outbound.counters().overflow;
    }

private:
    RobotEndSettings m_settings;
    RobotModel m_model;
    FaultyChannel<double> m_inbound; //!< the twist's component, knob → robot
    FaultyChannel<Wrench> m_outbound;
    int m_stepsPerOutput = 5;
    std::uint64_t m_steps = 0;
    double m_vRef = 0;
    double m_lastTwistAt = -1; //!< when the last twist reached the robot [s]
    bool m_stale = true;
    std::uint64_t m_twistsIn = 0;
};

} // namespace hatpic::robot
