// The model's ideal response to a plan: the simulated device in its ideal mode (model.md
// alone: no servo lag, quantisation or noise), fed the plan's τ_ext through SET_FEEDBACK before
// every control step — the offline simulation of `hatpicctl simulate --ideal` with τ_ext as
// the input instead of the hand.
#pragma once

#include "experiment/experimentplan.h"
#include "telemetry/sample.h"

#include <QList>

namespace hatpic {

//! One sample per control step at `rateHz`, t_s = plan time, from θ = θ0 at rest, over the
//! whole plan. `params` must be valid; `tauLimit` is the device's [N·m].
QList<Sample> idealResponse(const ExperimentPlan &plan, const DeviceParams &params, double tauLimit,
                            double rateHz);

} // namespace hatpic
