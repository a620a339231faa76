#include "fdhostport.h"

#include <cerrno>
#include <unistd.h>

namespace hatpic {

FdHostPort::FdHostPort(int fd) : m_fd(fd)
{
    m_pending.reserve(kReplyBound);
}

std::size_t FdHostPort::read(std::span<std::uint8_t> out)
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
