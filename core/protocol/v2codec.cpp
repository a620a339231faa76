#include "v2codec.h"

#include <QtEndian>

#include <array>
#include <cmath>
#include <cstring>
#include <optional>
#include <type_traits>

namespace hatpic::v2 {

// ---- CRC-16/CCITT-FALSE ----

namespace {

constexpr std::array<quint16, 256> makeCrcTable()
{
    std::array<quint16, 256> table{};
    for (int i = 0; i < 256; ++i) {
        quint16 crc = static_cast<quint16>(i << 8);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 0x8000) ? static_cast<quint16>((crc << 1) ^ 0x1021)
                                 : static_cast<quint16>(crc << 1);
        table[static_cast<std::size_t>(i)] = crc;
    }
    return table;
}

constexpr std::array<quint16, 256> kCrcTable = makeCrcTable();

} // namespace

quint16 crc16(QByteArrayView data)
{
    quint16 crc = 0xFFFF;
    for (const char c : data) {
        const auto index = static_cast<quint8>((crc >> 8) ^ static_cast<quint8>(c));
        crc = static_cast<quint16>((crc << 8) ^ kCrcTable[index]);
    }
    return crc;
}

// ---- COBS ----

QByteArray cobsEncode(QByteArrayView data)
{
    QByteArray out;
    out.reserve(data.size() + data.size() / 254 + 1);
    qsizetype codeIndex = 0;
    out.append('\x01'); // placeholder for the first block's code byte
    quint8 code = 1;
    for (qsizetype i = 0; i < data.size(); ++i) {
        const char byte = data[i];
        if (byte == 0) {
            out[codeIndex] = static_cast<char>(code);
            codeIndex = out.size();
            out.append('\x01');
            code = 1;
            continue;
        }
        out.append(byte);
        ++code;
        // A full block (254 data bytes) carries no implied zero. A new block is opened only
        // when more data follows, so a packet ending in a full block gets no trailing 0x01.
        if (code == 0xFF && i + 1 < data.size()) {
            out[codeIndex] = static_cast<char>(code);
            codeIndex = out.size();
            out.append('\x01');
            code = 1;
        }
    }
    out[codeIndex] = static_cast<char>(code);
    return out;
}

bool cobsDecode(QByteArrayView encoded, QByteArray &decoded)
{
    decoded.resize(0);
    decoded.reserve(encoded.size());
    qsizetype i = 0;
    while (i < encoded.size()) {
        const auto code = static_cast<quint8>(encoded[i]);
        if (code == 0)
            return false; // a delimiter cannot occur inside a frame body
        const qsizetype end = i + code;
        if (end > encoded.size())
            return false; // the block claims more bytes than the frame holds
        for (qsizetype k = i + 1; k < end; ++k) {
            if (encoded[k] == 0)
                return false;
            decoded.append(encoded[k]);
        }
        i = end;
        if (code != 0xFF && i < encoded.size())
            decoded.append('\0');
    }
    return true;
}

// ---- payload writer / reader ----

