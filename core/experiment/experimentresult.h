// What an experiment measured, next to what the model predicts, and the analysis that turns
// recorded samples into it (docs/experiments.md). Pure: the GUI re-analyses a recording with
// the same function the runner uses.
#pragma once

#include "analysis/frequencyresponse.h"
#include "analysis/spectrum.h"
#include "analysis/stepresponse.h"
#include "experiment/experimentplan.h"
#include "model/derived.h"
#include "telemetry/sample.h"

#include <QList>
#include <QMetaType>
#include <QString>

#include <vector>

namespace hatpic {

//! Device time for plan time, from the pairs (plan time, device time − plan time) the runner
//! notes as batches arrive. A batch's newest sample was taken at most at its arrival, so each
//! pair bounds the offset from below and the batch that came fastest bounds it best: the
//! largest offset within kWindow of a plan time is used. Local, so a device clock that runs
//! slower or faster than the host's (a starved simulator) is followed.
class ClockMap
{
public:
    static constexpr double kWindow = 0.5; //!< [s]
    static constexpr std::size_t kMaxPoints = 100'000;

    ClockMap() = default;
    //! A device clock `offset` ahead of plan time, everywhere.
    explicit ClockMap(double offset) { add(0, offset); }
    void add(double planTime, double offset);
    //! [s]; plan time when nothing was noted.
    double deviceTime(double planTime) const;

private:
    std::vector<std::pair<double, double>> m_points; //!< (plan time, offset), ascending
};

//! What held the knob besides the experiment's τ_ext while it ran: the figures say it, since a
//! hand that pushes (the simulator's sine) spoils them.
enum class RunHand {
    SimulatedIdle, //!< the in-process simulator: its hand was idle for the run
    User,          //!< a device on a port: the user's hand (or hatpic-sim's --hand), untouched
};
//! "idle (simulated)" / "the user's (real device)": the one wording of the tuner and hatpicctl.
QString runHandText(RunHand hand);

struct ExperimentResult
{
    enum class Outcome { Completed, Cancelled, Failed };

    ExperimentPlan plan;
    Outcome outcome = Outcome::Completed;
    //! Cancelled/Failed: why; Completed: empty, or why part of the analysis is missing.
    QString problem;
    //! Completed, but without the measurement the experiment exists for (no step in the
    //! device's τ_ext column, a frequency without samples, too few samples for a spectrum):
    //! no figure stands for the knob; `problem` says why.
    bool unmeasured = false;
    DeviceParams params;    //!< the device's parameters during the run
    double tauLimit = 0.44; //!< the device's torque limit [N·m]
    DerivedFigures figures; //!< the model's figures for `params`
    QList<Sample> samples;  //!< everything received during the run (device time)
    ClockMap clock;         //!< device time of plan time (estimated)
    double sampleRate = 0;  //!< measured telemetry rate [Hz]
    //! What held the knob besides τ_ext.
    RunHand hand = RunHand::User;

    // Step
    double stepAt = 0;                    //!< device time of the step (τ_ext column) [s]
    analysis::StepMetrics stepMeasured;   //!< of θ after the step
    analysis::SecondOrderFit fitMeasured; //!< fitted to θ after the step
    QList<Sample> ideal;                  //!< the ideal model's run of the same plan (plan time)
    double idealStepAt = 0;               //!< plan time of the step in `ideal` [s]
    analysis::StepMetrics stepIdeal;      //!< of the ideal response
    analysis::SecondOrderFit fitIdeal;    //!< fitted to the ideal response

    // Frequency response
    std::vector<analysis::FrequencyPoint> points; //!< measured θ/τ_ext, ascending frequency
    double bandwidth = 0;                         //!< measured −3 dB [Hz]; NaN if not reached
    double modelBandwidth = 0;                    //!< the model's −3 dB [Hz]

    // Spectrum
    analysis::Spectrum thetaSpectrum; //!< of θ [rad]
    analysis::Spectrum tauSpectrum;   //!< of τ [N·m]

    bool completed() const { return outcome == Outcome::Completed; }
};

//! Analyses `samples` recorded while `plan` ran, `clock` mapping plan time to device time:
//! the step's figures and fit (and the ideal model's run of the same plan), the frequency
//! points, or the spectra. The result's outcome is Completed; `problem` names what could not
//! be analysed (e.g. no step in the τ_ext column).
ExperimentResult analyseExperiment(const ExperimentPlan &plan, const QList<Sample> &samples,
                                   const ClockMap &clock, const DeviceParams &params,
                                   double tauLimit);

//! The spectra of θ and τ over samples (e.g. a plot's visible window); uniform spacing is
//! assumed at the median rate.
void spectraOf(const QList<Sample> &samples, analysis::Spectrum &theta, analysis::Spectrum &tau);

} // namespace hatpic

Q_DECLARE_METATYPE(hatpic::ExperimentResult)
