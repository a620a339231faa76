// The host link's transmit queue on the ESP32 (UsbHostPort): whole frames in, bytes out to the
// UART's hardware FIFO as fast as it takes them. The queue knows exactly how full it is, so
// "does this frame fit?" has a true answer and a write never waits: TELEMETRY that does not fit
// is dropped (a seq gap on the host), a reply that does not fit stays unanswered (the host
// retries it).
//
// Portable C++20 (no Arduino, no allocation): scripts/check-firmware compiles it with the device
// core, tests/firmware/tst_txqueue runs it on the host. Owned by the link task.
#pragma once

#include "firmware/ports.h"
#include "protocol/framecodec.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace hatpic::esp32 {

class TxQueue
{
public:
    //! 4 KiB ≈ 44 ms of output at 921600 baud: a busy host drains it late without a drop.
    static constexpr std::size_t kCapacity = 4096;
    //! Free space a Stream frame must leave for replies: two of the largest frames [bytes].
    static constexpr std::size_t kReplyReserve = 2 * v2::kMaxWireFrameBytes;

    //! Appends the whole frame when it fits, a Stream frame only when kReplyReserve stays free
    //! after it; otherwise appends nothing and returns false.
    bool push(std::span<const std::uint8_t> frame, fw::HostPort::Traffic traffic);
    //! The oldest bytes waiting, contiguous (up to the end of the ring); empty when none wait.
    std::span<const std::uint8_t> front() const;
    //! Forgets the first `count` bytes of front(), which went out.
    void pop(std::size_t count);

    std::size_t size() const { return m_size; }             //!< bytes waiting
    std::size_t room() const { return kCapacity - m_size; } //!< bytes that still fit

private:
    std::array<std::uint8_t, kCapacity> m_bytes{};
    std::size_t m_start = 0; //!< index of the oldest byte
    std::size_t m_size = 0;
};

} // namespace hatpic::esp32
