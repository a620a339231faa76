#include "v2codec.h"

#include "cobs.h"

namespace hatpic::v2 {

quint16 crc16(QByteArrayView data)
{
    return crc16(asBytes(data));
}

QByteArray cobsEncode(QByteArrayView data)
{
    QByteArray out(qsizetype(cobsMaxEncodedSize(std::size_t(data.size()))), Qt::Uninitialized);
    const std::size_t n = cobsEncode(
        asBytes(data), {reinterpret_cast<std::uint8_t *>(out.data()), std::size_t(out.size())});
    out.truncate(qsizetype(n));
    return out;
}

bool cobsDecode(QByteArrayView encoded, QByteArray &decoded)
{
    decoded.resize(encoded.size());
    const std::optional<std::size_t> n =
        cobsDecode(asBytes(encoded),
                   {reinterpret_cast<std::uint8_t *>(decoded.data()), std::size_t(decoded.size())});
    decoded.truncate(n ? qsizetype(*n) : 0);
    return n.has_value();
}

QByteArray encodePacket(quint8 type, quint8 seq, QByteArrayView payload)
{
    std::array<std::uint8_t, cobsMaxEncodedSize(kPacketOverhead + kMaxRawPayload) + 1> buffer;
    const std::size_t n = encodePacket(type, seq, asBytes(payload), buffer);
    return QByteArray(reinterpret_cast<const char *>(buffer.data()), qsizetype(n));
}

QByteArray encodeFrame(quint8 seq, const Message &message)
{
    FrameBuffer buffer;
    const std::size_t n = encodeFrame(seq, message, buffer);
    return QByteArray(reinterpret_cast<const char *>(buffer.data()), qsizetype(n));
}

QString dropReasonName(DropReason reason)
{
    const std::string_view text = dropReasonText(reason);
    return QString::fromLatin1(text.data(), qsizetype(text.size()));
}

QString ackStatusName(AckStatus status)
{
    const std::string_view name = ackStatusWireName(status);
    if (name.empty()) // a newer device may send a status this host does not know
        return QStringLiteral("STATUS_%1").arg(static_cast<int>(status));
    return QString::fromLatin1(name.data(), qsizetype(name.size()));
}

} // namespace hatpic::v2
