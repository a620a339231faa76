// The Feetech STS3032 bus (servo.md § 1–3): packet layout, register map, number formats and
// the conversions to SI. Shared by the master (StsBus) and the emulated servo, so the wire
// rules exist once.
//
// Plain C++20: no Qt, no OS calls, no exceptions, no RTTI, no allocation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace hatpic::fw {

namespace sts {

// ---- packets (servo.md § 1) ----
inline constexpr std::uint8_t kHeaderByte = 0xFF;  //!< a packet starts with two of these
inline constexpr std::uint8_t kBroadcastId = 0xFE; //!< every servo obeys, none answers
inline constexpr std::uint8_t kMaxId = 0xFD;       //!< highest single-servo id

inline constexpr std::uint8_t kPing = 0x01;
inline constexpr std::uint8_t kRead = 0x02;     //!< params: addr, count
inline constexpr std::uint8_t kWrite = 0x03;    //!< params: addr, data…
inline constexpr std::uint8_t kRegWrite = 0x04; //!< params: addr, data… (applied on ACTION)
inline constexpr std::uint8_t kAction = 0x05;
inline constexpr std::uint8_t kSyncWrite = 0x83; //!< params: addr, n, (id, n data bytes)…

//! Largest parameter count this project sends or accepts. The wire allows 253 (LEN is a byte);
//! 128 covers the whole register file and keeps the parser's buffer small.
inline constexpr std::size_t kMaxParams = 128;
//! FF FF ID LEN CODE + params + CHK.
inline constexpr std::size_t kPacketOverhead = 6;
inline constexpr std::size_t kMaxPacketBytes = kMaxParams + kPacketOverhead;

// ---- registers (servo.md § 2); 16-bit words are little-endian ----
inline constexpr std::uint8_t kRegModelNumber = 3; //!< 2 bytes, read-only
inline constexpr std::uint8_t kRegMode = 33;       //!< 0 = position mode
inline constexpr std::uint8_t kRegTorqueEnable = 40;
inline constexpr std::uint8_t kRegAcceleration = 41;
inline constexpr std::uint8_t kRegGoalPosition = 42;       //!< 2 bytes, sign bit 15 [tick]
inline constexpr std::uint8_t kRegGoalTime = 44;           //!< 2 bytes
inline constexpr std::uint8_t kRegGoalSpeed = 46;          //!< 2 bytes, 0 = servo maximum
inline constexpr std::uint8_t kRegPresentPosition = 56;    //!< 2 bytes, sign bit 15 [tick]
inline constexpr std::uint8_t kRegPresentSpeed = 58;       //!< 2 bytes, sign bit 15 [tick/s]
inline constexpr std::uint8_t kRegPresentLoad = 60;        //!< 2 bytes, sign bit 10 [0.1 %]
inline constexpr std::uint8_t kRegPresentVoltage = 62;     //!< 1 byte [0.1 V]
inline constexpr std::uint8_t kRegPresentTemperature = 63; //!< 1 byte [°C]
//! One READ of this many bytes at kRegPresentPosition gives position, speed and load.
inline constexpr std::uint8_t kFeedbackBytes = 6;

inline constexpr std::uint8_t kModePosition = 0;

inline constexpr unsigned kPositionSignBit = 15;
inline constexpr unsigned kSpeedSignBit = 15;
inline constexpr unsigned kLoadSignBit = 10;

// ---- conversions (servo.md § 3) ----
inline constexpr std::int32_t kTicksPerRev = 4096;
inline constexpr std::int32_t kDefaultCenterTick = 1000;
//! Goal positions are clamped to the servo's single-turn position-mode range (its default
//! angle limits 0…4095): a goal outside it would be refused or wrapped by the servo, and a
//! negative goal would put a sign bit on the wire that position mode does not define.
inline constexpr std::int32_t kMinGoalTick = 0;
inline constexpr std::int32_t kMaxGoalTick = 4095;
inline constexpr std::int32_t kLoadFullScale = 1000; //!< ±1000 = ±100 % of tau_limit
inline constexpr double kDefaultTauLimit = 0.44;     //!< [N·m]

//! ~(sum of ID, LEN, CODE and params) & 0xFF, LEN = params.size() + 2.
std::uint8_t checksum(std::uint8_t id, std::uint8_t code, std::span<const std::uint8_t> params);

//! Writes `FF FF id LEN code params… CHK` into `out`. The same layout serves instruction
//! packets (code = instruction) and status packets (code = the servo's error byte).
//! Returns the packet size, or 0 (nothing written) when `out` is too small or there are more
//! than kMaxParams params.
std::size_t encodePacket(std::uint8_t id, std::uint8_t code, std::span<const std::uint8_t> params,
                         std::span<std::uint8_t> out);

//! Little-endian 16-bit word from its low and high byte.
constexpr std::uint16_t word(std::uint8_t low, std::uint8_t high)
{
    return static_cast<std::uint16_t>(low | (high << 8));
}
//! The low and high byte of a 16-bit word.
constexpr std::array<std::uint8_t, 2> wordBytes(std::uint16_t value)
{
    return {static_cast<std::uint8_t>(value & 0xFF), static_cast<std::uint8_t>(value >> 8)};
}

//! Sign-magnitude with the sign at `signBit` and the magnitude in the bits below it. The
//! magnitude saturates at 2^signBit − 1.
constexpr std::uint16_t encodeSignMagnitude(std::int32_t value, unsigned signBit)
{
    const std::int32_t maxMagnitude = (std::int32_t{1} << signBit) - 1;
    const std::int32_t magnitude = value < -maxMagnitude  ? maxMagnitude
                                   : value < 0            ? -value
                                   : value > maxMagnitude ? maxMagnitude
                                                          : value;
    const std::uint32_t sign = value < 0 ? (std::uint32_t{1} << signBit) : 0u;
    return static_cast<std::uint16_t>(sign | static_cast<std::uint32_t>(magnitude));
}
//! Inverse of encodeSignMagnitude. Bits above `signBit` are ignored; "−0" decodes to 0.
constexpr std::int32_t decodeSignMagnitude(std::uint16_t raw, unsigned signBit)
{
    const std::int32_t magnitude = raw & ((std::int32_t{1} << signBit) - 1);
    return (raw >> signBit) & 1u ? -magnitude : magnitude;
}

// The measurements are converted in double and rounded once to float, exactly as the
// simulator's measureTheta/measureOmega/measureTau did before the bus was emulated, so
// telemetry is bit-identical whichever path produced it. (On the ESP32 the double multiply is
// done in software; it is a few of them per cycle.)

//! θ = (position − centerTick) · 2π/4096 [rad].
float positionToTheta(std::int32_t position, std::int32_t centerTick);
//! ω = speed · 2π/4096 [rad/s]; speed in ticks/s.
float speedToOmega(std::int32_t speed);
//! τ = load · (tauLimit · 10⁻³), saturated at ±tauLimit [N·m]; load in 0.1 % of tauLimit. A knob
//! pushed toward +θ reads a negative load (the servo resists): τ is the interaction torque.
float loadToTorque(std::int32_t load, double tauLimit);
//! centerTick + round(θ · 4096/2π) (half away from zero), clamped to kMinGoalTick…kMaxGoalTick;
//! NaN gives centerTick (clamped). @param theta [rad]
std::int32_t thetaToGoalTick(double theta, std::int32_t centerTick);

} // namespace sts

