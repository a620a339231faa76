// What an experiment does to the knob: the τ_ext it applies over time, and where its analysis
// looks (docs/experiments.md). A plan is a value; ExperimentRunner carries it out.
#pragma once

#include "model/params.h"

#include <QList>
#include <QMetaType>
#include <QString>

namespace hatpic {

enum class ExperimentKind {
    Step,      //!< τ_ext steps from `tauFrom` to `tauTo`
    Frequency, //!< stepped sines around `offset`, one segment per frequency
    Spectrum,  //!< τ_ext held at 0; θ and τ are recorded for `duration`
};
QString experimentKindName(ExperimentKind kind); //!< "step", "bode", "spectrum"

//! One frequency of a stepped-sine plan, in plan time (seconds since the plan started).
struct SineSegment
{
    double frequency = 0;   //!< [Hz]
    double start = 0;       //!< the sine starts (phase 0) [s]
    double analyseFrom = 0; //!< after the transient and the guard [s]
    double analyseTo = 0;   //!< `cycles` whole periods later [s]
    double end = 0;         //!< the next segment starts [s]
};

struct ExperimentPlan
{
    static constexpr double kMaxDuration = 120;  //!< longest plan [s]
    static constexpr int kMaxFrequencies = 50;   //!< points of a frequency response
    static constexpr int kMaxCycles = 1000;      //!< periods analysed per frequency
    static constexpr double kMaxFrequency = 250; //!< a quarter of the 1 kHz stream [Hz]
    //! Shortest spectrum [s]: a resolution of 10 Hz, 100 samples at the 1 kHz stream. Shorter
    //! records leave the report's lines (above twice the resolution) nowhere to be.
    static constexpr double kMinSpectrumDuration = 0.1;
    //! Margin around each analysed stretch for the feedback stream's delay and the host clock's
    //! uncertainty about the device's [s].
    static constexpr double kGuard = 0.05;

    ExperimentKind kind = ExperimentKind::Step;
    double settle = 0.5;   //!< τ_ext before the step / the bias before the sines / transient [s]
    double duration = 1.0; //!< step: response after the step; spectrum: the recording [s]
    double tauFrom = 0;    //!< step: τ_ext before the step [N·m]
    double tauTo = 0;      //!< step: τ_ext after it [N·m]
    double offset = 0;     //!< sines: bias τ_ext [N·m]
    double amplitude = 0;  //!< sines: amplitude [N·m]
    QList<double> frequencies; //!< sines: ascending [Hz]
    int cycles = 4;            //!< sines: whole periods analysed at each frequency

    //! A plan for `params` that keeps the knob in the notch band, where τ_rec = −K_max·e is
    //! linear (docs/experiments.md § Why the knob is biased): the step goes from a quarter to
    //! three quarters of the band [Q_dz, N]; the sines swing a quarter band around its middle
    //! over 8 frequencies from a tenth to three times the model's bandwidth. Times follow the
    //! model's settling time.
    static ExperimentPlan defaults(ExperimentKind kind, const DeviceParams &params);

    //! Empty when the plan can run on a device with `tauLimit` [N·m]; otherwise one sentence.
    QString check(double tauLimit) const;
    //! τ_ext at plan time t [s] (0 before and after the plan).
    double tauExt(double t) const;
    //! The whole plan [s].
    double totalDuration() const;
    //! Step: plan time of the step [s].
    double stepTime() const { return settle; }
    //! Sines: the segments, one per frequency.
    QList<SineSegment> segments() const;
};

//! The model's 2 % settling estimate for `params` (4/(ζ·ω_n), or 4 over the slow pole when
//! over-damped) [s]; +inf when K_max = 0.
double modelSettlingEstimate(const DeviceParams &params);

} // namespace hatpic

Q_DECLARE_METATYPE(hatpic::ExperimentPlan)
