// Exit codes of hatpicctl (docs/cli.md, "Exit codes"). Scripts depend on these values.
#pragma once

namespace hatpic::cli {

enum ExitCode : int {
    ExitSuccess = 0,
    ExitRejected = 2, //!< the device answered, but refused the command
    ExitNoDevice = 3, //!< no device, no answer in time, or the link was lost
    ExitBadUsage = 4, //!< bad arguments, or a file that cannot be read, written or validated
};

} // namespace hatpic::cli
