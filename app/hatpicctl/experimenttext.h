// How `hatpicctl experiment` prints a result: a table of measured next to model figures on
// stdout (docs/cli.md).
#pragma once

#include "experiment/experimentresult.h"

#include <QString>

namespace hatpic::cli {

//! The figures, measured next to the model's, one per line.
QString experimentReport(const ExperimentResult &result);

} // namespace hatpic::cli
