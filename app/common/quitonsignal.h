// Signals for the programs that run until stopped (hatpic-sim, hatpic-fw-host,
// hatpic-servo-sim): every signal that would end the program ends it in order, through the
// event loop, or — when it cannot wait for the loop — after an async-signal-safe emergency
// action (the knob left without force, the --link symlink removed). And an interrupt that a
// program's run turns into an orderly end of that run (InterruptsCall).
#pragma once

#include <functional>
#include <memory>

namespace hatpic {

//! Installs async-signal-safe handlers for every signal whose default action ends the process
//! and that can wait for the event loop — SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2,
//! SIGALRM, SIGXCPU, SIGVTALRM, SIGPROF, SIGIO, SIGPWR, SIGSTKFLT and the real-time signals:
//! each only writes its number to a self-pipe, and a QSocketNotifier on the pipe quits the
//! application's event loop. SIGPIPE and SIGXFSZ are ignored: a write to a closed pipe or past
//! the file-size limit (ulimit -f) fails with EPIPE or EFBIG instead of killing the program.
//! Also installs the fatal-signal handlers of onFatalSignal(). Call once, after the
//! QCoreApplication exists. False when the pipe cannot be made.
bool quitOnSignals();

//! The signal that quit the event loop; 0 while none has.
int quitSignal();

//! Runs `action` when a signal arrives that cannot wait for the event loop — SIGSEGV, SIGBUS,
//! SIGFPE, SIGILL, SIGABRT, SIGSYS, SIGTRAP — whether a fault of this process raised it or it
//! was sent; then the signal takes its default action (the process ends as it would have). The
//! action runs once, on the main thread's alternate stack when the main thread faults (a stack
//! overflow too). It must be async-signal-safe: write(), unlink(), nanosleep(), atomics, no
//! allocation, no lock. nullptr withdraws the action.
void onFatalSignal(void (*action)());

//! Runs `report` on the event loop each time SIGUSR1 arrives (hatpic-sim's fault summary).
//! Same self-pipe technique; call once, after quitOnSignals().
bool reportOnSignal(std::function<void()> report);

//! While it lives, SIGINT, SIGTERM and SIGHUP do not end the program: each calls `then` on the
//! event loop, at once (the handlers only write to a self-pipe, which a QSocketNotifier
//! watches). The handlers that were in place come back when it goes. One at a time; after the
//! QCoreApplication exists. hatpicctl's `stream` and `experiment` end their run this way.
class InterruptsCall
{
public:
    explicit InterruptsCall(std::function<void()> then);
    ~InterruptsCall();
    InterruptsCall(const InterruptsCall &) = delete;
    InterruptsCall &operator=(const InterruptsCall &) = delete;

private:
    struct Installed;
    std::unique_ptr<Installed> m_installed; //!< null when the pipe could not be made
};

} // namespace hatpic
