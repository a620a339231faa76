// A register-level emulation of the Feetech STS3032 on the simulated knob (servo.md § 1–2,
// docs/simulator.md § 3), speaking the bus through the firmware's own packet code.
//
// Plain C++20, no Qt. Single-threaded: the owner feeds instruction bytes with receive() and
// drains status bytes with takeOutput(); the plant is only touched from those calls.
#pragma once

#include "firmware/sts3032.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

namespace hatpic {

class ServoPlant;

//! The servo's side of the bus, bound to a ServoPlant.
//!
//! It answers every instruction addressed to its id with a status packet (error byte 0), as
//! Feetech servos do at their default response level: PING, READ, WRITE, and also REG_WRITE
//! and ACTION (Feetech's library waits for that answer too). Broadcast packets (SYNC_WRITE,
//! broadcast WRITE/REG_WRITE/ACTION) are obeyed and never answered; broadcast PING and READ
//! are ignored. Packets for other ids are ignored. A malformed instruction (wrong parameter
//! count, a range beyond address 255, an unknown instruction) is refused without an answer,
//! so the master times out.
//!
//! Registers (servo.md § 2): mode 33, torque enable 40, acceleration 41, goal position 42–43,
//! goal time 44–45 and goal speed 46–47 are stored; only the goal position and the torque
//! enable act on the plant (the emulated servo is always in position mode with the plant's
//! own loop). Present position, speed and load are sampled from the plant when a READ covers
//! them; addresses 0–4 and 56–63 are read-only (writes to them are dropped).
class EmulatedSts3032
{
public:
    //! An arbitrary plausible model number (addresses 3–4), not a verified STS3032 value:
    //! firmware only logs it.
    static constexpr std::uint16_t kDefaultModelNumber = 0x0309;

    struct Config
    {
        std::uint8_t id = 1;
        std::int32_t centerTick = fw::sts::kDefaultCenterTick; //!< tick of θ_plant = 0 [tick]
        double tauLimit = fw::sts::kDefaultTauLimit;           //!< torque at load ±1000 [N·m]
        double noise = 0;              //!< std-dev of the load reading's noise [N·m]; 0 = none
        std::uint64_t seed = 1;        //!< noise seed (std::mt19937_64)
        std::uint8_t voltage = 60;     //!< present voltage [0.1 V]
        std::uint8_t temperature = 30; //!< present temperature [°C]
        std::uint16_t modelNumber = kDefaultModelNumber;
    };

    struct Stats
    {
        std::uint64_t received = 0;   //!< valid instruction packets, any id
        std::uint64_t answered = 0;   //!< status packets sent
        std::uint64_t ignored = 0;    //!< valid packets for another id, broadcast PING/READ
        std::uint64_t refused = 0;    //!< malformed instructions for this servo (no answer)
        std::uint64_t badPackets = 0; //!< checksum or LEN errors (the parser's count)
    };

    //! The torque enable register starts as the plant's torque state and the goal as its
    //! command, so binding the emulation changes nothing in the plant.
    EmulatedSts3032(ServoPlant &plant, const Config &config);

    //! Bus bytes from the master (any chunking). Answers are queued for takeOutput().
    void receive(std::span<const std::uint8_t> bytes);
    //! Moves up to out.size() queued answer bytes into `out`; returns how many.
    std::size_t takeOutput(std::span<std::uint8_t> out);
    std::size_t pendingOutput() const { return m_output.size(); }
    void discardOutput() { m_output.clear(); }

    //! Register value as last stored or sampled (for tests and diagnostics).
    std::uint8_t reg(std::uint8_t addr) const { return m_regs[addr]; }
    const Config &config() const { return m_config; }
    Stats stats() const;

private:
    void handle(const fw::StsPacket &packet);
    void reply(std::span<const std::uint8_t> params);
    //! Stores `data` at `addr` and applies the side effects; false when out of range.
    bool apply(std::size_t addr, std::span<const std::uint8_t> data);
    //! Samples position, speed and load from the plant; draws the noise only when
    //! `drawNoise` (once per READ covering the load register).
    void sampleFeedback(bool drawNoise);
    void setWord(std::uint8_t addr, std::uint16_t value);

    ServoPlant &m_plant;
    Config m_config;
    std::array<std::uint8_t, 256> m_regs{};
    fw::StsPacketParser m_parser;
    std::vector<std::uint8_t> m_output;
    std::array<std::uint8_t, fw::sts::kMaxParams> m_registered{}; //!< REG_WRITE: addr, data…
    std::size_t m_registeredSize = 0;                             //!< 0 = nothing registered
    std::mt19937_64 m_rng;
    std::normal_distribution<double> m_normal{0.0, 1.0};
    Stats m_stats;
};

} // namespace hatpic
