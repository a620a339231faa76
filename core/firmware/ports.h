// The device core's seams to hardware: everything the firmware's logic needs from the board
// enters through these small interfaces, so the same files run on the ESP32, on Linux
// (hatpic-fw-host) and inside the simulator.
//
// Plain C++20: no Qt, no OS calls, no exceptions, no RTTI, no allocation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace hatpic::fw {

//! The byte link to the host (USB serial on the ESP32, a pseudo-terminal on Linux, the
//! emulated UART in the simulator). Used from the link context only.
class HostPort
{
public:
    //! What a frame is for: a stream frame (TELEMETRY) is dropped when the transmit buffer
    //! cannot take it whole; a reply may use a reserve that streams leave free.
    enum class Traffic { Stream, Reply };

    virtual ~HostPort() = default;
    //! Copies up to out.size() received bytes into `out` without waiting; returns how many.
    virtual std::size_t read(std::span<std::uint8_t> out) = 0;
    //! Queues one whole frame without waiting. False (and nothing queued) when it does not fit.
    virtual bool write(std::span<const std::uint8_t> frame, Traffic traffic) = 0;
};

//! The half-duplex servo bus (UART at 1 Mbaud on the ESP32, a USB–TTL adapter on Linux, the
//! emulated STS3032 in the simulator). Used from the control context only.
class ServoPort
{
public:
    virtual ~ServoPort() = default;
    //! Forgets bytes received but not read yet (stale replies, line noise).
    virtual void discardInput() = 0;
    //! Sends `bytes` on the bus (returns once they are queued for transmission).
    virtual void write(std::span<const std::uint8_t> bytes) = 0;
    //! Reads into `out` until it is full or `timeoutUs` has passed since the call; returns
    //! the number of bytes read (fewer than out.size() means a timeout).
    virtual std::size_t read(std::span<std::uint8_t> out, std::uint32_t timeoutUs) = 0;
};

//! A free-running microsecond clock that wraps at 2³² (esp_timer, CLOCK_MONOTONIC, or the
//! simulator's simulated time).
class Clock
{
public:
    virtual ~Clock() = default;
    virtual std::uint32_t micros() = 0;
};

} // namespace hatpic::fw