namespace {

class Writer
{
public:
    void u8(quint8 v) { m_bytes.append(static_cast<char>(v)); }
    void u16(quint16 v)
    {
        char b[2];
        qToLittleEndian(v, b);
        m_bytes.append(b, 2);
    }
    void u32(quint32 v)
    {
        char b[4];
        qToLittleEndian(v, b);
        m_bytes.append(b, 4);
    }
    void f32(float v)
    {
        quint32 bits = 0;
        std::memcpy(&bits, &v, sizeof bits);
        u32(bits);
    }
    void params(const DeviceParams &p)
    {
        // Doubles travel as binary32: rounded to the nearest float, out-of-range values
        // become ±Inf and NaN stays NaN (the receiver's validation rejects both).
        for (int i = 0; i < DeviceParams::kFieldCount; ++i)
            f32(static_cast<float>(p.field(i)));
    }
    void bytes(QByteArrayView b) { m_bytes.append(b); }
    QByteArray take() { return std::move(m_bytes); }

private:
    QByteArray m_bytes;
};

class Reader
{
public:
    explicit Reader(QByteArrayView bytes) : m_bytes(bytes) {}
    quint8 u8() { return static_cast<quint8>(m_bytes[m_pos++]); }
    quint16 u16()
    {
        const auto v = qFromLittleEndian<quint16>(m_bytes.data() + m_pos);
        m_pos += 2;
        return v;
    }
    quint32 u32()
    {
        const auto v = qFromLittleEndian<quint32>(m_bytes.data() + m_pos);
        m_pos += 4;
        return v;
    }
    float f32()
    {
        const quint32 bits = u32();
        float v = 0;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }
    DeviceParams params()
    {
        DeviceParams p;
        for (int i = 0; i < DeviceParams::kFieldCount; ++i)
            p.setField(i, static_cast<double>(f32()));
        return p;
    }
    QByteArrayView bytes(qsizetype n)
    {
        const QByteArrayView v = m_bytes.sliced(m_pos, n);
        m_pos += n;
        return v;
    }

private:
    QByteArrayView m_bytes;
    qsizetype m_pos = 0;
};

constexpr int kFirmwareBytes = 16;
constexpr int kParamBlockBytes = 4 * DeviceParams::kFieldCount;
constexpr int kHelloReplyBytes = 1 + 1 + 2 + 4 + 4 + kFirmwareBytes;
constexpr int kAckBytes = 4;
constexpr int kTelemetryBytes = 4 + 5 * 4 + 1;
constexpr int kPacketOverhead = 4; // type, seq, crc
static_assert(kParamBlockBytes == 28 && kHelloReplyBytes == 28 && kTelemetryBytes == 25);

//! UTF-8 of `text`, cut at a character boundary so that it fits in `maxBytes`.
QByteArray utf8Truncated(const QString &text, qsizetype maxBytes)
{
    QByteArray utf8 = text.toUtf8();
    if (utf8.size() <= maxBytes)
        return utf8;
    qsizetype cut = maxBytes;
    // Back off while the byte at the cut is a continuation byte (10xxxxxx): cutting there
    // would split a character.
    while (cut > 0 && (static_cast<quint8>(utf8[cut]) & 0xC0) == 0x80)
        --cut;
    utf8.truncate(cut);
    return utf8;
}

QByteArray encodePayload(const Message &message, bool &encodable)
{
    encodable = true;
    Writer w;
    std::visit(
        [&](const auto &m) {
            using T = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<T, SetParams> || std::is_same_v<T, Params>) {
                w.params(m.params);
            } else if constexpr (std::is_same_v<T, SetStream>) {
                w.u16(m.rateHz);
            } else if constexpr (std::is_same_v<T, SetFeedback>) {
                w.f32(m.tauExt);
            } else if constexpr (std::is_same_v<T, Ping> || std::is_same_v<T, Pong>) {
                w.u32(m.token);
            } else if constexpr (std::is_same_v<T, HelloReply>) {
                w.u8(m.protocolVersion);
                w.u8(0); // reserved
                w.u16(m.maxStreamHz);
                w.u32(m.deviceId);
                w.f32(m.tauLimit);
                QByteArray firmware = utf8Truncated(m.firmware, kFirmwareBytes);
                firmware.append(kFirmwareBytes - firmware.size(), '\0');
                w.bytes(firmware);
            } else if constexpr (std::is_same_v<T, Ack>) {
                w.u8(m.ackedSeq);
                w.u8(static_cast<quint8>(m.status));
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
            } else if constexpr (std::is_same_v<T, Log>) {
                const QByteArray text = utf8Truncated(m.text, kMaxPayload);
                if (text.isEmpty())
                    encodable = false; // a LOG carries 1…240 bytes
                w.bytes(text);
            } else if constexpr (std::is_same_v<T, Refused>) {
                encodable = false;
            }
            // Hello, GetParams, SaveParams, Zero: no payload.
        },
        message);
    return w.take();
}

//! Payload length a known type must have: >= 0 fixed, -1 unknown for this direction,
//! -2 variable (LOG, 1…kMaxPayload).
int expectedLength(quint8 type, Direction direction)
{
    if (direction == Direction::FromHost) {
        switch (static_cast<MessageType>(type)) {
        case MessageType::Hello:
        case MessageType::GetParams:
        case MessageType::SaveParams:
        case MessageType::Zero:
            return 0;
        case MessageType::SetParams:
            return kParamBlockBytes;
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
        return kHelloReplyBytes;
    case MessageType::Params:
        return kParamBlockBytes;
    case MessageType::Ack:
        return kAckBytes;
    case MessageType::Pong:
        return 4;
    case MessageType::Telemetry:
        return kTelemetryBytes;
    case MessageType::Log:
        return -2;
    default:
        return -1;
    }
}

//! Payload of a known type with the right length → typed message.
Message decodePayload(quint8 type, QByteArrayView payload)
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
    case MessageType::HelloReply: {
        HelloReply m;
        m.protocolVersion = r.u8();
        r.u8(); // reserved, ignored
        m.maxStreamHz = r.u16();
        m.deviceId = r.u32();
        m.tauLimit = r.f32();
        QByteArrayView firmware = r.bytes(kFirmwareBytes);
        const auto nul = std::memchr(firmware.data(), 0, static_cast<std::size_t>(kFirmwareBytes));
        if (nul)
            firmware = firmware.first(static_cast<const char *>(nul) - firmware.data());
        m.firmware = QString::fromUtf8(firmware);
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
        return m;
    }
    case MessageType::Log:
        return Log{QString::fromUtf8(payload)};
    }
    return Refused{type, AckStatus::UnknownType}; // not reached: callers check the type first
}

} // namespace

