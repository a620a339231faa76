// Factories of the subcommands; each lives in its own <name>subcommand.cpp.
#pragma once

#include <memory>

namespace hatpic::cli {

class Subcommand;

std::unique_ptr<Subcommand> makePortsSubcommand();
std::unique_ptr<Subcommand> makeInfoSubcommand();
std::unique_ptr<Subcommand> makeGetSubcommand();
std::unique_ptr<Subcommand> makeSetSubcommand();
std::unique_ptr<Subcommand> makeZeroSubcommand();
std::unique_ptr<Subcommand> makeSaveSubcommand();
std::unique_ptr<Subcommand> makeStreamSubcommand();
std::unique_ptr<Subcommand> makeCurveSubcommand();
std::unique_ptr<Subcommand> makeSimulateSubcommand();
std::unique_ptr<Subcommand> makeValidateSubcommand();
std::unique_ptr<Subcommand> makeExperimentSubcommand();
std::unique_ptr<Subcommand> makeVibrateSubcommand();
std::unique_ptr<Subcommand> makeTeleopMapSubcommand();

} // namespace hatpic::cli
