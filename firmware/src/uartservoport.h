// ServoPort over Serial2: the STS3032 bus of the HATPIC board, RX GPIO16, TX GPIO17,
// 1 000 000 baud 8N1 (servo.md § 1; the published board's wiring). On ESP32-WROVER modules
// GPIO16/17 belong to the PSRAM: the board must carry an ESP32-WROOM (esp32dev).
//
// Owned by the control task: only it calls discardInput(), write() and read().
#pragma once

#include "firmware/ports.h"

#include <cstddef>
#include <cstdint>

class HardwareSerial;

namespace hatpic::esp32 {

class UartServoPort final : public fw::ServoPort
{
public:
    static constexpr unsigned long kBaud = 1000000;
    static constexpr int kRxPin = 16;
    static constexpr int kTxPin = 17;
    //! Idle time after which the UART hands received bytes to the driver [symbols, 10 µs each].
    //! A status packet arrives back to back, so one symbol of silence ends it.
    static constexpr std::uint8_t kRxTimeoutSymbols = 1;

    explicit UartServoPort(HardwareSerial &serial) : m_serial(serial) {}

    //! Opens the port. Call once, before any other call.
    void begin();

    void discardInput() override;
    void write(std::span<const std::uint8_t> bytes) override;
    //! Spins on the driver's buffer until `out` is full or `timeoutUs` has passed (esp_timer).
    //! A spin, not a sleep: a reply takes ~300 µs, far below the 1 ms FreeRTOS tick, and the
    //! control task owns core 1.
    std::size_t read(std::span<std::uint8_t> out, std::uint32_t timeoutUs) override;

private:
    HardwareSerial &m_serial;
};

} // namespace hatpic::esp32
