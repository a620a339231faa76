#include "serialservoport.h"

#include <QFile>

#include <asm/termbits.h> // termios2, BOTHER (glibc's <termios.h> cannot be included with it)
#include <cerrno>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <linux/serial.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

namespace hatpic {

namespace {

QString errnoText(int error)
{
    return QString::fromLocal8Bit(std::strerror(error));
}

std::int64_t monotonicUs()
{
    timespec ts{};
    ::clock_gettime(CLOCK_MONOTONIC, &ts);
    return std::int64_t(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

//! The Bxxx constant of a standard rate, 0 when there is none.
speed_t standardRate(std::uint32_t baud)
{
    switch (baud) {
    case 9600:
        return B9600;
    case 19200:
        return B19200;
    case 38400:
        return B38400;
    case 57600:
        return B57600;
    case 115200:
        return B115200;
    case 230400:
        return B230400;
    case 460800:
        return B460800;
    case 500000:
        return B500000;
    case 576000:
        return B576000;
    case 921600:
        return B921600;
    case 1000000:
        return B1000000;
    case 1152000:
        return B1152000;
    case 1500000:
        return B1500000;
    case 2000000:
        return B2000000;
    case 2500000:
        return B2500000;
    case 3000000:
        return B3000000;
    default:
        return 0;
    }
}

//! Raw 8N1, receiver on, modem lines ignored, no flow control, at `baud`. termios2 carries
//! both the standard Bxxx form and BOTHER with the rate in c_ispeed/c_ospeed.
bool configure(int fd, std::uint32_t baud)
{
    termios2 tio{};
    if (::ioctl(fd, TCGETS2, &tio) != 0)
        return false;
    tio.c_iflag &= ~tcflag_t(IGNBRK | BRKINT | PARMRK | ISTRIP | INLCR | IGNCR | ICRNL | IXON |
                             IXOFF | IXANY | INPCK);
    tio.c_oflag &= ~tcflag_t(OPOST);
    tio.c_lflag &= ~tcflag_t(ECHO | ECHONL | ICANON | ISIG | IEXTEN);
    tio.c_cflag &= ~tcflag_t(CSIZE | PARENB | CSTOPB | CRTSCTS | CBAUD | (CBAUD << IBSHIFT));
    tio.c_cflag |= CS8 | CREAD | CLOCAL;
    tio.c_cc[VMIN] = 0;
    tio.c_cc[VTIME] = 0;
    const speed_t standard = standardRate(baud);
    if (standard != 0) {
        tio.c_cflag |= standard;
        tio.c_ispeed = baud;
        tio.c_ospeed = baud;
    } else {
        tio.c_cflag |= BOTHER;
        tio.c_ispeed = baud;
        tio.c_ospeed = baud;
    }
    return ::ioctl(fd, TCSETS2, &tio) == 0;
}

} // namespace

SerialServoPort::~SerialServoPort()
{
    close();
}

QString SerialServoPort::open(const QString &path, std::uint32_t baud)
{
    close();
    const QByteArray name = QFile::encodeName(path);
    const int fd = ::open(name.constData(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return QStringLiteral("Cannot open the servo port %1: %2.").arg(path, errnoText(errno));
    if (!configure(fd, baud)) {
        const int error = errno;
        ::close(fd);
        return QStringLiteral("Cannot set %1 to %2 baud, 8N1: %3.")
            .arg(path)
            .arg(baud)
            .arg(errnoText(error));
    }
    serial_struct serial{};
    if (::ioctl(fd, TIOCGSERIAL, &serial) == 0) {
        serial.flags |= ASYNC_LOW_LATENCY;
        ::ioctl(fd, TIOCSSERIAL, &serial); // not every driver allows it; fine either way
    }
    ::ioctl(fd, TCFLSH, TCIOFLUSH);
    m_fd = fd;
    m_writeErrors = 0;
    return {};
}

void SerialServoPort::close()
{
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = -1;
}

void SerialServoPort::discardInput()
{
    if (m_fd < 0)
        return;
    ::ioctl(m_fd, TCFLSH, TCIFLUSH);
    // What arrived between the flush and now (a USB frame in flight) is drained too.
    std::uint8_t sink[64];
    while (::read(m_fd, sink, sizeof sink) > 0) {
    }
}

void SerialServoPort::write(std::span<const std::uint8_t> bytes)
{
    if (m_fd < 0)
        return;
    constexpr int kWriteTimeoutMs = 10; // a bus packet is ≤ 0.3 ms at 1 Mbaud
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(m_fd, bytes.data() + done, bytes.size() - done);
        if (n > 0) {
            done += std::size_t(n);
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        pollfd p{m_fd, POLLOUT, 0};
        if (n < 0 && errno == EAGAIN && ::poll(&p, 1, kWriteTimeoutMs) > 0)
            continue;
        ++m_writeErrors;
        return;
    }
}

std::size_t SerialServoPort::read(std::span<std::uint8_t> out, std::uint32_t timeoutUs)
{
    if (m_fd < 0)
        return 0;
    const std::int64_t deadline = monotonicUs() + timeoutUs;
    std::size_t done = 0;
    while (done < out.size()) {
        const ssize_t n = ::read(m_fd, out.data() + done, out.size() - done);
        if (n > 0) {
            done += std::size_t(n);
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        // With VMIN = VTIME = 0 "nothing yet" reads 0 bytes (not EAGAIN); a hang-up shows in
        // poll's revents below.
        if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK)
            break; // a real error: the bus reports a short reply or a timeout
        const std::int64_t left = deadline - monotonicUs();
        if (left <= 0)
            break;
        // ppoll keeps the µs resolution that poll()'s milliseconds would lose.
        const timespec wait{time_t(left / 1000000), long(left % 1000000) * 1000};
        pollfd p{m_fd, POLLIN, 0};
        const int ready = ::ppoll(&p, 1, &wait, nullptr);
        if (ready < 0 && errno != EINTR)
            break;
        if (ready > 0 && (p.revents & (POLLERR | POLLHUP | POLLNVAL)))
            break;
    }
    return done;
}

} // namespace hatpic
