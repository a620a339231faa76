// The host's Qt adaptor over the protocol v2 wire format: QByteArray in and out, QList of
// frames, QString names. Every wire rule lives in the plain files it includes (crc16.h,
// cobs.h, messages.h, framecodec.h), which the device core compiles too.
#pragma once

#include "crc16.h"
#include "framecodec.h"
#include "messages.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QList>
#include <QString>

#include <span>

namespace hatpic::v2 {

//! The bytes of a QByteArrayView as the plain wire code takes them.
inline std::span<const std::uint8_t> asBytes(QByteArrayView bytes)
{
    return {reinterpret_cast<const std::uint8_t *>(bytes.data()),
            static_cast<std::size_t>(bytes.size())};
}

quint16 crc16(QByteArrayView data);
QByteArray cobsEncode(QByteArrayView data);
//! Standard COBS decoding of one frame body (without its delimiter); false on a malformed body.
bool cobsDecode(QByteArrayView encoded, QByteArray &decoded);

//! Raw packet `type | seq | payload | crc` → COBS + delimiter, ready for the wire.
QByteArray encodePacket(quint8 type, quint8 seq, QByteArrayView payload);
//! Typed message → wire bytes (Refused and an empty LOG are not encodable: empty array).
QByteArray encodeFrame(quint8 seq, const Message &message);

QString dropReasonName(DropReason reason);
//! "OUT_OF_RANGE", …; a status this build does not know is named by its number.
QString ackStatusName(AckStatus status);

template<std::size_t N> QString toQString(const FixedText<N> &text)
{
    const std::string_view v = text.view();
    return QString::fromUtf8(v.data(), static_cast<qsizetype>(v.size()));
}
template<std::size_t N> FixedText<N> fixedText(const QString &text)
{
    const QByteArray utf8 = text.toUtf8();
    return FixedText<N>(std::string_view(utf8.constData(), static_cast<std::size_t>(utf8.size())));
}

//! Text as a person reads it: the wire's UTF-8 compared with a QString.
template<std::size_t N> bool operator==(const FixedText<N> &wire, const QString &text)
{
    return toQString(wire) == text;
}

//! WireDecoder yielding into a QList.
class FrameDecoder
{
public:
    static constexpr int kMaxFrameBytes = int(WireDecoder::kMaxFrameBytes);

    explicit FrameDecoder(Direction direction) : m_decoder(direction) {}

    void feed(QByteArrayView bytes, QList<Frame> &out)
    {
        m_decoder.feed(asBytes(bytes), [&out](const Frame &frame) { out.append(frame); });
    }
    const DecoderStats &stats() const { return m_decoder.stats(); }
    void resetStats() { m_decoder.resetStats(); }
    void clear() { m_decoder.clear(); }
    qsizetype pendingBytes() const { return qsizetype(m_decoder.pendingBytes()); }

private:
    WireDecoder m_decoder;
};

} // namespace hatpic::v2