// ---- frames ----

QByteArray encodePacket(quint8 type, quint8 seq, QByteArrayView payload)
{
    QByteArray packet;
    packet.reserve(payload.size() + kPacketOverhead);
    packet.append(static_cast<char>(type));
    packet.append(static_cast<char>(seq));
    packet.append(payload);
    char crc[2];
    qToLittleEndian(crc16(packet), crc);
    packet.append(crc, 2);
    QByteArray wire = cobsEncode(packet);
    wire.append('\0');
    return wire;
}

QByteArray encodeFrame(quint8 seq, const Message &message)
{
    bool encodable = true;
    const QByteArray payload = encodePayload(message, encodable);
    if (!encodable)
        return {};
    return encodePacket(messageType(message), seq, payload);
}

// ---- decoder ----

QString dropReasonName(DropReason reason)
{
    switch (reason) {
    case DropReason::Cobs:
        return QStringLiteral("COBS error");
    case DropReason::Short:
        return QStringLiteral("too short");
    case DropReason::Crc:
        return QStringLiteral("CRC mismatch");
    case DropReason::UnknownType:
        return QStringLiteral("unknown type");
    case DropReason::BadLength:
        return QStringLiteral("bad length");
    case DropReason::Overflow:
        return QStringLiteral("overflow");
    }
    return QStringLiteral("unknown reason %1").arg(static_cast<int>(reason));
}

quint64 DecoderStats::totalDropped() const
{
    quint64 total = 0;
    for (const quint64 n : drops)
        total += n;
    return total;
}

void FrameDecoder::clear()
{
    m_buffer.resize(0);
    m_overflowing = false;
}

void FrameDecoder::feed(QByteArrayView bytes, QList<Frame> &out)
{
    m_stats.bytes += static_cast<quint64>(bytes.size());
    while (!bytes.isEmpty()) {
        const auto *zero = static_cast<const char *>(
            std::memchr(bytes.data(), 0, static_cast<std::size_t>(bytes.size())));
        const qsizetype partLength = zero ? zero - bytes.data() : bytes.size();
        if (!m_overflowing) {
            if (m_buffer.size() + partLength > kMaxFrameBytes) {
                // Too long for any frame: drop what we hold and skip to the next delimiter.
                ++m_stats.drops[static_cast<int>(DropReason::Overflow)];
                m_buffer.resize(0);
                m_overflowing = true;
            } else {
                m_buffer.append(bytes.first(partLength));
            }
        }
        if (!zero)
            return;
        if (m_overflowing)
            m_overflowing = false; // resynchronised
        else if (!m_buffer.isEmpty())
            finishFrame(out);
        // else: an empty frame (two delimiters in a row) — skipped, not a drop.
        bytes = bytes.sliced(partLength + 1);
    }
}

void FrameDecoder::finishFrame(QList<Frame> &out)
{
    QByteArray packet;
    const bool cobsOk = cobsDecode(m_buffer, packet);
    m_buffer.resize(0);
    const auto drop = [this](DropReason reason) { ++m_stats.drops[static_cast<int>(reason)]; };
    if (!cobsOk) {
        drop(DropReason::Cobs);
        return;
    }
    if (packet.size() < kPacketOverhead) {
        drop(DropReason::Short);
        return;
    }
    const QByteArrayView body = QByteArrayView(packet).first(packet.size() - 2);
    const auto received = qFromLittleEndian<quint16>(packet.constData() + packet.size() - 2);
    if (crc16(body) != received) {
        drop(DropReason::Crc);
        return;
    }
    const auto type = static_cast<quint8>(packet[0]);
    const auto seq = static_cast<quint8>(packet[1]);
    const QByteArrayView payload = body.sliced(2);
    const int expected = expectedLength(type, m_direction);
    if (expected == -1) {
        drop(DropReason::UnknownType);
        out.append(Frame{seq, Refused{type, AckStatus::UnknownType}});
        return;
    }
    const bool lengthOk = expected == -2 ? (payload.size() >= 1 && payload.size() <= kMaxPayload)
                                         : payload.size() == expected;
    if (!lengthOk) {
        drop(DropReason::BadLength);
        out.append(Frame{seq, Refused{type, AckStatus::BadLength}});
        return;
    }
    ++m_stats.frames;
    out.append(Frame{seq, decodePayload(type, payload)});
}

} // namespace hatpic::v2
