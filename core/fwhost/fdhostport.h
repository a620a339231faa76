// The host link of hatpic-fw-host: a fw::HostPort over a non-blocking file descriptor (the
// master of a pseudo-terminal).
//
// Used from the link context only (the main thread): DeviceCore::serviceHost() calls read() and
// write(), the owner calls flush() afterwards and whenever the fd becomes writable.
#pragma once

#include "firmware/ports.h"
#include "link/faultinjector.h"

#include <QByteArray>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace hatpic {

class FdHostPort : public fw::HostPort
{
public:
    //! Output kept when the fd does not take it: a stream frame is dropped when the backlog
    //! would exceed kStreamBound, a reply when it would exceed kReplyBound [bytes]. The gap
    //! keeps room for replies while a client that stopped reading is flooded with telemetry.
    static constexpr std::size_t kStreamBound = 4 * 1024;
    static constexpr std::size_t kReplyBound = 64 * 1024;

    //! `fd` stays the caller's (not closed here); it must be non-blocking.
    explicit FdHostPort(int fd);
    ~FdHostPort() override;

    //! Passes both directions through `faults` from now on (hatpic-fw-host --faults); the
    //! injector's clock starts here.
    void setFaults(std::unique_ptr<FaultInjector> faults);
    const FaultInjector *faults() const { return m_faults.get(); }

    std::size_t read(std::span<std::uint8_t> out) override;
    bool write(std::span<const std::uint8_t> frame, Traffic traffic) override;
    //! Writes as much of the backlog as the fd takes now.
    void flush();

    //! Whether a read() saw end-of-file or an error other than "nothing yet" since the last
    //! call (the fd then polls readable without data: the owner pauses its notifier).
    bool takeHangUp() { return std::exchange(m_hangUp, false); }

    std::size_t pendingBytes() const { return m_pending.size(); }
    std::uint64_t streamDropped() const { return m_streamDropped; } //!< frames
    std::uint64_t replyDropped() const { return m_replyDropped; }   //!< frames

private:
    std::size_t readFd(std::span<std::uint8_t> out);
    double seconds() const;

    int m_fd;
    std::unique_ptr<FaultInjector> m_faults;
    std::chrono::steady_clock::time_point m_faultStart;
    QByteArray m_inbox; //!< host bytes the injector passed on, not read by the core yet
    std::vector<std::uint8_t> m_pending;
    std::uint64_t m_streamDropped = 0;
    std::uint64_t m_replyDropped = 0;
    bool m_hangUp = false;
};

} // namespace hatpic
