// The passivity observer at the knob's port (docs/teleop.md § The passivity observer): the
// energy the feedback path has put into the knob, E = ∫ τ_ext·ω dt, and whether the loop is
// generating energy while in contact with something.
//
// Sign: E grows when τ_ext pushes the knob the way it moves (τ_ext·ω > 0): the feedback path
// gives the knob energy, which goes on into the operator's hand and the knob's damping. A passive
// contact only takes energy and gives back at most what it took: pushing into a wall
// (τ_ext = −g·F_e against the motion) makes E fall, letting go gives some of it back. So, from
// the moment a contact begins (nothing stored yet), E above its value then is energy the loop
// generated: delay, too much gain or too little damping.
//
// Plain C++20: no Qt. Times on any clock that does not jump [s]; torques [N·m]; rates [rad/s];
// energies [J].
#pragma once

#include "model/passivity.h"

#include <cstdint>
#include <deque>
#include <limits>
#include <string>
#include <vector>

namespace hatpic::analysis {

struct PassivitySettings
{
    double window = 1.5; //!< how far back a rise of E is measured [s], > 0
    //! The first seconds of a contact are its approach and are not judged: a robot driven
    //! into a wall (or pushed) returns through the knob energy its own motor supplied, once.
    //! What the loop generates after it is the loop's [s], ≥ 0.
    double approach = 1.5;
    double threshold = 0.5e-3;   //!< a rise above this within the window is "generating" [J], > 0
    double contactTorque = 5e-3; //!< |τ_ext| above this is contact [N·m], > 0
    double hold = 0.5;    //!< the warning stays this long after the rule last held [s], ≥ 0
    double maxGap = 0.25; //!< a step between samples longer than this is not integrated [s]
};

//! Every violated rule, naming the field, the rule and the value; empty when valid.
std::vector<std::string> validate(const PassivitySettings &settings);

class PassivityObserver
{
public:
    struct State
    {
        //! ∫ τ_ext·ω dt since reset(): > 0 when the feedback path gave the knob net energy [J].
        double energy = 0;
        //! E − max(E a window ago, E when this contact began, E when its approach ended):
        //! what the loop generated lately in this contact; 0 out of contact and during the
        //! approach. A passive contact keeps it ≤ 0 [J].
        double generated = 0;
        //! |τ_ext| > contactTorque within the last window.
        bool inContact = false;
        //! generated > threshold now (so for up to a window after the generation stopped).
        bool generating = false;
        //! generating within the last `hold` seconds: what a person is warned of.
        bool warning = false;
        std::uint64_t samples = 0; //!< samples taken in
        std::uint64_t gaps = 0;    //!< steps not integrated: longer than maxGap, or backwards
        std::uint64_t invalid = 0; //!< samples with a non-finite time, τ_ext or ω: skipped
        double time = std::numeric_limits<double>::quiet_NaN(); //!< of the last sample [s]

        // The device's passivity controller (passivity.md), from the τ_pc and R its telemetry
        // carries: the observer above stays an independent check of what it achieves.
        bool controllerReported = false; //!< a finite τ_pc came since reset()
        //! τ_pc ≠ 0 within the last `hold` seconds: the controller is damping.
        bool damping = false;
        //! The largest β = −τ_pc/ω within the last `hold` seconds (0 when idle) [N·m·s/rad].
        double dampingCoefficient = 0;
        double controllerTorque = 0; //!< τ_pc of the last sample [N·m]
        //! ∫ −τ_pc·ω dt = ∫ β·ω² dt since reset(): the energy the controller took out [J].
        double dissipated = 0;
        //! R of the last sample; NaN when the device does not report it [J].
        double reserve = std::numeric_limits<double>::quiet_NaN();
        //! The knob has stayed within passivity::kStillBand for passivity::kRestTime (θ given).
        bool atRest = false;
        //! While at rest: the share of samples with τ_pc ≠ 0, averaged over about the last
        //! second (exponentially); 0 otherwise.
        double restDampedShare = 0;
        //! At rest and damped in more than kDampedAtRestShare of it: the controller holds the
        //! knob heavier than tuned because the loop does not rest on its own (docs/teleop.md).
        bool dampedAtRest = false;
    };

    //! Damped in more than this share of a rest's samples is "damped at rest" (passivity.md's
    //! target: at most 5 % once at rest).
    static constexpr double kDampedAtRestShare = 0.05;

    //! Settings that validate() refuses are not taken: the defaults are used instead.
    explicit PassivityObserver(const PassivitySettings &settings = {});

    //! One sample: time `t` [s], τ_ext as the device rendered it [N·m], the knob's ω [rad/s],
    //! the passivity controller's τ_pc [N·m] and reserve R [J] (NaN: not reported), and the
    //! knob's angle θ [rad] (NaN: rest is not judged). The energies are integrated by the
    //! trapezoidal rule from the previous sample.
    void add(double t, double tauExt, double omega,
             double tauPc = std::numeric_limits<double>::quiet_NaN(),
             double reserve = std::numeric_limits<double>::quiet_NaN(),
             double theta = std::numeric_limits<double>::quiet_NaN());
    //! E back to 0, no contact, counters 0.
    void reset();

    const State &state() const { return m_state; }
    const PassivitySettings &settings() const { return m_settings; }

private:
    //! Whether the knob rests at `theta` and how often the controller damped it there.
    void judgeRest(double t, double theta, bool damped);

    struct Point
    {
        double t;
        double energy;
    };

    PassivitySettings m_settings;
    State m_state;
    bool m_havePrevious = false;
    double m_previousT = 0;
    double m_previousPower = 0;
    double m_previousControllerPower = 0; //!< −τ_pc·ω of the previous sample (0: not reported)
    double m_lastDampingT = -std::numeric_limits<double>::infinity();
    double m_dampingPeakT = -std::numeric_limits<double>::infinity(); //!< of dampingCoefficient
    //! E every window/kPointsPerWindow at most, over a little more than the last window.
    std::deque<Point> m_history;
    double m_contactStartEnergy = 0; //!< max(E at the contact's start, E at its approach's end)
    double m_contactStartT = 0;      //!< when this contact began [s]
    bool m_approachOver = false;     //!< m_contactStartEnergy holds
    double m_lastContactT = -std::numeric_limits<double>::infinity();
    double m_lastGeneratingT = -std::numeric_limits<double>::infinity();
    StillClock<double> m_still;                                 //!< of θ, as the device's tank
    double m_stillT = std::numeric_limits<double>::quiet_NaN(); //!< its last observation [s]
    double m_restT = std::numeric_limits<double>::quiet_NaN();  //!< the rest's last sample [s]
};

} // namespace hatpic::analysis
