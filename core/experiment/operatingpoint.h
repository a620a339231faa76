// Where an experiment's knob was, against where the model's figures apply (docs/experiments.md
// § The operating point): the notch band, no haptic effects, a response of more than a few
// encoder counts. Issue 27: on the Detents preset the knob sat in a detent at 0.78 rad, the
// step moved it 2 counts, and ω_n 61.6 "against 114" was reported as a result.
#pragma once

#include "experiment/experimentresult.h"
#include "model/devicetuning.h"

#include <QStringList>

namespace hatpic {

//! One encoder count of the STS3032: 2π/4096 [rad].
double encoderCount();

//! A response smaller than this many encoder counts is too coarse to fit.
inline constexpr double kMinResponseCounts = 5;
//! An effects torque above this fraction of the experiment's τ_ext change spoils the figures.
inline constexpr double kMaxEffectsShare = 0.05;

//! Before a run: why the model's figures will not apply (effects that act inside the notch
//! band), one sentence each; empty when nothing stands in the way.
QStringList operatingPointWarnings(const ExperimentKind kind, const DeviceTuning &tuning);

//! After a run: why its figures are not the model's (the knob outside the notch band, the
//! effects' torque, a response of a few encoder counts), one sentence each; empty when the
//! operating point was the model's. A spectrum has no model figures: always empty.
QStringList operatingPointCaveats(const ExperimentResult &result);

} // namespace hatpic
