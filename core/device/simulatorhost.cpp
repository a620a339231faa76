#include "simulatorhost.h"

#include <QFile>
#include <QFileInfo>
#include <QSocketNotifier>
#include <QTimer>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

namespace hatpic {

namespace {

QString errnoText(int error)
{
    return QString::fromLocal8Bit(std::strerror(error));
}

void makeRaw(int fd)
{
    termios tio{};
    if (::tcgetattr(fd, &tio) == 0) {
        ::cfmakeraw(&tio);
        ::tcsetattr(fd, TCSANOW, &tio);
    }
}

void setFlag(int fd, int getCmd, int setCmd, int flag)
{
    const int flags = ::fcntl(fd, getCmd);
    if (flags >= 0)
        ::fcntl(fd, setCmd, flags | flag);
}

} // namespace

SimulatorHost::SimulatorHost(const SimulatedDevice::Config &config, QObject *parent)
    : QObject(parent), m_device(std::make_unique<SimulatedDevice>(config))
{}

SimulatorHost::~SimulatorHost()
{
    stop();
}

QString SimulatorHost::start()
{
    if (isRunning())
        return {};
    int master = -1;
    int slave = -1;
    if (::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0)
        return QStringLiteral("Cannot open a pseudo-terminal: %1.").arg(errnoText(errno));
    char name[256] = {};
    if (::ttyname_r(slave, name, sizeof name) != 0) {
        const int error = errno;
        ::close(master);
        ::close(slave);
        return QStringLiteral("Cannot name the pseudo-terminal: %1.").arg(errnoText(error));
    }
    // Raw on both sides: the line discipline must not translate CR/LF, echo or eat bytes.
    makeRaw(master);
    makeRaw(slave);
    setFlag(master, F_GETFL, F_SETFL, O_NONBLOCK);
    setFlag(master, F_GETFD, F_SETFD, FD_CLOEXEC);
    setFlag(slave, F_GETFD, F_SETFD, FD_CLOEXEC);
    m_master = master;
    m_slave = slave;
    m_slavePath = QFile::decodeName(name);

    m_readNotifier = new QSocketNotifier(qintptr(m_master), QSocketNotifier::Read, this);
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
    removeLink();
    delete m_readNotifier;
    m_readNotifier = nullptr;
    delete m_timer;
    m_timer = nullptr;
    if (m_master >= 0)
        ::close(m_master);
    if (m_slave >= 0)
        ::close(m_slave);
    m_master = -1;
    m_slave = -1;
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
    m_device->advance(dt);
}

void SimulatorHost::readHost()
{
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(m_master, buffer, sizeof buffer);
        if (n > 0) {
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
    const QByteArray out = m_device->takeOutput();
    const qsizetype room = kMaxPendingBytes - m_pending.size();
    if (out.size() > room) {
        m_pending.append(out.left(room));
        m_discarded += quint64(out.size() - room);
    } else {
        m_pending.append(out);
    }
    while (!m_pending.isEmpty()) {
        const ssize_t n = ::write(m_master, m_pending.constData(), size_t(m_pending.size()));
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
            ::tcflush(m_slave, TCIFLUSH);
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
    const QFileInfo info(path);
    if (info.exists() && !info.isSymLink())
        return QStringLiteral("Cannot create link %1: a file that is not a symlink is in the "
                              "way.")
            .arg(path);
    // Make the link beside its final place, then rename over any old one (atomic).
    const QByteArray target = QFile::encodeName(m_slavePath);
    const QByteArray finalName = QFile::encodeName(path);
    const QByteArray temp = finalName + ".tmp" + QByteArray::number(qint64(::getpid()));
    ::unlink(temp.constData());
    if (::symlink(target.constData(), temp.constData()) != 0) {
        return QStringLiteral("Cannot create link %1: %2.").arg(path, errnoText(errno));
    }
    if (::rename(temp.constData(), finalName.constData()) != 0) {
        const int error = errno;
        ::unlink(temp.constData());
        return QStringLiteral("Cannot create link %1: %2.").arg(path, errnoText(error));
    }
    m_linkPath = path;
    return {};
}

void SimulatorHost::removeLink()
{
    if (m_linkPath.isEmpty())
        return;
    const QFileInfo info(m_linkPath);
    // Only remove the link if it still points at our slave (another simulator may own it).
    if (info.isSymLink() && info.symLinkTarget() == m_slavePath)
        QFile::remove(m_linkPath);
    m_linkPath.clear();
}

} // namespace hatpic
