// The CSV form of samples that `stream` (to stdout) and `simulate` print.
#pragma once

#include "telemetry/sample.h"

#include <QByteArray>

namespace hatpic::cli {

//! "t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags\n"
QByteArray sampleCsvHeader();
//! One row; numbers in shortest round-trip form, flags as a decimal integer.
QByteArray sampleCsvRow(const Sample &sample);

} // namespace hatpic::cli
