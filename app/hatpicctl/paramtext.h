// How device parameters are shown: a text table and a profile document.
#pragma once

#include "model/effects.h"
#include "model/params.h"
#include "session/sessiontypes.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace hatpic::cli {

QString fieldUnit(int index);    //!< "kg·m²"
QString fieldMeaning(int index); //!< "virtual inertia of the admittance filter"

//! One line per field: name, value, unit, meaning — columns separated by spaces.
QString parameterTable(const DeviceParams &params);

//! A complete profile (profile.md) holding `params`, with default host settings except
//! tau_limit, which is the device's.
QByteArray parameterProfile(const DeviceParams &params, const DeviceInfo &info);

//! parameterProfile() when `json`, else parameterTable() — what get, set and zero print.
QByteArray parameterOutput(const DeviceParams &params, const DeviceInfo &info, bool json);
//! The same with the device's effect block: the table gains one line per effect field, the
//! profile its device.effects (written when the block differs from the defaults). Without
//! `effects` (a device without the capability), exactly the output above.
QByteArray parameterOutput(const DeviceParams &params, const std::optional<EffectParams> &effects,
                           const DeviceInfo &info, bool json);

//! One line per effect field: name, value, unit, meaning.
QString effectTable(const EffectParams &effects);
//! Why an effect block a device reported is not usable (effects.md § 2 against `tauLimit`);
//! empty when it is valid.
QString deviceEffectsProblem(const EffectParams &effects, double tauLimit);

//! Why parameters a device reported are not usable (model.md § 1, as 32-bit floats), every
//! violation joined with "; "; empty when they are valid.
QString deviceParamsProblem(const DeviceParams &params);

} // namespace hatpic::cli
