#include "quitonsignal.h"

#include <QCoreApplication>
#include <QSocketNotifier>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <ctime>
#include <fcntl.h>
#include <iterator>
#include <memory>
#include <unistd.h>

namespace hatpic {

namespace {

constexpr int kFatalWaitMs = 2000; //!< longest wait for another thread's emergency action [ms]

int g_signalPipe[2] = {-1, -1};
int g_reportPipe[2] = {-1, -1};
int g_interruptPipe[2] = {-1, -1}; //!< made once, kept: a late signal still has somewhere to go
int g_quitSignal = 0;              //!< main thread only

std::atomic<void (*)()> g_fatalAction{nullptr};
std::atomic<int> g_fatalState{0}; //!< 0 none yet, 1 an action runs, 2 it ran
alignas(16) char g_alternateStack[64 * 1024];

void wake(int fd, int signal)
{
    const int saved = errno;
    const auto byte = static_cast<unsigned char>(signal);
    [[maybe_unused]] const ssize_t n = ::write(fd, &byte, 1);
    errno = saved;
}

void onSignal(int signal)
{
    wake(g_signalPipe[1], signal);
}

void onReport(int signal)
{
    wake(g_reportPipe[1], signal);
}

void onInterrupt(int signal)
{
    wake(g_interruptPipe[1], signal);
}

void onFatal(int signal)
{
    int idle = 0;
    if (g_fatalState.compare_exchange_strong(idle, 1)) {
        if (void (*action)() = g_fatalAction.load())
            action();
        g_fatalState.store(2);
    } else {
        // Another thread runs the action: let it finish before this signal ends the process.
        const timespec step{0, 1000000};
        for (int i = 0; i < kFatalWaitMs && g_fatalState.load() == 1; ++i)
            ::nanosleep(&step, nullptr);
    }
    // SA_RESETHAND restored the default action: raised again, the signal ends the process as
    // soon as this handler returns (a fault's instruction would raise it again as well).
    ::raise(signal);
}

// A notifier on the read end of `fds`, owned by `owner`, that drains it and calls `then` with
// the first byte.
QSocketNotifier *watchPipe(const int (&fds)[2], std::function<void(int)> then,
                           QObject *owner = QCoreApplication::instance())
{
    auto *notifier = new QSocketNotifier(qintptr(fds[0]), QSocketNotifier::Read, owner);
    QObject::connect(notifier, &QSocketNotifier::activated, notifier,
                     [fd = fds[0], then = std::move(then)] {
                         unsigned char bytes[16];
                         int first = 0;
                         for (ssize_t n; (n = ::read(fd, bytes, sizeof bytes)) > 0;) {
                             if (first == 0)
                                 first = bytes[0];
                         }
                         then(first);
                     });
    return notifier;
}

void handle(int signal, void (*handler)(int), int flags = SA_RESTART,
            struct sigaction *previous = nullptr)
{
    struct sigaction action = {};
    action.sa_handler = handler;
    sigemptyset(&action.sa_mask);
    action.sa_flags = flags;
    ::sigaction(signal, &action, previous);
}

constexpr int kInterrupts[] = {SIGINT, SIGTERM, SIGHUP};

void ignore(int signal)
{
    struct sigaction action = {};
    action.sa_handler = SIG_IGN;
    sigemptyset(&action.sa_mask);
    ::sigaction(signal, &action, nullptr);
}

} // namespace

bool quitOnSignals()
{
    if (::pipe2(g_signalPipe, O_CLOEXEC | O_NONBLOCK) != 0)
        return false;
    watchPipe(g_signalPipe, [](int signal) {
        if (g_quitSignal == 0)
            g_quitSignal = signal;
        QCoreApplication::quit();
    });
    for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGXCPU,
                             SIGVTALRM, SIGPROF, SIGIO, SIGPWR, SIGSTKFLT})
        handle(signal, onSignal);
    for (int signal = SIGRTMIN; signal <= SIGRTMAX; ++signal)
        handle(signal, onSignal);
    ignore(SIGPIPE);
    ignore(SIGXFSZ);

    // The main thread's alternate stack, so that a stack overflow still runs the action.
    stack_t stack = {};
    stack.ss_sp = g_alternateStack;
    stack.ss_size = sizeof g_alternateStack;
    ::sigaltstack(&stack, nullptr);
    for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGSYS, SIGTRAP})
        handle(signal, onFatal, SA_RESETHAND | SA_ONSTACK);
    return true;
}

int quitSignal()
{
    return g_quitSignal;
}

void onFatalSignal(void (*action)())
{
    g_fatalAction.store(action);
}

bool reportOnSignal(std::function<void()> report)
{
    if (::pipe2(g_reportPipe, O_CLOEXEC | O_NONBLOCK) != 0)
        return false;
    watchPipe(g_reportPipe, [report = std::move(report)](int) { report(); });
    handle(SIGUSR1, onReport);
    return true;
}

struct InterruptsCall::Installed
{
    std::unique_ptr<QSocketNotifier> notifier;
    struct sigaction previous[std::size(kInterrupts)] = {};
};

InterruptsCall::InterruptsCall(std::function<void()> then)
{
    if (g_interruptPipe[0] < 0 && ::pipe2(g_interruptPipe, O_CLOEXEC | O_NONBLOCK) != 0)
        return;
    m_installed = std::make_unique<Installed>();
    m_installed->notifier.reset(watchPipe(
        g_interruptPipe, [then = std::move(then)](int) { then(); }, nullptr));
    for (std::size_t i = 0; i < std::size(kInterrupts); ++i)
        handle(kInterrupts[i], onInterrupt, SA_RESTART, &m_installed->previous[i]);
}

InterruptsCall::~InterruptsCall()
{
    if (!m_installed)
        return;
    for (std::size_t i = 0; i < std::size(kInterrupts); ++i)
        ::sigaction(kInterrupts[i], &m_installed->previous[i], nullptr);
    // What arrived meanwhile belonged to this run: the next one starts clean.
    unsigned char bytes[16];
    while (::read(g_interruptPipe[0], bytes, sizeof bytes) > 0) {
    }
}

} // namespace hatpic
