// What the editor shows for each numeric parameter: meaning, unit, ranges, tooltips.
#pragma once

#include "editor/parameterfield.h"

#include <QList>

namespace hatpic {

//! The seven device fields in ParamBlock order (spin ranges: model.md § 1 per-field rules).
QList<ParameterField::Spec> deviceFieldSpecs();
//! Spec of host field "v_max".
ParameterField::Spec vMaxSpec();
//! Spec of host field "tau_limit".
ParameterField::Spec tauLimitSpec();
//! The seven effect fields in wire order (effects.md § 2). detent_strength's spin box goes up
//! to tau_limit's own maximum; validation holds it to the set's tau_limit.
QList<ParameterField::Spec> effectFieldSpecs();
//! The passivity controller's two fields in wire order (passivity.md).
QList<ParameterField::Spec> passivityFieldSpecs();
//! The vibration cue's amplitude, frequency and duration (VIBRATE; not part of a profile).
QList<ParameterField::Spec> vibrationFieldSpecs();

} // namespace hatpic
