#include "simulatorhost.h"

#include <QSocketNotifier>
#include <QTimer>

#include <cerrno>
#include <termios.h>
#include <unistd.h>

namespace hatpic {

SimulatorHost::SimulatorHost(const SimulatedDevice::Config &config, QObject *parent)
    : QObject(parent), m_device(std::make_unique<SimulatedDevice>(config)),
      m_faults(makeFaultInjector(config))
{}

SimulatorHost::~SimulatorHost()
{
    stop();
}

QString SimulatorHost::start()
{
    if (isRunning())
        return {};
    if (const QString error = m_pty.open(); !error.isEmpty())
        return error;

    m_readNotifier = new QSocketNotifier(qintptr(m_pty.master()), QSocketNotifier::Read, this);
    connect(m_readNotifier, &QSocketNotifier::activated, this, [this] {
        advanceToNow();
        readHost();
        writeOutput();
    });
    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    m_timer->setInterval(kTickMs);
    connect(m_timer, &QTimer::timeout, this, [this] {
        advanceToNow();
        writeOutput();
        m_readNotifier->setEnabled(true);
    });
    m_clock.start();
    m_lastNs = 0;
    m_timer->start();
    return {};
}

void SimulatorHost::stop()
{
    delete m_readNotifier;
    m_readNotifier = nullptr;
    delete m_timer;
    m_timer = nullptr;
    m_pty.close(); // removes the link (if still ours)
    m_pending.clear();
}

void SimulatorHost::advanceToNow()
{
    const qint64 now = m_clock.nsecsElapsed();
    double dt = double(now - m_lastNs) * 1e-9;
    m_lastNs = now;
    // After a long stall (suspend, debugger) simulated time falls behind instead of running
    // thousands of cycles at once.
    if (dt > kMaxCatchUp)
        dt = kMaxCatchUp;
    if (m_faults) // host frames held back by a delay reach the device when due
        m_device->receive(m_faults->toDevice({}, seconds()));
    m_device->advance(dt);
}

void SimulatorHost::readHost()
{
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(m_pty.master(), buffer, sizeof buffer);
        if (n > 0) {
            if (m_faults)
                m_device->receive(m_faults->toDevice(QByteArrayView(buffer, n), seconds()));
            else
                m_device->receive(QByteArrayView(buffer, n));
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
            break;
        // EOF or an error such as EIO (no slave open; cannot happen while m_slave is open).
        // The master stays readable in that state, so pause the notifier until the next
        // timer tick instead of spinning; the next client is served as before.
        m_readNotifier->setEnabled(false);
        break;
    }
}

void SimulatorHost::writeOutput()
{
    QByteArray out = m_device->takeOutput();
    if (m_faults)
        out = m_faults->toHost(out, seconds());
    const qsizetype room = kMaxPendingBytes - m_pending.size();
    if (out.size() > room) {
        m_pending.append(out.left(room));
        m_discarded += quint64(out.size() - room);
    } else {
        m_pending.append(out);
    }
    while (!m_pending.isEmpty()) {
        const ssize_t n = ::write(m_pty.master(), m_pending.constData(), size_t(m_pending.size()));
        if (n > 0) {
            m_pending.remove(0, n);
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK) &&
            m_pending.size() >= kMaxPendingBytes) {
            // Nobody has read for a long while (no client, or one that stopped reading):
            // what waits in the pty is stale. Discard it and our backlog so the next reader
            // starts with fresh bytes, and memory stays bounded.
            ::tcflush(m_pty.slave(), TCIFLUSH);
            m_discarded += quint64(m_pending.size());
            m_pending.clear();
        }
        break;
    }
}

QString SimulatorHost::createLink(const QString &path)
{
    if (!isRunning())
        return QStringLiteral("Cannot create link %1: the simulator is not running.").arg(path);
    return m_pty.createLink(path);
}

} // namespace hatpic
