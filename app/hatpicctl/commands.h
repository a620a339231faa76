// Factories of the subcommands; each lives in its own <name>command.cpp.
#pragma once

#include <memory>

namespace hatpic::cli {

class Command;

std::unique_ptr<Command> makePortsCommand();
std::unique_ptr<Command> makeInfoCommand();
std::unique_ptr<Command> makeGetCommand();
std::unique_ptr<Command> makeSetCommand();
std::unique_ptr<Command> makeZeroCommand();
std::unique_ptr<Command> makeSaveCommand();
std::unique_ptr<Command> makeStreamCommand();
std::unique_ptr<Command> makeCurveCommand();
std::unique_ptr<Command> makeSimulateCommand();
std::unique_ptr<Command> makeValidateCommand();
std::unique_ptr<Command> makeExperimentCommand();
std::unique_ptr<Command> makeVibrateCommand();

} // namespace hatpic::cli
