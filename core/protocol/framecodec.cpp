#include "framecodec.h"

#include "crc16.h"

#include <bit>
#include <cstring>
#include <type_traits>

namespace hatpic::v2 {

namespace {

//! Little-endian payload writer straight into the caller's frame buffer; the caller has
//! checked the room (payloadSize()).
class Writer
{
public:
    explicit Writer(std::uint8_t *at) : m_at(at) {}
    void u8(std::uint8_t v) { *m_at++ = v; }
    void u16(std::uint16_t v) { put(v); }
    void u32(std::uint32_t v) { put(v); }
    void f32(float v) { u32(std::bit_cast<std::uint32_t>(v)); }
    void params(const DeviceParams &p)
    {
        // Doubles travel as binary32: rounded to the nearest float, out-of-range values
        // become ±Inf and NaN stays NaN (the receiver's validation rejects both).
        for (int i = 0; i < DeviceParams::kFieldCount; ++i)
            f32(static_cast<float>(p.field(i)));
    }
    void effects(const EffectParams &p)
    {
        for (int i = 0; i < EffectParams::kFieldCount; ++i)
            f32(static_cast<float>(p.field(i)));
    }
    void text(std::string_view t, std::size_t padTo)
    {
        std::memcpy(m_at, t.data(), t.size());
        m_at += t.size();
        if (t.size() < padTo) {
            std::memset(m_at, 0, padTo - t.size());
            m_at += padTo - t.size();
        }
    }
    std::uint8_t *end() const { return m_at; }

private:
    template<typename U> void put(U v)
    {
        if constexpr (std::endian::native == std::endian::little) {
            std::memcpy(m_at, &v, sizeof v);
            m_at += sizeof v;
        } else {
            for (std::size_t i = 0; i < sizeof v; ++i)
                u8(static_cast<std::uint8_t>(v >> (8 * i)));
        }
    }

    std::uint8_t *m_at;
};

//! Little-endian payload reader; callers check the length first.
class Reader
{
public:
    explicit Reader(std::span<const std::uint8_t> bytes) : m_bytes(bytes) {}
    std::uint8_t u8() { return m_bytes[m_pos++]; }
    std::uint16_t u16() { return get<std::uint16_t>(); }
    std::uint32_t u32() { return get<std::uint32_t>(); }
    float f32() { return std::bit_cast<float>(u32()); }
    DeviceParams params()
    {
        DeviceParams p;
        for (int i = 0; i < DeviceParams::kFieldCount; ++i)
            p.setField(i, static_cast<double>(f32()));
        return p;
    }
    EffectParams effects()
    {
        EffectParams p;
        for (int i = 0; i < EffectParams::kFieldCount; ++i)
            p.setField(i, static_cast<double>(f32()));
        return p;
    }
    std::size_t remaining() const { return m_bytes.size() - m_pos; }
    std::span<const std::uint8_t> bytes(std::size_t n)
    {
        const auto v = m_bytes.subspan(m_pos, n);
        m_pos += n;
        return v;
    }

private:
    template<typename U> U get()
    {
        U v = 0;
        if constexpr (std::endian::native == std::endian::little) {
            std::memcpy(&v, m_bytes.data() + m_pos, sizeof v);
        } else {
            for (std::size_t i = 0; i < sizeof v; ++i)
                v = static_cast<U>(v | (U(m_bytes[m_pos + i]) << (8 * i)));
        }
        m_pos += sizeof v;
        return v;
    }

