#include "fdhostport.h"

#include <algorithm>
#include <cerrno>
#include <unistd.h>

namespace hatpic {

FdHostPort::FdHostPort(int fd) : m_fd(fd)
{
    m_pending.reserve(kReplyBound);
}

FdHostPort::~FdHostPort() = default;

void FdHostPort::setFaults(std::unique_ptr<FaultInjector> faults)
{
    m_faults = std::move(faults);
    m_faultStart = std::chrono::steady_clock::now();
}

double FdHostPort::seconds() const
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_faultStart).count();
}

std::size_t FdHostPort::read(std::span<std::uint8_t> out)
{
    if (!m_faults)
        return readFd(out);
    // Whole host frames go through the injector; what it passes waits in m_inbox.
    if (m_inbox.isEmpty()) {
        std::uint8_t buffer[256];
        const std::size_t n = readFd(buffer);
        m_inbox = m_faults->toDevice(
            QByteArrayView(reinterpret_cast<const char *>(buffer), qsizetype(n)), seconds());
    }
    const std::size_t n = std::min(out.size(), std::size_t(m_inbox.size()));
    std::copy_n(reinterpret_cast<const std::uint8_t *>(m_inbox.constData()), n, out.data());
    m_inbox.remove(0, qsizetype(n));
    return n;
}

std::size_t FdHostPort::readFd(std::span<std::uint8_t> out)
{
    for (;;) {
        const ssize_t n = ::read(m_fd, out.data(), out.size());
        if (n > 0)
            return std::size_t(n);
        if (n < 0 && errno == EINTR)
            continue;
        if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK))
            m_hangUp = true; // EOF/EIO: no client at the other end
        return 0;
    }
}

bool FdHostPort::write(std::span<const std::uint8_t> frame, Traffic traffic)
{
    QByteArray passed;
    if (m_faults) {
        passed = m_faults->toHost(
            QByteArrayView(reinterpret_cast<const char *>(frame.data()), qsizetype(frame.size())),
            seconds());
        frame = {reinterpret_cast<const std::uint8_t *>(passed.constData()),
                 std::size_t(passed.size())};
    }
    const std::size_t bound = traffic == Traffic::Stream ? kStreamBound : kReplyBound;
    if (m_pending.size() + frame.size() > bound) {
        flush(); // make room if the fd takes bytes again
        if (m_pending.size() + frame.size() > bound) {
            ++(traffic == Traffic::Stream ? m_streamDropped : m_replyDropped);
            return false;
        }
    }
    m_pending.insert(m_pending.end(), frame.begin(), frame.end());
    return true;
}

void FdHostPort::flush()
{
    if (m_faults) { // frames a delay held back go out when due
        const QByteArray due = m_faults->toHost({}, seconds());
        m_pending.insert(m_pending.end(), due.begin(), due.end());
    }
    std::size_t done = 0;
    while (done < m_pending.size()) {
        const ssize_t n = ::write(m_fd, m_pending.data() + done, m_pending.size() - done);
        if (n > 0) {
            done += std::size_t(n);
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        break; // EAGAIN: the pty is full (nobody reads); keep the rest for later
    }
    m_pending.erase(m_pending.begin(), m_pending.begin() + std::ptrdiff_t(done));
}

} // namespace hatpic
