// Protocol v2 frames (protocol.md § 2–3): typed message ⇄ `COBS(type | seq | payload | crc)`
// + 0x00. The one encoder and the one decoder, used by the device core and, through the thin
// Qt adaptor in v2codec.h, by the host.
//
// Plain C++20: no Qt, no OS calls, no allocation; memory is fixed at construction.
#pragma once

#include "cobs.h"
#include "messages.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

namespace hatpic::v2 {

constexpr std::size_t kPacketOverhead = 4; //!< type, seq, crc [bytes]
constexpr std::size_t kParamBlockBytes = 4 * DeviceParams::kFieldCount;
constexpr std::size_t kHelloReplyBytes = 1 + 1 + 2 + 4 + 4 + kFirmwareBytes;
constexpr std::size_t kAckBytes = 4;
constexpr std::size_t kTelemetryBytes = 4 + 5 * 4 + 1;         //!< without τ_fx
constexpr std::size_t kTelemetryFxBytes = kTelemetryBytes + 4; //!< with τ_fx (effects.md § 3)
constexpr std::size_t kEffectBlockBytes = 4 * EffectParams::kFieldCount;
constexpr std::size_t kVibrateBytes = 3 * 4;
//! A TELEMETRY frame's length on the wire (COBS adds at most one byte here, plus the
//! delimiter): 31 bytes, 35 with τ_fx [bytes].
constexpr std::size_t telemetryWireBytes(bool withEffects)
{
    return cobsMaxEncodedSize(kPacketOverhead +
                              (withEffects ? kTelemetryFxBytes : kTelemetryBytes)) +
           1;
}
//! Largest frame on the wire: COBS of the largest packet plus the delimiter [bytes].
constexpr std::size_t kMaxWireFrameBytes = cobsMaxEncodedSize(kPacketOverhead + kMaxPayload) + 1;
static_assert(kParamBlockBytes == 28 && kHelloReplyBytes == 28 && kTelemetryBytes == 25);
static_assert(telemetryWireBytes(false) == 31 && telemetryWireBytes(true) == 35);

//! A buffer that holds any one frame.
using FrameBuffer = std::array<std::uint8_t, kMaxWireFrameBytes>;

//! Longest payload encodePacket() takes: more than any valid frame carries (kMaxPayload), so
//! that tests can build the oversize frames a receiver must refuse [bytes].
constexpr std::size_t kMaxRawPayload = 256;

//! Raw packet `type | seq | payload | crc` → COBS + delimiter in `out`. Returns the wire
//! length, or 0 when the payload is longer than kMaxRawPayload or `out` is too small.
std::size_t encodePacket(std::uint8_t type, std::uint8_t seq, std::span<const std::uint8_t> payload,
                         std::span<std::uint8_t> out);

//! Typed message → wire bytes in `out`. Returns the wire length, or 0 when the message is not
//! encodable (Refused, an empty LOG) or `out` is too small.
std::size_t encodeFrame(std::uint8_t seq, const Message &message, std::span<std::uint8_t> out);

//! Which side's messages a decoder accepts.
enum class Direction {
    FromDevice, //!< host side: accepts 0x81…0xE0
    FromHost,   //!< device side: accepts 0x01…0x0B
};

enum class DropReason {
    Cobs,        //!< COBS decoding failed
    Short,       //!< packet shorter than 4 bytes
    Crc,         //!< CRC mismatch
    UnknownType, //!< CRC ok, type unknown for this direction
    BadLength,   //!< CRC ok, payload length wrong for the type
    Overflow,    //!< more than kMaxFrameBytes without a delimiter
};
constexpr int kDropReasonCount = 6;

//! Short English name of a drop reason ("CRC mismatch", …).
std::string_view dropReasonText(DropReason reason);

struct DecoderStats
{
    std::uint64_t bytes = 0;  //!< bytes fed
    std::uint64_t frames = 0; //!< frames yielded with a known message
    std::array<std::uint64_t, kDropReasonCount> drops{};

    std::uint64_t dropped(DropReason r) const { return drops[static_cast<std::size_t>(r)]; }
    std::uint64_t totalDropped() const;
    friend bool operator==(const DecoderStats &, const DecoderStats &) = default;
};

//! Incremental decoder: accepts bytes in any chunking, yields typed frames.
//!
//! Memory is fixed: at most kMaxFrameBytes are buffered; a longer run without a delimiter is
//! discarded (counted once as Overflow) and decoding resumes after the next 0x00. Frames that
//! fail COBS, length or CRC are counted and dropped; an unknown type or a bad length is counted
//! as dropped *and* yielded as a Refused message, so that a device can answer it.
class WireDecoder
{
public:
    static constexpr std::size_t kMaxFrameBytes = 256;

    explicit WireDecoder(Direction direction) : m_direction(direction) {}

    //! Decodes what `bytes` completes, calling `onFrame(const Frame &)` for each frame.
    template<typename OnFrame> void feed(std::span<const std::uint8_t> bytes, OnFrame &&onFrame)
    {
        m_stats.bytes += bytes.size();
        while (!bytes.empty()) {
            const auto *zero =
                static_cast<const std::uint8_t *>(std::memchr(bytes.data(), 0, bytes.size()));
            if (!zero) {
                append(bytes);
                return;
            }
            const auto part = static_cast<std::size_t>(zero - bytes.data());
            if (m_size > 0 || m_overflowing) {
                append(bytes.first(part)); // completes the frame held, or overflows
                if (m_overflowing) {
                    m_overflowing = false; // resynchronised
                } else {
                    const std::size_t held = m_size;
                    m_size = 0;
                    Frame frame;
                    if (decodeBody({m_buffer.data(), held}, frame))
                        onFrame(static_cast<const Frame &>(frame));
                }
            } else if (part > kMaxFrameBytes) {
                overflow(); // a run too long for any frame, ended by this delimiter
            } else if (part > 0) {
                // The whole frame is in `bytes`: decoded from there, never copied first.
                Frame frame;
                if (decodeBody(bytes.first(part), frame))
                    onFrame(static_cast<const Frame &>(frame));
            }
            // else: an empty frame (two delimiters in a row) — skipped, not a drop.
            bytes = bytes.subspan(part + 1);
        }
    }

    const DecoderStats &stats() const { return m_stats; }
    void resetStats() { m_stats = {}; }
    //! Forgets a partial frame (e.g. after reopening a port).
    void clear()
    {
        m_size = 0;
        m_overflowing = false;
    }
    //! Bytes of an unfinished frame held right now; never more than kMaxFrameBytes.
    std::size_t pendingBytes() const { return m_size; }

private:
    void append(std::span<const std::uint8_t> part);
    void overflow(); //!< counts a run too long for any frame
    //! Decodes one frame body (the bytes between two delimiters: no 0x00, at most
    //! kMaxFrameBytes; may be m_buffer itself); false when it was dropped.
    bool decodeBody(std::span<const std::uint8_t> encoded, Frame &out);

    Direction m_direction;
    std::array<std::uint8_t, kMaxFrameBytes> m_buffer{};
    std::size_t m_size = 0;
    bool m_overflowing = false;
    DecoderStats m_stats;
};

} // namespace hatpic::v2
