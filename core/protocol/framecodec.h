// Protocol v2 frames (protocol.md § 2–3): typed message ⇄ `COBS(type | seq | payload | crc)`
// + 0x00. The one encoder and the one decoder, used by the device core and, through the thin
// Qt adaptor in v2codec.h, by the host.
//
// Plain C++20: no Qt, no OS calls, no allocation; memory is fixed at construction.
#pragma once

#include "cobs.h"
#include "messages.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <type_traits>

namespace hatpic::v2 {

constexpr std::size_t kPacketOverhead = 4; //!< type, seq, crc [bytes]

// ---- payload lengths, from each message's fields() (messages.h) ----

template<typename F> constexpr bool kIsOptionalField = false;
template<typename T> constexpr bool kIsOptionalField<std::optional<T>> = true;
template<typename F> constexpr bool kIsRestField = false;
template<typename Text> constexpr bool kIsRestField<Rest<Text>> = true;
template<typename F> constexpr bool kIsTextField = false;
template<std::size_t N> constexpr bool kIsTextField<FixedText<N>> = true;
//! DeviceParams, EffectParams: a block of f32 in wire order.
template<typename F>
concept FieldBlock = requires(F block)
{
    F::kFieldCount;
    block.setField(0, 0.0);
};
//! A message that travels on the wire (Refused does not).
template<typename T>
concept WireMessage = requires
{
    T::kType;
};
//! A visitor that takes any field: what FieldStruct tries fields() with.
struct AnyField
{
    template<typename F> constexpr void operator()(F &&) const {}
};
//! A group of fields inside a message (KnobTelemetry): its own fields(), in wire order.
template<typename F>
concept FieldStruct = !WireMessage<F> && requires(F & m, AnyField &v)
{
    F::fields(m, v);
};

//! Bytes of a field whose length does not depend on its value.
template<typename F> constexpr std::size_t fixedFieldBytes()
{
    if constexpr (std::is_same_v<F, Reserved>)
        return 1;
    else if constexpr (FieldBlock<F>)
        return 4 * std::size_t(F::kFieldCount);
    else if constexpr (kIsTextField<F>)
        return F::capacity();
    else if constexpr (FieldStruct<F>) {
        std::size_t bytes = 0;
        F m{};
        auto add = [&bytes](const auto &field) {
            bytes += fixedFieldBytes<std::remove_cvref_t<decltype(field)>>();
        };
        F::fields(m, add);
        return bytes;
    } else {
        static_assert(std::is_integral_v<F> || std::is_enum_v<F> || std::is_same_v<F, float>,
                      "a field's wire form: see messages.h");
        return sizeof(F);
    }
}

//! Payload lengths a receiver accepts for a message type: min…max [bytes].
struct PayloadBounds
{
    std::size_t min = 0;
    std::size_t max = 0;
    bool valid = true; //!< false when a field follows an optional or Rest field (an optional
                       //!< may follow an optional)
};

//! The lengths T's fields() allow: fixed fields add to both bounds; an optional field lets the
//! payload grow to kMaxPayload (newer senders may append); Rest text adds 1…N bytes.
template<typename T> constexpr PayloadBounds payloadBounds()
{
    PayloadBounds bounds;
    if constexpr (!std::is_empty_v<T>) {
        bool open = false;
        bool openByOptional = false;
        T m{};
        auto visit = [&](const auto &field) {
            using F = std::remove_cvref_t<decltype(field)>;
            bounds.valid = bounds.valid && (!open || (openByOptional && kIsOptionalField<F>));
            if constexpr (kIsOptionalField<F>) {
                bounds.max = kMaxPayload;
                open = true;
                openByOptional = true;
            } else if constexpr (kIsRestField<F>) {
                const std::size_t capacity = std::remove_cvref_t<decltype(field.text)>::capacity();
                bounds.max = std::min(bounds.min + capacity, kMaxPayload);
                bounds.min += 1;
                open = true;
            } else {
                bounds.min += fixedFieldBytes<F>();
                bounds.max += fixedFieldBytes<F>();
            }
        };
        T::fields(m, visit);
    }
    return bounds;
}

constexpr std::size_t kTelemetryBytes = payloadBounds<Telemetry>().min; //!< without τ_fx
constexpr std::size_t kTelemetryFxBytes = kTelemetryBytes + 4; //!< with τ_fx (effects.md § 3)
//! With τ_fx, τ_pc and R (the passivity capability, passivity.md) [bytes].
constexpr std::size_t kTelemetryPcBytes = kTelemetryFxBytes + 8;
//! TELEMETRY of a device with `axes` knobs (kCapabilityAxes; 2…4): 37 bytes, then 33 per
//! further knob [bytes].
constexpr std::size_t telemetryBytes(int axes)
{
    return kTelemetryPcBytes + std::size_t(axes - 1) * fixedFieldBytes<KnobTelemetry>();
}
//! A TELEMETRY frame's length on the wire (COBS adds at most one byte here, plus the
//! delimiter): 31 bytes, 35 with τ_fx, 43 with τ_pc and R too, and 33 more for each further
//! knob of a device with several (with both capabilities) [bytes].
constexpr std::size_t telemetryWireBytes(bool withEffects, bool withPassivity = false, int axes = 1)
{
    const std::size_t payload = axes > 1        ? telemetryBytes(axes)
                                : withPassivity ? kTelemetryPcBytes
                                : withEffects   ? kTelemetryFxBytes
                                                : kTelemetryBytes;
    return cobsMaxEncodedSize(kPacketOverhead + payload) + 1;
}
//! Largest frame on the wire: COBS of the largest packet plus the delimiter [bytes].
constexpr std::size_t kMaxWireFrameBytes = cobsMaxEncodedSize(kPacketOverhead + kMaxPayload) + 1;
// The descriptions against protocol.md § 3 and effects.md § 3.
static_assert(payloadBounds<Params>().min == 28);
static_assert(payloadBounds<HelloReply>().min == 28);
static_assert(fixedFieldBytes<KnobTelemetry>() == 33);
static_assert(telemetryBytes(4) == 136 && telemetryWireBytes(true, true, 4) == 142);
static_assert(payloadBounds<Ack>().min == 4 && payloadBounds<Ack>().max == 4);
static_assert(payloadBounds<Vibrate>().min == 12);
static_assert(kTelemetryBytes == 25 && payloadBounds<Telemetry>().max == kMaxPayload);
static_assert(payloadBounds<Log>().min == 1 && payloadBounds<Log>().max == kMaxPayload);
static_assert(telemetryWireBytes(false) == 31 && telemetryWireBytes(true) == 35);
static_assert(telemetryWireBytes(true, true) == 43);
static_assert(payloadBounds<SetPassivity>().min == 8);

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
    FromHost,   //!< device side: accepts 0x01…0x0D
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
