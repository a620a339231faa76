#include "quitonsignal.h"

#include <QCoreApplication>
#include <QSocketNotifier>

#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <unistd.h>

namespace hatpic {

namespace {

int g_signalPipe[2] = {-1, -1};
int g_reportPipe[2] = {-1, -1};

void wake(int fd)
{
    const int saved = errno;
    const char byte = 1;
    [[maybe_unused]] const ssize_t n = ::write(fd, &byte, 1);
    errno = saved;
}

void onSignal(int)
{
    wake(g_signalPipe[1]);
}

void onReport(int)
{
    wake(g_reportPipe[1]);
}

// A notifier on the read end of `fds` that drains it and calls `then`.
void watchPipe(const int (&fds)[2], std::function<void()> then)
{
    auto *notifier =
        new QSocketNotifier(qintptr(fds[0]), QSocketNotifier::Read, QCoreApplication::instance());
    QObject::connect(notifier, &QSocketNotifier::activated, notifier,
                     [fd = fds[0], then = std::move(then)] {
                         char bytes[16];
                         while (::read(fd, bytes, sizeof bytes) > 0) {
                         }
                         then();
                     });
}

void handle(int signal, void (*handler)(int))
{
    struct sigaction action = {};
    action.sa_handler = handler;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    ::sigaction(signal, &action, nullptr);
}

} // namespace

bool quitOnSignals()
{
    if (::pipe2(g_signalPipe, O_CLOEXEC | O_NONBLOCK) != 0)
        return false;
    watchPipe(g_signalPipe, [] { QCoreApplication::quit(); });
    handle(SIGINT, onSignal);
    handle(SIGTERM, onSignal);
    std::signal(SIGPIPE, SIG_IGN);
    return true;
}

bool reportOnSignal(std::function<void()> report)
{
    if (::pipe2(g_reportPipe, O_CLOEXEC | O_NONBLOCK) != 0)
        return false;
    watchPipe(g_reportPipe, std::move(report));
    handle(SIGUSR1, onReport);
    return true;
}

} // namespace hatpic
