// The servo bus on Linux: a fw::ServoPort over a serial device (a USB–TTL adapter such as
// Feetech's URT-1, or the pseudo-terminal of hatpic-servo-sim).
//
// Used from the control context only (hatpic-fw-host's control thread) once open() returned.
#pragma once

#include "firmware/ports.h"

#include <QString>

#include <cstddef>
#include <cstdint>
#include <span>

namespace hatpic {

class SerialServoPort : public fw::ServoPort
{
public:
    SerialServoPort() = default;
    ~SerialServoPort() override; //!< close()
    SerialServoPort(const SerialServoPort &) = delete;
    SerialServoPort &operator=(const SerialServoPort &) = delete;

    //! Opens `path` non-blocking, raw 8N1, no flow control, at `baud` [bit/s]: a standard
    //! Bxxx rate through termios, any other through termios2/BOTHER. Also asks the driver for
    //! low latency (ASYNC_LOW_LATENCY: FTDI's 16 ms latency timer drops to 1 ms), ignoring a
    //! refusal. Returns an empty string on success, else one sentence.
    QString open(const QString &path, std::uint32_t baud);
    void close();
    bool isOpen() const { return m_fd >= 0; }

    void discardInput() override;
    //! Writes all of `bytes`, waiting (poll) while the driver's buffer is full.
    void write(std::span<const std::uint8_t> bytes) override;
    //! poll()s until `out` is full or `timeoutUs` [µs] since the call has passed (CLOCK_MONOTONIC).
    std::size_t read(std::span<std::uint8_t> out, std::uint32_t timeoutUs) override;

    //! Failed write()s (short or refused) since open(); the bus then times out on the reply.
    std::uint64_t writeErrors() const { return m_writeErrors; }

private:
    int m_fd = -1;
    std::uint64_t m_writeErrors = 0;
};

} // namespace hatpic
