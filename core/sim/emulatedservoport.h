// The servo bus of the simulator: a fw::ServoPort wired straight to an EmulatedSts3032.
//
// Plain C++20, no Qt. Synchronous and in-process: the servo answers inside write(), so read()
// never waits; simulated time does not advance during a transaction (the bus takes about
// 0.2 ms per transaction on the real device, which the simulator does not model).
#pragma once

#include "firmware/ports.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace hatpic {

class EmulatedSts3032;

class EmulatedServoPort : public fw::ServoPort
{
public:
    explicit EmulatedServoPort(EmulatedSts3032 &servo);

    //! When on, every written byte is heard back before the servo's answer, as on a
    //! half-duplex adapter whose TX is tied to RX. Off by default.
    void setEcho(bool echo) { m_echo = echo; }

    void discardInput() override;
    void write(std::span<const std::uint8_t> bytes) override;
    //! Returns what is there at once: a missing answer is a timeout of zero length.
    std::size_t read(std::span<std::uint8_t> out, std::uint32_t timeoutUs) override;

private:
    EmulatedSts3032 &m_servo;
    bool m_echo = false;
    std::vector<std::uint8_t> m_echoed; //!< echo bytes not read yet
};

} // namespace hatpic
