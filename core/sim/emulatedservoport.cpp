#include "emulatedservoport.h"

#include "sim/emulatedsts3032.h"

#include <algorithm>

namespace hatpic {

EmulatedServoPort::EmulatedServoPort(EmulatedSts3032 &servo) : m_servo(servo) {}

void EmulatedServoPort::discardInput()
{
    m_echoed.clear();
    m_servo.discardOutput();
}

void EmulatedServoPort::write(std::span<const std::uint8_t> bytes)
{
    if (m_echo)
        m_echoed.insert(m_echoed.end(), bytes.begin(), bytes.end());
    m_servo.receive(bytes);
}

std::size_t EmulatedServoPort::read(std::span<std::uint8_t> out, std::uint32_t /*timeoutUs*/)
{
    const std::size_t fromEcho = std::min(out.size(), m_echoed.size());
    std::copy_n(m_echoed.begin(), fromEcho, out.begin());
    m_echoed.erase(m_echoed.begin(), m_echoed.begin() + static_cast<std::ptrdiff_t>(fromEcho));
    return fromEcho + m_servo.takeOutput(out.subspan(fromEcho));
}

} // namespace hatpic
