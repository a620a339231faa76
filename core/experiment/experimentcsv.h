// A result's curves as CSV, the same from `hatpicctl experiment --csv` and the tuner's export
// (docs/experiments.md § Files): SI units, one header line naming the columns.
//   step      t_s,theta,tau_ext,model_theta   (t_s since the step; model_theta: the ideal run)
//   bode      frequency_hz,magnitude,phase,model_magnitude,model_phase   (rad/(N·m), rad)
//   spectrum  frequency_hz,theta,theta_db,tau,tau_db   (amplitudes in rad and N·m)
#pragma once

#include "experiment/experimentresult.h"

#include <QByteArray>

namespace hatpic {

QByteArray experimentCsv(const ExperimentResult &result);

} // namespace hatpic
