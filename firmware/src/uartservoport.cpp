#include "uartservoport.h"

#include <HardwareSerial.h>
#include <esp_timer.h>

#include <algorithm>
#include <array>

namespace hatpic::esp32 {

namespace {

std::uint32_t nowUs()
{
    return static_cast<std::uint32_t>(esp_timer_get_time());
}

} // namespace

void UartServoPort::begin()
{
    m_serial.begin(kBaud, SERIAL_8N1, kRxPin, kTxPin);
    m_serial.setRxTimeout(kRxTimeoutSymbols);
}

void UartServoPort::discardInput()
{
    std::array<std::uint8_t, 32> junk;
    for (int available = m_serial.available(); available > 0; available = m_serial.available())
        m_serial.read(junk.data(), std::min(junk.size(), static_cast<std::size_t>(available)));
}

void UartServoPort::write(std::span<const std::uint8_t> bytes)
{
    m_serial.write(bytes.data(), bytes.size());
}

std::size_t UartServoPort::read(std::span<std::uint8_t> out, std::uint32_t timeoutUs)
{
    const std::uint32_t start = nowUs();
    std::size_t got = 0;
    while (got < out.size()) {
        const int available = m_serial.available();
        if (available > 0) {
            const std::size_t want =
                std::min(out.size() - got, static_cast<std::size_t>(available));
            got += m_serial.read(out.data() + got, want);
        }
        if (got < out.size() && nowUs() - start >= timeoutUs)
            break;
    }
    return got;
}

} // namespace hatpic::esp32
