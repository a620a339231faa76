// The command-line programs' words (hatpicctl, hatpic-bridge) for what the device session reports
// in codes and numbers: the state's detail, a command's failure and the session's notices. One
// sentence each, as printed.
#pragma once

#include "session/sessiontypes.h"

#include <QString>

namespace hatpic::cli {

//! "/dev/ttyUSB0 at 921600 baud", or "the simulated joystick" (no serial line, no baud rate).
QString portDescription(const StateDetail &detail);
//! e.g. "Lost /dev/ttyUSB0 at 921600 baud: reading from the port failed"; empty for None.
QString stateDetailText(const StateDetail &detail);
//! Why a command failed, e.g. "The device rejected K_max (field 3): OUT_OF_RANGE; its
//! parameters are unchanged."; empty for Ok (hatpicctl prints what it got instead).
QString commandFailureText(const CommandResult &result);
//! e.g. "Not connected: a recording starts once a device is connected."
QString noticeText(const SessionNotice &notice);

//! The programs report each failure once, in the sentences above; the library's own log lines
//! ("hatpic.*" categories) would repeat them, so this turns them off. QT_LOGGING_RULES=
//! "hatpic.*=true" brings them back (the environment takes precedence).
void silenceLibraryLog();

} // namespace hatpic::cli
