#include "realtime.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <set>
#include <thread>

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>

namespace hatpic::realtime {

namespace {

bool turnedOff()
{
    const char *value = std::getenv("HATPIC_REALTIME");
    return value && std::string(value) == "0";
}

std::string refused(const char *what, int error, const std::string &remedy)
{
    return std::string(what) + " refused (" + std::strerror(error) + "): " + remedy;
}

} // namespace

std::string makeThreadRealtime(int priority)
{
    if (turnedOff())
        return "real-time scheduling turned off (HATPIC_REALTIME=0); running at normal priority";
    sched_param param{};
    param.sched_priority = priority;
    const int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
    if (error != 0)
        return refused("real-time scheduling", error,
                       "allow it with CAP_SYS_NICE or an rtprio limit of at least " +
                           std::to_string(priority) +
                           " (/etc/security/limits.conf); running at normal priority");
    return {};
}

std::string lockMemory()
{
    if (turnedOff())
        return "memory locking turned off (HATPIC_REALTIME=0)";
    const std::string remedy =
        "allow it with CAP_IPC_LOCK or a memlock limit (ulimit -l); running unlocked";
    if (mlockall(MCL_CURRENT) != 0)
        return refused("locking memory", errno, remedy);
    // The future on fault only; this call leaves the pages locked above as they are.
    if (mlockall(MCL_FUTURE | MCL_ONFAULT) != 0) {
        const int error = errno;
        munlockall();
        return refused("locking memory", error, remedy);
    }
    return {};
}

std::string probeRealtime(int priority)
{
    std::string problem;
    std::thread([&] { problem = makeThreadRealtime(priority); }).join();
    return problem;
}

int threadFifoPriority()
{
    int policy = 0;
    sched_param param{};
    if (pthread_getschedparam(pthread_self(), &policy, &param) != 0 || policy != SCHED_FIFO)
        return 0;
    return param.sched_priority;
}

bool firstTimeFor(const std::string &problem)
{
    static std::mutex mutex;
    static std::set<std::string> said;
    const std::lock_guard lock(mutex);
    return said.insert(problem.substr(0, problem.find(' '))).second;
}

} // namespace hatpic::realtime
