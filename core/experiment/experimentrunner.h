// Carries out an ExperimentPlan on a connected device through its DeviceClient: streams the
// plan's τ_ext with SET_FEEDBACK, collects the samples, and analyses them. τ_ext goes back to
// 0 whenever the run ends — completed, cancelled, failed or destroyed.
//
// A device fault fails the run (docs/experiments.md § Faults): a sample whose telemetry says
// the torque is off (v2::kFlagTorqueOff) ends it at once, quoting what the device said in LOG
// frames during the run.
// On the in-process simulator (given to the runner by the program that made it) the simulated
// hand is the only other torque on the knob: it goes idle for the run (the knob given kReleaseMs to
// come to rest first when it was pushing) and is given back, as it was, whenever the run ends. A
// device on a port has a person's hand (or hatpic-sim's --hand), which no program can lift: the
// result says which it was (RunHand).
// The device's passivity controller (docs/teleop.md) would take the plan's τ_ext for a robot's
// port and damp the very response measured: it is turned off for the run (SET_PASSIVITY with
// pc_damping_max 0 before the plan) and its block is sent back whenever the run ends.
//
// Lives on the client's thread; every method returns at once.
#pragma once

#include "experiment/experimentresult.h"
#include "session/deviceclient.h"
#include "sim/simulatedjoystick.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <optional>

namespace hatpic {

class ExperimentRunner : public QObject
{
    Q_OBJECT
public:
    static constexpr int kTickMs = 1; //!< how often τ_ext is updated [ms]
    //! Longest wait after the plan for its last samples to arrive [ms].
    static constexpr int kDrainTimeoutMs = 1000;
    //! Samples kept per run: the longest plan at 4 kHz; beyond it the newest are dropped.
    static constexpr qsizetype kMaxSamples = 480'000;
    //! LOG lines kept per run for the failure's reason; later ones are not quoted.
    static constexpr qsizetype kMaxLogLines = 4;
    //! Time for the knob to come to rest once the simulated hand let go, before the plan [ms].
    static constexpr int kReleaseMs = 1000;
    //! Times the passivity block is sent back at the end when the device does not answer: a
    //! push that timed out may or may not have taken effect, and a controller left off after
    //! an experiment would leave a robot's loop without it.
    static constexpr int kRestoreAttempts = 3;

    //! `simulator`: the simulated joystick the client is connected through, if it is; its hand
    //! is idle for a run.
    explicit ExperimentRunner(DeviceClient &client, SimulatedJoystick *simulator = nullptr,
                              QObject *parent = nullptr);
    ~ExperimentRunner() override; //!< a running experiment is cancelled: τ_ext = 0

    //! Why no experiment can start on the client's device now; empty when one can.
    static QString refusal(const DeviceClient &client);
    //! What will hold the knob besides τ_ext during a run on the client's device now.
    RunHand handFor() const;

    //! Starts `plan`; returns why not (refusal(), the plan's check(), already running), or
    //! empty when it started.
    QString start(const ExperimentPlan &plan);
    //! Stops a running experiment; finished() reports it Cancelled.
    void cancel();
    bool running() const { return m_phase != Phase::Idle; }
    //! While running: what holds the knob besides τ_ext.
    RunHand hand() const { return m_hand; }

Q_SIGNALS:
    void progress(double fraction); //!< 0 … 1 of the plan
    void finished(const hatpic::ExperimentResult &result);

private:
    //! Preparing: the passivity controller going off, the simulated hand letting go.
    enum class Phase { Idle, Preparing, Running, Draining };

    //! The device answered the push that turns its passivity controller off.
    void onQuieted(const Outcome &outcome);
    //! The plan, once the controller is off and the knob has come to rest.
    void beginPlanWhenReady();
    void beginPlan();
    //! Sends the passivity block back as it was before the run, once per run.
    void restorePassivity();
    //! Pushes `block`; again while the device does not answer, `attempts` times in all.
    void sendPassivity(const PassivityParams &block, int attempts);
    void tick();
    void onSamples(const QList<Sample> &batch);
    void onDeviceLog(const QString &line);
    void end(ExperimentResult::Outcome outcome, const QString &problem);
    //! Gives the simulated hand back, as it was before the run.
    void restoreHand();
    double elapsed() const; //!< plan time [s]

    QPointer<DeviceClient> m_client; //!< null once the client is gone
    QPointer<SimulatedJoystick> m_simulator;
    QTimer m_timer;
    QTimer m_drainTimer;
    QTimer m_releaseTimer;
    QElapsedTimer m_clock;
    Phase m_phase = Phase::Idle;
    ExperimentPlan m_plan;
    DeviceParams m_params;
    double m_tauLimit = 0;
    QList<Sample> m_samples;
    QStringList m_deviceLog; //!< LOG lines of this run, at most kMaxLogLines
    ClockMap m_deviceClock;  //!< plan time → device time, from the batches' arrivals
    int m_lastProgress = -1; //!< percent last reported
    RunHand m_hand = RunHand::User;
    HandInput m_handBefore; //!< the simulated hand to give back (RunHand::SimulatedIdle)
    //! The device's passivity block to send back at the end; empty when it was left alone.
    std::optional<PassivityParams> m_passivityBefore;
    bool m_quieting = false;  //!< Preparing: the controller's push is on its way
    bool m_releasing = false; //!< Preparing: the simulated hand let go kReleaseMs ago
};

} // namespace hatpic
