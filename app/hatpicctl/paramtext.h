// How a device's tuning is shown: a text table and a profile document.
#pragma once

#include "model/devicetuning.h"
#include "session/sessiontypes.h"

#include <QByteArray>
#include <QString>

#include <vector>

namespace hatpic::cli {

//! One line per parameter (model.md): name, value, unit, meaning — columns separated by spaces.
QString parameterTable(const DeviceParams &params);

//! What get, set and zero print of `tuning`: with `json` a complete profile (profile.md) that
//! `set --profile` accepts — default host settings except tau_limit, the device's — else the
//! table above followed by one line per field of each block the tuning has (the effect block,
//! effects.md; the passivity block, passivity.md). A part the tuning lacks (a device without the
//! capability) adds no lines and leaves the profile's block at its defaults, so it is not
//! written.
QByteArray tuningOutput(const DeviceTuning &tuning, const DeviceInfo &info, bool json);

//! The violations joined with "; " (each naming field, rule and value); empty when there are
//! none. Why a block a device reported is not usable.
QString problemText(const std::vector<Violation> &violations);

} // namespace hatpic::cli