    std::span<const std::uint8_t> m_bytes;
    std::size_t m_pos = 0;
};

std::string_view textOf(std::span<const std::uint8_t> bytes)
{
    return {reinterpret_cast<const char *>(bytes.data()), bytes.size()};
}

//! Payload length of a message on the wire, or -1 when it is not encodable.
template<typename T> std::ptrdiff_t payloadSize(const T &m)
{
    if constexpr (std::is_same_v<T, SetParams> || std::is_same_v<T, Params>)
        return std::ptrdiff_t(kParamBlockBytes);
    else if constexpr (std::is_same_v<T, SetEffects> || std::is_same_v<T, Effects>)
        return std::ptrdiff_t(kEffectBlockBytes);
    else if constexpr (std::is_same_v<T, Vibrate>)
        return std::ptrdiff_t(kVibrateBytes);
    else if constexpr (std::is_same_v<T, SetStream>)
        return 2;
    else if constexpr (std::is_same_v<T, SetFeedback> || std::is_same_v<T, Ping> ||
                       std::is_same_v<T, Pong>)
        return 4;
    else if constexpr (std::is_same_v<T, HelloReply>)
        return std::ptrdiff_t(kHelloReplyBytes);
    else if constexpr (std::is_same_v<T, Ack>)
        return std::ptrdiff_t(kAckBytes);
    else if constexpr (std::is_same_v<T, Telemetry>)
        return std::ptrdiff_t(m.tau_fx ? kTelemetryFxBytes : kTelemetryBytes);
    else if constexpr (std::is_same_v<T, Log>)
        return m.text.empty() ? -1 : std::ptrdiff_t(m.text.size()); // a LOG carries 1…240 bytes
    else
        return 0; // Hello, GetParams, SaveParams, Zero, GetEffects: no payload
}

//! Writes the payload of `m` (payloadSize(m) bytes).
template<typename T> void writePayload(const T &m, Writer &w)
{
    if constexpr (std::is_same_v<T, SetParams> || std::is_same_v<T, Params>) {
        w.params(m.params);
    } else if constexpr (std::is_same_v<T, SetEffects> || std::is_same_v<T, Effects>) {
        w.effects(m.effects);
    } else if constexpr (std::is_same_v<T, Vibrate>) {
        w.f32(m.amplitude);
        w.f32(m.frequency);
        w.f32(m.duration);
    } else if constexpr (std::is_same_v<T, SetStream>) {
        w.u16(m.rateHz);
    } else if constexpr (std::is_same_v<T, SetFeedback>) {
        w.f32(m.tauExt);
    } else if constexpr (std::is_same_v<T, Ping> || std::is_same_v<T, Pong>) {
        w.u32(m.token);
    } else if constexpr (std::is_same_v<T, HelloReply>) {
        w.u8(m.protocolVersion);
        w.u8(m.capabilities);
        w.u16(m.maxStreamHz);
        w.u32(m.deviceId);
        w.f32(m.tauLimit);
        w.text(m.firmware.view(), kFirmwareBytes);
    } else if constexpr (std::is_same_v<T, Ack>) {
        w.u8(m.ackedSeq);
        w.u8(static_cast<std::uint8_t>(m.status));
        w.u8(m.field);
        w.u8(0); // reserved
    } else if constexpr (std::is_same_v<T, Telemetry>) {
        w.u32(m.t_us);
        w.f32(m.theta);
        w.f32(m.omega);
        w.f32(m.tau);
        w.f32(m.tau_rec);
        w.f32(m.tau_ext);
        w.u8(m.flags);
        if (m.tau_fx)
            w.f32(*m.tau_fx);
    } else if constexpr (std::is_same_v<T, Log>) {
        w.text(m.text.view(), 0);
    }
}

//! Completes a frame whose packet body (`type | seq | payload`, `body` bytes) sits at out[1…]:
//! appends the CRC, stuffs the packet in place (it fits one COBS block) and the delimiter.
std::size_t finishFrame(std::span<std::uint8_t> out, std::size_t body)
{
    static_assert(kPacketOverhead + kMaxPayload <= kCobsBlockBytes);
    const std::uint16_t crc = crc16(out.subspan(1, body));
    out[1 + body] = static_cast<std::uint8_t>(crc);
    out[2 + body] = static_cast<std::uint8_t>(crc >> 8);
    const std::size_t n = cobsEncodeInPlace(out.first(body + 3));
    out[n] = 0;
    return n + 1;
}

template<typename T>
std::size_t encodeMessage(std::uint8_t seq, const T &m, std::span<std::uint8_t> out)
{
    if constexpr (std::is_same_v<T, Refused>) {
        return 0; // what a receiver made of a frame, not a message to send
    } else {
        const std::ptrdiff_t payload = payloadSize(m);
        if (payload < 0)
            return 0;
        const std::size_t body = 2 + std::size_t(payload);
        if (out.size() < body + 4) // code byte, body, CRC, delimiter
            return 0;
        out[1] = static_cast<std::uint8_t>(messageTypeOf<T>());
        out[2] = seq;
        Writer w(out.data() + 3);
        writePayload(m, w);
        return finishFrame(out, body);
    }
}

//! Payload length a known type must have: >= 0 fixed, -1 unknown for this direction,
//! -2 variable (LOG, 1…kMaxPayload), -3 at least kTelemetryBytes (TELEMETRY may grow:
//! effects.md § 3; a receiver reads what it knows).
int expectedLength(std::uint8_t type, Direction direction)
{
    if (direction == Direction::FromHost) {
        switch (static_cast<MessageType>(type)) {
        case MessageType::Hello:
        case MessageType::GetParams:
        case MessageType::SaveParams:
        case MessageType::Zero:
        case MessageType::GetEffects:
            return 0;
        case MessageType::SetEffects:
            return int(kEffectBlockBytes);
        case MessageType::Vibrate:
            return int(kVibrateBytes);
        case MessageType::SetParams:
            return int(kParamBlockBytes);
        case MessageType::SetStream:
            return 2;
        case MessageType::SetFeedback:
        case MessageType::Ping:
            return 4;
        default:
            return -1;
        }
    }
    switch (static_cast<MessageType>(type)) {
    case MessageType::HelloReply:
        return int(kHelloReplyBytes);
    case MessageType::Params:
        return int(kParamBlockBytes);
    case MessageType::Ack:
        return int(kAckBytes);
    case MessageType::Pong:
        return 4;
    case MessageType::Effects:
        return int(kEffectBlockBytes);
    case MessageType::Telemetry:
        return -3;
    case MessageType::Log:
        return -2;
    default:
        return -1;
    }
}

//! Payload of a known type with the right length → typed message in `out`, built in place.
void decodePayload(std::uint8_t type, std::span<const std::uint8_t> payload, Message &out)
{
    Reader r(payload);
    switch (static_cast<MessageType>(type)) {
    case MessageType::Hello:
        out.emplace<Hello>();
        return;
    case MessageType::GetParams:
        out.emplace<GetParams>();
        return;
    case MessageType::SetParams:
        out.emplace<SetParams>(SetParams{r.params()});
        return;
    case MessageType::SetStream:
        out.emplace<SetStream>(SetStream{r.u16()});
        return;
    case MessageType::SetFeedback:
        out.emplace<SetFeedback>(SetFeedback{r.f32()});
        return;
    case MessageType::SaveParams:
        out.emplace<SaveParams>();
        return;
    case MessageType::Ping:
        out.emplace<Ping>(Ping{r.u32()});
        return;
    case MessageType::Zero:
        out.emplace<Zero>();
        return;
    case MessageType::SetEffects:
        out.emplace<SetEffects>(SetEffects{r.effects()});
        return;
    case MessageType::GetEffects:
        out.emplace<GetEffects>();
        return;
    case MessageType::Vibrate: {
        Vibrate &m = out.emplace<Vibrate>();
        m.amplitude = r.f32();
        m.frequency = r.f32();
        m.duration = r.f32();
        return;
    }
    case MessageType::Effects:
        out.emplace<Effects>(Effects{r.effects()});
        return;
    case MessageType::HelloReply: {
        HelloReply &m = out.emplace<HelloReply>();
        m.protocolVersion = r.u8();
        m.capabilities = r.u8();
        m.maxStreamHz = r.u16();
        m.deviceId = r.u32();
        m.tauLimit = r.f32();
        std::string_view firmware = textOf(r.bytes(kFirmwareBytes));
        firmware = firmware.substr(0, firmware.find('\0'));
        m.firmware.assign(firmware);
        return;
    }
    case MessageType::Params:
        out.emplace<Params>(Params{r.params()});
        return;
    case MessageType::Ack: {
        Ack &m = out.emplace<Ack>();
        m.ackedSeq = r.u8();
        m.status = static_cast<AckStatus>(r.u8());
        m.field = r.u8();
        return; // reserved byte ignored
    }
    case MessageType::Pong:
        out.emplace<Pong>(Pong{r.u32()});
        return;
    case MessageType::Telemetry: {
        Telemetry &m = out.emplace<Telemetry>();
        m.t_us = r.u32();
        m.theta = r.f32();
        m.omega = r.f32();
        m.tau = r.f32();
        m.tau_rec = r.f32();
        m.tau_ext = r.f32();
        m.flags = r.u8();
        if (r.remaining() >= 4)
            m.tau_fx = r.f32();
        return; // anything after τ_fx is for newer hosts
    }
    case MessageType::Log:
        out.emplace<Log>().text.assign(textOf(payload));
        return;
    }
    out = Refused{type, AckStatus::UnknownType}; // not reached: callers check the type first
}

} // namespace

std::size_t encodePacket(std::uint8_t type, std::uint8_t seq, std::span<const std::uint8_t> payload,
                         std::span<std::uint8_t> out)
{
    if (payload.size() > kMaxRawPayload)
        return 0;
    const std::size_t body = 2 + payload.size();
    const std::size_t length = body + 2;
    if (out.size() < cobsMaxEncodedSize(length) + 1)
        return 0;
    if (length <= kCobsBlockBytes) {
        out[1] = type;
        out[2] = seq;
        std::copy(payload.begin(), payload.end(), out.begin() + 3);
        return finishFrame(out, body);
    }
    // Longer than any valid frame (tests build them): more than one COBS block.
    std::array<std::uint8_t, kPacketOverhead + kMaxRawPayload> packet;
    packet[0] = type;
    packet[1] = seq;
    std::copy(payload.begin(), payload.end(), packet.begin() + 2);
    const std::uint16_t crc = crc16({packet.data(), body});
    packet[body] = static_cast<std::uint8_t>(crc);
    packet[body + 1] = static_cast<std::uint8_t>(crc >> 8);
    const std::size_t n = cobsEncode({packet.data(), length}, out);
    out[n] = 0;
    return n + 1;
}

std::size_t encodeFrame(std::uint8_t seq, const Message &message, std::span<std::uint8_t> out)
{
    return std::visit([&](const auto &m) { return encodeMessage(seq, m, out); }, message);
}

std::string_view dropReasonText(DropReason reason)
{
    switch (reason) {
    case DropReason::Cobs:
        return "COBS error";
    case DropReason::Short:
        return "too short";
    case DropReason::Crc:
        return "CRC mismatch";
    case DropReason::UnknownType:
        return "unknown type";
    case DropReason::BadLength:
        return "bad length";
    case DropReason::Overflow:
        return "overflow";
    }
    return "unknown reason";
}

std::uint64_t DecoderStats::totalDropped() const
{
    std::uint64_t total = 0;
    for (const std::uint64_t n : drops)
        total += n;
    return total;
}

void WireDecoder::append(std::span<const std::uint8_t> part)
{
    if (m_overflowing)
        return;
    if (m_size + part.size() > kMaxFrameBytes) {
        // Too long for any frame: drop what we hold and skip to the next delimiter.
        overflow();
        m_size = 0;
        m_overflowing = true;
        return;
    }
    std::copy(part.begin(), part.end(), m_buffer.begin() + static_cast<std::ptrdiff_t>(m_size));
    m_size += part.size();
}

void WireDecoder::overflow()
{
    ++m_stats.drops[static_cast<std::size_t>(DropReason::Overflow)];
}

bool WireDecoder::decodeBody(std::span<const std::uint8_t> encoded, Frame &out)
{
    const auto drop = [this](DropReason reason) {
        ++m_stats.drops[static_cast<std::size_t>(reason)];
        return false;
    };
    // Into m_buffer: from the caller's bytes, or in place when the body is m_buffer (the
    // decoded packet is never longer than its encoding).
    const std::optional<std::size_t> decoded = cobsDecodeBody(encoded, m_buffer);
    if (!decoded)
        return drop(DropReason::Cobs);
    const std::size_t length = *decoded;
    if (length < kPacketOverhead)
        return drop(DropReason::Short);
    const std::span<const std::uint8_t> body{m_buffer.data(), length - 2};
    const auto received =
        static_cast<std::uint16_t>(m_buffer[length - 2] | (m_buffer[length - 1] << 8));
    if (crc16(body) != received)
        return drop(DropReason::Crc);
    const std::uint8_t type = body[0];
    out.seq = body[1];
    const std::span<const std::uint8_t> payload = body.subspan(2);
    const int expected = expectedLength(type, m_direction);
    if (expected == -1) {
        drop(DropReason::UnknownType);
        out.message = Refused{type, AckStatus::UnknownType};
        return true;
    }
    bool lengthOk = false;
    if (expected == -2)
        lengthOk = !payload.empty() && payload.size() <= kMaxPayload;
    else if (expected == -3)
        lengthOk = payload.size() >= kTelemetryBytes && payload.size() <= kMaxPayload;
    else
        lengthOk = payload.size() == static_cast<std::size_t>(expected);
    if (!lengthOk) {
        drop(DropReason::BadLength);
        out.message = Refused{type, AckStatus::BadLength};
        return true;
    }
    ++m_stats.frames;
    decodePayload(type, payload, out.message);
    return true;
}

} // namespace hatpic::v2
