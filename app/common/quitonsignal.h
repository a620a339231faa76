// SIGINT/SIGTERM → QCoreApplication::quit(), for the programs that run until stopped
// (hatpic-sim, hatpic-fw-host, hatpic-servo-sim).
#pragma once

namespace hatpic {

//! Installs async-signal-safe handlers for SIGINT and SIGTERM that only write a byte to a
//! self-pipe; a QSocketNotifier on the pipe quits the application's event loop. SIGPIPE is
//! ignored. Call once, after the QCoreApplication exists. False when the pipe cannot be made.
bool quitOnSignals();

} // namespace hatpic
