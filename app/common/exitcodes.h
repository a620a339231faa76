// The exit codes of every HATPIC program (docs/cli.md, "Exit codes"): one table, so that a code
// means the same thing whichever program returns it. Scripts depend on these values.
#pragma once

namespace hatpic {

enum ExitCode : int {
    ExitSuccess = 0,
    //! It ran and could not go on: no pseudo-terminal, no servo, the middleware refused
    //! (hatpic-sim, hatpic-fw-host, hatpic-servo-sim, hatpic-bridge, hatpic-robot-sim).
    ExitFailure = 1,
    ExitRejected = 2, //!< hatpicctl: the device answered, but refused the command
    ExitNoDevice = 3, //!< hatpicctl: no device, no answer in time, or the link was lost
    //! Every program: a bad option or value (one sentence on stderr); hatpicctl also for a file
    //! that cannot be read, written or validated.
    ExitBadUsage = 4,
};

} // namespace hatpic
