#include "usbhostport.h"

#include <Arduino.h>
#include <HardwareSerial.h>
#include <driver/uart.h>

#include <algorithm>

namespace hatpic::esp32 {

namespace {

constexpr uart_port_t kPort = UART_NUM_0; //!< Serial (Serial0) on the ESP32

} // namespace

void UsbHostPort::begin()
{
    // Buffer sizes must be set before begin() (Arduino-ESP32 3.x). A TX buffer of 0 keeps the
    // IDF driver's TX ring off: only flush() puts bytes into the FIFO.
    m_serial.setRxBufferSize(kRxBufferBytes);
    m_serial.setTxBufferSize(0);
    m_serial.begin(kBaud, SERIAL_8N1);
}

std::size_t UsbHostPort::read(std::span<std::uint8_t> out)
{
    const int available = m_serial.available();
    if (available <= 0 || out.empty())
        return 0;
    const std::size_t count = std::min(out.size(), static_cast<std::size_t>(available));
    return m_serial.read(out.data(), count); // no wait: `count` bytes are buffered
}

bool UsbHostPort::write(std::span<const std::uint8_t> frame, Traffic traffic)
{
    flush(); // room first
    if (!m_queue.push(frame, traffic))
        return false;
    flush();
    return true;
}

void UsbHostPort::flush()
{
    for (;;) {
        const std::span<const std::uint8_t> bytes = m_queue.front();
        if (bytes.empty())
            return;
        // Copies what the hardware FIFO has room for and returns; -1 only for a bad port.
        const int sent = uart_tx_chars(kPort, reinterpret_cast<const char *>(bytes.data()),
                                       static_cast<std::uint32_t>(bytes.size()));
        if (sent <= 0)
            return;
        m_queue.pop(static_cast<std::size_t>(sent));
    }
}

void UsbHostPort::drain(std::uint32_t timeoutMs)
{
    const std::uint32_t start = millis();
    flush();
    while (m_queue.size() > 0 && millis() - start < timeoutMs) {
        delay(1);
        flush();
    }
}

} // namespace hatpic::esp32
