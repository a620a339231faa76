// Real-time scheduling for the threads of the robot path (performance.md § The loop with the
// CPU busy): the session's I/O thread, the bridge's middleware threads (the ROS 1 callback
// thread; Cyclone DDS's receive threads through its configuration) and the simulated device's
// thread. Where the system allows it the thread runs SCHED_FIFO at a modest priority, so that
// CPU-bound processes (a build, a simulator) cannot delay it; where it does not, the thread
// stays as it was and the caller gets one sentence to print once.
#pragma once

#include <string>

namespace hatpic::realtime {

//! SCHED_FIFO priority of the robot path's threads: above every normal thread, below the
//! kernel's threaded interrupts (50) and watchdogs (99), so a runaway loop cannot starve them.
constexpr int kPriority = 20;
//! The simulated device's thread, which stands in for hardware: one above the host's threads.
constexpr int kDevicePriority = kPriority + 1;

//! Makes the calling thread SCHED_FIFO at `priority`. Empty on success, else one sentence
//! ("real-time scheduling refused (Operation not permitted): …; running at normal priority")
//! and the thread is left as it was. HATPIC_REALTIME=0 in the environment turns it off.
std::string makeThreadRealtime(int priority = kPriority);

//! Locks the process's memory (mlockall), so that no page fault on the robot path waits for the
//! disk: what is mapped now at once, what is mapped later as each page is first touched
//! (MCL_ONFAULT). So an allocation nobody fills — a hostile ROS 1 peer announcing a 900 MB
//! frame that roscpp reserves (docs/performance.md) — costs address space, not locked RAM, and
//! thread stacks cost what they use. Empty on success, else one sentence; the process goes on
//! unlocked. HATPIC_REALTIME=0 turns it off too.
std::string lockMemory();

//! Whether a thread of this process may run SCHED_FIFO at `priority`: tried on a thread of its
//! own, which ends. Empty when it may, else makeThreadRealtime()'s sentence.
std::string probeRealtime(int priority = kPriority);

//! Whether the calling thread runs SCHED_FIFO now, and at which priority (0 when not).
int threadFifoPriority();

//! The one sentence a program prints when `problem` (from the two above) is not empty, once
//! per process and per problem kind: returns true the first time for `problem`'s kind.
bool firstTimeFor(const std::string &problem);

} // namespace hatpic::realtime
