#include "framecodec.h"

#include "crc16.h"

#include <bit>
#include <type_traits>

namespace hatpic::v2 {

namespace {

//! Little-endian payload writer into a fixed buffer.
class Writer
{
public:
    void u8(std::uint8_t v) { m_bytes[m_size++] = v; }
    void u16(std::uint16_t v)
    {
        u8(static_cast<std::uint8_t>(v));
        u8(static_cast<std::uint8_t>(v >> 8));
    }
    void u32(std::uint32_t v)
    {
        u16(static_cast<std::uint16_t>(v));
        u16(static_cast<std::uint16_t>(v >> 16));
    }
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
        for (const char c : t)
            u8(static_cast<std::uint8_t>(c));
        for (std::size_t i = t.size(); i < padTo; ++i)
            u8(0);
    }
    std::span<const std::uint8_t> bytes() const { return {m_bytes.data(), m_size}; }

private:
    std::array<std::uint8_t, kMaxPayload> m_bytes{};
    std::size_t m_size = 0;
};

//! Little-endian payload reader; callers check the length first.
class Reader
{
public:
    explicit Reader(std::span<const std::uint8_t> bytes) : m_bytes(bytes) {}
    std::uint8_t u8() { return m_bytes[m_pos++]; }
    std::uint16_t u16()
    {
        const std::uint16_t lo = u8();
        return static_cast<std::uint16_t>(lo | (u8() << 8));
    }
    std::uint32_t u32()
    {
        const std::uint32_t lo = u16();
        return lo | (static_cast<std::uint32_t>(u16()) << 16);
    }
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
    std::span<const std::uint8_t> m_bytes;
    std::size_t m_pos = 0;
};

std::string_view textOf(std::span<const std::uint8_t> bytes)
{
    return {reinterpret_cast<const char *>(bytes.data()), bytes.size()};
}

//! Writes the payload of `message`; false when it is not encodable.
bool encodePayload(const Message &message, Writer &w)
{
    return std::visit(
        [&](const auto &m) {
            using T = std::decay_t<decltype(m)>;
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
                if (m.text.empty())
                    return false; // a LOG carries 1…240 bytes
                w.text(m.text.view(), 0);
            } else if constexpr (std::is_same_v<T, Refused>) {
                return false;
            }
            // Hello, GetParams, SaveParams, Zero: no payload.
            return true;
        },
        message);
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

//! Payload of a known type with the right length → typed message.
Message decodePayload(std::uint8_t type, std::span<const std::uint8_t> payload)
{
    Reader r(payload);
    switch (static_cast<MessageType>(type)) {
    case MessageType::Hello:
        return Hello{};
    case MessageType::GetParams:
        return GetParams{};
    case MessageType::SetParams:
        return SetParams{r.params()};
    case MessageType::SetStream:
        return SetStream{r.u16()};
    case MessageType::SetFeedback:
        return SetFeedback{r.f32()};
    case MessageType::SaveParams:
        return SaveParams{};
    case MessageType::Ping:
        return Ping{r.u32()};
    case MessageType::Zero:
        return Zero{};
    case MessageType::SetEffects:
        return SetEffects{r.effects()};
    case MessageType::GetEffects:
        return GetEffects{};
    case MessageType::Vibrate: {
        Vibrate m;
        m.amplitude = r.f32();
        m.frequency = r.f32();
        m.duration = r.f32();
        return m;
    }
    case MessageType::Effects:
        return Effects{r.effects()};
    case MessageType::HelloReply: {
        HelloReply m;
        m.protocolVersion = r.u8();
        m.capabilities = r.u8();
        m.maxStreamHz = r.u16();
        m.deviceId = r.u32();
        m.tauLimit = r.f32();
        std::string_view firmware = textOf(r.bytes(kFirmwareBytes));
        firmware = firmware.substr(0, firmware.find('\0'));
        m.firmware.assign(firmware);
        return m;
    }
    case MessageType::Params:
        return Params{r.params()};
    case MessageType::Ack: {
        Ack m;
        m.ackedSeq = r.u8();
        m.status = static_cast<AckStatus>(r.u8());
        m.field = r.u8();
        return m; // reserved byte ignored
    }
    case MessageType::Pong:
        return Pong{r.u32()};
    case MessageType::Telemetry: {
        Telemetry m;
        m.t_us = r.u32();
        m.theta = r.f32();
        m.omega = r.f32();
        m.tau = r.f32();
        m.tau_rec = r.f32();
        m.tau_ext = r.f32();
        m.flags = r.u8();
        if (r.remaining() >= 4)
            m.tau_fx = r.f32();
        return m; // anything after τ_fx is for newer hosts
    }
    case MessageType::Log: {
        Log m;
        m.text.assign(textOf(payload));
        return m;
    }
    }
    return Refused{type, AckStatus::UnknownType}; // not reached: callers check the type first
}

} // namespace

std::size_t encodePacket(std::uint8_t type, std::uint8_t seq, std::span<const std::uint8_t> payload,
                         std::span<std::uint8_t> out)
{
    if (payload.size() > kMaxRawPayload)
        return 0;
    std::array<std::uint8_t, kPacketOverhead + kMaxRawPayload> packet;
    packet[0] = type;
    packet[1] = seq;
    std::copy(payload.begin(), payload.end(), packet.begin() + 2);
    const std::size_t body = 2 + payload.size();
    const std::uint16_t crc = crc16({packet.data(), body});
    packet[body] = static_cast<std::uint8_t>(crc);
    packet[body + 1] = static_cast<std::uint8_t>(crc >> 8);
    const std::size_t length = body + 2;
    if (out.size() < cobsMaxEncodedSize(length) + 1)
        return 0;
    const std::size_t n = cobsEncode({packet.data(), length}, out);
    out[n] = 0;
    return n + 1;
}

std::size_t encodeFrame(std::uint8_t seq, const Message &message, std::span<std::uint8_t> out)
{
    Writer w;
    if (!encodePayload(message, w))
        return 0;
    return encodePacket(messageType(message), seq, w.bytes(), out);
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
        ++m_stats.drops[static_cast<std::size_t>(DropReason::Overflow)];
        m_size = 0;
        m_overflowing = true;
        return;
    }
    std::copy(part.begin(), part.end(), m_buffer.begin() + static_cast<std::ptrdiff_t>(m_size));
    m_size += part.size();
}

bool WireDecoder::finishFrame(Frame &out)
{
    const std::span<std::uint8_t> held{m_buffer.data(), m_size};
    m_size = 0;
    const auto drop = [this](DropReason reason) {
        ++m_stats.drops[static_cast<std::size_t>(reason)];
        return false;
    };
    // In place: the decoded packet is never longer than its encoding.
    const std::optional<std::size_t> decoded = cobsDecode(held, held);
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
    out.message = decodePayload(type, payload);
    return true;
}

} // namespace hatpic::v2
