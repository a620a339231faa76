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

} // namespace hatpic
