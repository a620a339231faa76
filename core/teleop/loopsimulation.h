// The whole teleoperation loop of robot.md in one process, on virtual time: the simulated
// joystick's device core as hatpic-sim runs it (emulated servo, its load noise, the hand of
// --hand), the host's reference and the bridge's mapping (teleop/wrenchfeedback.h: gain, limit,
// stale; teleop/ratelimiter.h: the twist's rate), and robot.md's robot between its two fault
// channels (robot/robotend.h), each stepped every millisecond. Nothing waits for a clock, so a
// 20 s run takes a small fraction of a second; the same seed gives the same run.
#pragma once

#include "model/effects.h"
#include "model/params.h"
#include "model/passivity.h"
#include "profile/bridgesettings.h"
#include "robot/loopequilibrium.h"
#include "robot/robotend.h"
#include "sim/handinput.h"
#include "sim/simulateddevice.h"

#include <QString>

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace hatpic::teleop {

//! One loop: the tuning, the hand, the bridge, the robot and the network between them.
struct LoopConfig
{
    DeviceParams device; //!< the knob's tuning (rounded to the device's floats when sent)
    HostParams host;     //!< v_max, the reference's dead zone, tau_limit
    EffectParams effects;
    //! The passivity controller's block (passivity.md; pc_damping_max 0: off).
    PassivityParams passivity;
    //! The hand on the knob (hatpic-sim --hand); robot.md's loop pushes 0.05 N·m.
    HandInput hand{HandInput::Kind::Constant, 0.05};
    //! The bridge's wrench → τ_ext (hatpic-bridge --component force.x --gain 0.02).
    bridge::FeedbackSettings feedback{
        {false, 0}, 0.02, bridge::FeedbackSettings{}.limit, bridge::FeedbackSettings{}.staleAfter};
    double twistRateHz = bridge::BridgeSettings{}.publishRateHz; //!< the bridge's [Hz]
    //! The robot, its wrench rate and stale time (hatpic-robot-sim's defaults), the network's
    //! faults (--delay, --jitter, --loss) and their seed.
    robot::RobotEndSettings robot;
    //! Virtual time run [s]; with several contacts, the time of each.
    double duration = 20;
    //! How many contacts (passivity.md's "every contact"): with more than one, a constant hand
    //! pushes for `duration`, lets go for kRelease, and pushes again, `contacts` times
    //! (HandInput::pushing); each contact is judged on its own.
    int contacts = 1;
    double noise = SimulatedDevice::kProgramNoise; //!< load-reading noise, hatpic-sim's [N·m]
    std::uint64_t seed = 1;                        //!< the noise's seed (the faults': robot.seed)

    static constexpr double kRelease = 2.0; //!< the hand lets go this long between contacts [s]
    static constexpr int kMaxContacts = 100;
    //! The virtual time the whole run takes: every contact and the releases between [s].
    double runTime() const { return contacts * duration + (contacts - 1) * kRelease; }
};

//! The figures of one contact of a run (docs/teleop.md § The stability map): the whole run
//! when it makes one contact.
struct LoopResult
{
    static constexpr double kBand = 0.003;     //!< |θ − θ_eq| that counts as at rest [rad]
    static constexpr double kRestWindow = 2.0; //!< the last seconds judged [s]
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

    int index = 1;           //!< which contact of the run, from 1
    bool contact = false;    //!< τ_ext ≠ 0 in some cycle
    double contactAt = kNaN; //!< the first such cycle, from the run's start [s]
    double thetaEq = kNaN;   //!< where the loop must rest (robot.md), NaN: no rest known [rad]
    //! At rest at θ_eq: every θ of the last 2 s within kBand of θ_eq.
    bool settled = false;
    //! From contact to the last cycle with |θ − θ_eq| > kBand (passivity.md); NaN when not
    //! settled [s].
    double settleS = kNaN;
    double p2p = kNaN;        //!< θ's peak to peak over the last 2 s [rad]
    double thetaRest = kNaN;  //!< θ's mean over the last 2 s [rad]
    double tauExtRest = kNaN; //!< τ_ext's mean over the last 2 s [N·m]
    double xRest = kNaN;      //!< the robot's mean position over the last 2 s [m]
    //! RMS(τ_pc) / RMS(τ_ext) from contact to rest (to the end when not settled); NaN
    //! without contact.
    double rmsTauPcRatio = kNaN;
    double dissipatedJ = 0; //!< Σ β·ω²·h: what the passivity controller took out [J]
    //! The share of the last 2 s's cycles in which the passivity controller damped (β > 0):
    //! the knob made heavier at rest (passivity.md: at most 5 % once at rest).
    double dampedAtRest = kNaN;
    //! Empty, or why the run stopped early (it left the finite numbers).
    QString problem;
};

class LoopSimulation
{
public:
    //! One cycle of the loop as the device and the robot saw it.
    struct Step
    {
        double t = 0;       //!< [s]
        double theta = 0;   //!< measured knob angle [rad]
        double omega = 0;   //!< [rad/s]
        double tauExt = 0;  //!< the feedback the device rendered [N·m]
        double tauPc = 0;   //!< the passivity controller's torque [N·m]
        double reserve = 0; //!< the passivity controller's reserve R after the cycle [J]
        double x = 0;       //!< the robot's position [m]
    };

    //! Empty when `config` can run, else one sentence naming the field, the rule and the value.
    static QString check(const LoopConfig &config);
    //! Where the loop must come to rest: robot.md's equilibrium for a constant hand (or a
    //! step's final torque), nullopt for other hands or when the hand pulls away from the wall.
    static std::optional<robot::LoopEquilibrium> equilibrium(const LoopConfig &config);

    //! `config` must pass check().
    explicit LoopSimulation(const LoopConfig &config);
    ~LoopSimulation();
    LoopSimulation(const LoopSimulation &) = delete;
    LoopSimulation &operator=(const LoopSimulation &) = delete;

    bool atEnd() const;
    Step step(); //!< the next millisecond
    //! The figures of each contact, of the cycles run so far.
    std::vector<LoopResult> contactResults() const;
    //! The figures of the worst contact (worst(contactResults())).
    LoopResult result() const;
    //! The worst of `contacts`: one that never settled (the widest swing) before the slowest
    //! to settle; a default result when empty.
    static LoopResult worst(const std::vector<LoopResult> &contacts);

    //! Runs `config` to its end and returns its figures (its worst contact's).
    static LoopResult run(const LoopConfig &config);
    //! Runs `config` to its end and returns the figures of each contact.
    static std::vector<LoopResult> runContacts(const LoopConfig &config);

private:
    class Private;
    std::unique_ptr<Private> d;
};

} // namespace hatpic::teleop
