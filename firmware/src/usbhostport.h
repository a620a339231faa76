// HostPort over the board's USB serial (UART0 behind the USB–UART bridge) at 921600 baud.
//
// Reads go through Arduino's HardwareSerial. Writes do not: Arduino-ESP32 3.x answers
// availableForWrite() with ESP-IDF's uart_get_tx_buffer_free_size(), which subtracts only the
// item the driver's interrupt is sending, not what waits in its TX ring buffer, and a write
// the ring cannot take blocks in xRingbufferSend(…, portMAX_DELAY). So the driver runs without a
// TX ring (setTxBufferSize(0)), frames wait in our own TxQueue, whose fill is exact, and
// flush() moves them into the UART's 128-byte hardware FIFO with uart_tx_chars(), which copies
// what the FIFO takes and returns at once. Nothing here waits for the wire.
//
// Owned by the link task: only it calls read(), write() and flush(). setup() may write LOG
// frames (and drain()) before that task exists. Nothing else may print on UART0 (main.cpp
// silences the ESP-IDF log).
#pragma once

#include "txqueue.h"

#include "firmware/ports.h"

#include <cstddef>
#include <cstdint>

class HardwareSerial;

namespace hatpic::esp32 {

class UsbHostPort final : public fw::HostPort
{
public:
    static constexpr unsigned long kBaud = 921600;
    static constexpr std::size_t kRxBufferBytes = 1024;

    explicit UsbHostPort(HardwareSerial &serial) : m_serial(serial) {}

    //! Sizes the receive buffer, turns the driver's TX ring off and opens the port (8N1). Call
    //! once, before any other call.
    void begin();

    std::size_t read(std::span<std::uint8_t> out) override;
    //! Queues the whole frame when the TxQueue takes it (a Stream frame also leaves the reply
    //! reserve free), then flush(); otherwise queues nothing and returns false. Never waits.
    bool write(std::span<const std::uint8_t> frame, Traffic traffic) override;
    //! Moves queued bytes into the UART's FIFO, as many as it has room for now. Never waits;
    //! the link task calls it every turn, so the queue drains at the line rate.
    void flush();
    //! flush() until the queue is empty or `timeoutMs` has passed (setup() only: it may wait).
    void drain(std::uint32_t timeoutMs);

private:
    HardwareSerial &m_serial;
    TxQueue m_queue;
};

} // namespace hatpic::esp32
