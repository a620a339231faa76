// hatpic-sim's --cycle-log: every control cycle of the simulated device as one CSV line. Its
// columns are t_s (the simulated time), then the cycle's quantities as forEachCycleQuantity
// lists them (model/cyclequantities.h: TELEMETRY's, in its order), then tau_total, the device's
// clamped sum, which TELEMETRY does not carry. A quantity added to that list is a column here
// without a change to this file.
#pragma once

#include "sim/simulateddevice.h"

#include <QByteArray>

namespace hatpic {

//! The header line, without its newline: "t_s,t_us,theta,…,tau_total".
QByteArray cycleLogHeader();
//! One cycle's line, without its newline: whole numbers for t_us and flags, the rest with 9
//! significant digits.
QByteArray cycleLogLine(const SimulatedDevice::Cycle &cycle);

} // namespace hatpic
