// SIGINT/SIGTERM → QCoreApplication::quit(), for the programs that run until stopped
// (hatpic-sim, hatpic-fw-host, hatpic-servo-sim).
#pragma once

#include <functional>

namespace hatpic {

//! Installs async-signal-safe handlers for SIGINT and SIGTERM that only write a byte to a
//! self-pipe; a QSocketNotifier on the pipe quits the application's event loop. SIGPIPE is
//! ignored. Call once, after the QCoreApplication exists. False when the pipe cannot be made.
bool quitOnSignals();

//! Runs `report` on the event loop each time SIGUSR1 arrives (hatpic-sim's fault summary).
//! Same self-pipe technique; call once, after the QCoreApplication exists.
bool reportOnSignal(std::function<void()> report);

} // namespace hatpic
