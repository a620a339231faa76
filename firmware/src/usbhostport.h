// HostPort over the board's USB serial (UART0 behind the USB–UART bridge) at 921600 baud.
//
// Owned by the link task: only it calls read() and write(). setup() may write LOG frames before
// that task exists. Nothing else may print on UART0 (main.cpp silences the ESP-IDF log).
#pragma once

#include "firmware/ports.h"
#include "protocol/framecodec.h"

#include <cstddef>
#include <cstdint>

class HardwareSerial;

namespace hatpic::esp32 {

class UsbHostPort final : public fw::HostPort
{
public:
    static constexpr unsigned long kBaud = 921600;
    static constexpr std::size_t kRxBufferBytes = 1024;
    //! 4 KiB ≈ 44 ms of output at 921600 baud: a busy host drains it late without a drop.
    static constexpr std::size_t kTxBufferBytes = 4096;
    //! Bytes the UART driver's ring buffer spends on each write besides the data (its item
    //! header), counted against the free space so that a checked write never blocks.
    static constexpr std::size_t kWriteOverhead = 16;
    //! Free space a Stream frame must leave for replies: two of the largest frames [bytes].
    static constexpr std::size_t kReplyReserve = 2 * (v2::kMaxWireFrameBytes + kWriteOverhead);

    explicit UsbHostPort(HardwareSerial &serial) : m_serial(serial) {}

    //! Sizes the buffers and opens the port (8N1). Call once, before any read() or write().
    void begin();

    std::size_t read(std::span<std::uint8_t> out) override;
    //! Writes the whole frame when availableForWrite() can take it (a Stream frame also needs
    //! kReplyReserve left over); otherwise writes nothing and returns false. Never blocks.
    bool write(std::span<const std::uint8_t> frame, Traffic traffic) override;

private:
    HardwareSerial &m_serial;
};

} // namespace hatpic::esp32