//! A packet as the parser saw it; `params` points into the parser's buffer and stays valid
//! until the next push(), next() or reset().
struct StsPacket
{
    std::uint8_t id = 0;
    std::uint8_t code = 0; //!< instruction, or the error byte of a status packet
    std::span<const std::uint8_t> params;
};

//! Incremental packet parser with a fixed buffer (never allocates, never grows).
//!
//! Bytes before a header (FF FF followed by an id other than FF) are skipped. A packet whose
//! LEN is below 2 or above kMaxParams + 2, or whose checksum is wrong, is counted and
//! dropped; the search for the next header restarts one byte after the rejected header, so a
//! valid packet hidden inside the rejected bytes is still found.
class StsPacketParser
{
public:
    struct Stats
    {
        std::uint32_t packets = 0;      //!< valid packets reported
        std::uint32_t badChecksum = 0;  //!< complete packets with a wrong checksum
        std::uint32_t badLength = 0;    //!< headers with an impossible LEN
        std::uint32_t skippedBytes = 0; //!< bytes dropped outside valid packets
        std::uint32_t errors() const { return badChecksum + badLength; }
    };

    //! Adds one byte. True when a valid packet is complete: read it with packet(). The packet
    //! reported before is dropped first.
    bool push(std::uint8_t byte);
    //! Drops the packet reported last and looks for another complete one in the bytes already
    //! pushed (only possible after a resynchronisation). True when there is one.
    bool next();
    //! The packet reported by the last push() or next() that returned true.
    StsPacket packet() const;
    //! Raw bytes of that packet, header and checksum included.
    std::span<const std::uint8_t> packetBytes() const;
    //! Bytes held that do not form a reported packet (a header or packet in progress).
    std::size_t pending() const { return m_size - m_packetSize; }
    //! Bytes still missing to complete the packet in progress, as its LEN declares; 0 until
    //! the held bytes reach LEN (or when a packet is reported).
    std::size_t missing() const;
    //! Forgets buffered bytes; keeps the statistics.
    void reset();

    const Stats &stats() const { return m_stats; }

private:
    bool scan();
    void drop(std::size_t count);

    std::array<std::uint8_t, sts::kMaxPacketBytes> m_buffer{};
    std::size_t m_size = 0;
    std::size_t m_packetSize = 0; //!< size of the reported packet at the buffer's start, or 0
    Stats m_stats;
};

} // namespace hatpic::fw
