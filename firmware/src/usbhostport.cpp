#include "usbhostport.h"

#include <HardwareSerial.h>

#include <algorithm>

namespace hatpic::esp32 {

void UsbHostPort::begin()
{
    // Buffer sizes must be set before begin() (Arduino-ESP32 3.x).
    m_serial.setRxBufferSize(kRxBufferBytes);
    m_serial.setTxBufferSize(kTxBufferBytes);
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
    const std::size_t reserve = traffic == Traffic::Stream ? kReplyReserve : 0;
    const std::size_t free = static_cast<std::size_t>(std::max(0, m_serial.availableForWrite()));
    if (free < frame.size() + kWriteOverhead + reserve)
        return false;
    // Fits whole: the single writer (the link task) cannot be overtaken between check and write.
    return m_serial.write(frame.data(), frame.size()) == frame.size();
}

} // namespace hatpic::esp32
