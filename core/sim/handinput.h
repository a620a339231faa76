// The operator's hand on the simulated knob: a torque [N·m] as a function of time and state.
#pragma once

#include <QMetaType>
#include <QString>

#include <numbers>
#include <optional>

namespace hatpic {

//! Parsed form of a hand SPEC (docs/cli.md): `idle`, `const:T`, `step:T[:T0[:AT]]`,
//! `sine:A:F`, `chirp:A:F0:F1`, `hand:ANGLE`, `pushes:T:N:ON:OFF`. Torques are the operator's
//! torque τ_op on the knob; positive pushes θ positive (so the measured τ is its negative).
struct HandInput
{
    enum class Kind { Idle, Constant, Step, Sine, Chirp, VirtualHand, Pushes };

    Kind kind = Kind::Idle;
    double amplitude = 0;  //!< T for const/step, A for sine/chirp [N·m]
    double offset = 0;     //!< T0 of step: torque before the step [N·m]
    double frequency = 0;  //!< F of sine, F0 of chirp [Hz]
    double frequency1 = 0; //!< F1 of chirp [Hz]
    double angle = 0;      //!< target of the virtual hand [rad]
    //! AT of step: when the step happens [s]. Last, so that brace-initialised hands written
    //! before it keep their meaning.
    double stepTime = kStepTime;
    int pushes = 1;         //!< N of pushes: how many times the hand pushes
    double pushTime = 0;    //!< ON of pushes: how long each push holds T [s]
    double releaseTime = 0; //!< OFF of pushes: how long the hand lets go between pushes [s]

    static constexpr double kStepTime = 0.1;      //!< when a step happens by default [s]
    static constexpr double kMaxStepTime = 3600;  //!< AT at most: an hour [s]
    static constexpr double kChirpPeriod = 10.0;  //!< one linear F0→F1 sweep, then repeats [s]
    static constexpr double kHandStiffness = 2.0; //!< virtual hand spring [N·m/rad]
    static constexpr double kHandDamping = 0.05;  //!< virtual hand damper [N·m·s/rad]

    // What parse() accepts (simulator.md § 4): far beyond what a hand does to this knob, yet
    // small enough that the simulated knob stays within finite numbers.
    static constexpr double kMaxTorque = 10.0;                //!< |T|, |T0|, |A| [N·m]
    static constexpr double kMaxFrequency = 1000.0;           //!< F, F0, F1 [Hz]
    static constexpr double kMaxAngle = 2 * std::numbers::pi; //!< |ANGLE|: one turn [rad]
    static constexpr int kMaxPushes = 1000;                   //!< N of pushes at most
    static constexpr double kMaxPhase = 3600;                 //!< ON, OFF at most: an hour [s]

    //! A hand that pushes `torque` for `on` s, lets go for `off` s, `count` times, and then lets
    //! go (pushes:T:N:ON:OFF): the same contact made again and again.
    static HandInput pushing(double torque, int count, double on, double off);
    //! Pushes: when push `index` (from 0) begins [s].
    double pushStart(int index) const { return index * (pushTime + releaseTime); }

    //! τ_op at time t since the input started, for knob angle θ [rad] and rate ω [rad/s].
    double torque(double t, double theta, double omega) const;

    //! Parses SPEC; on failure returns nullopt and sets `error` to one clear sentence.
    static std::optional<HandInput> parse(const QString &spec, QString *error = nullptr);
    //! The SPEC text that parses back to this input.
    QString toSpec() const;

    friend bool operator==(const HandInput &, const HandInput &) = default;
};

} // namespace hatpic

Q_DECLARE_METATYPE(hatpic::HandInput)
