// Protocol v2 framing: COBS + CRC-16/CCITT-FALSE + 0x00 delimiter (protocol.md § 2).
#pragma once

#include "messages.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QList>

#include <array>

namespace hatpic::v2 {

//! CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, xorout 0).
quint16 crc16(QByteArrayView data);

//! Standard COBS encoding (no delimiter appended).
QByteArray cobsEncode(QByteArrayView data);
//! Standard COBS decoding of one frame body (without its delimiter); false on a malformed body.
bool cobsDecode(QByteArrayView encoded, QByteArray &decoded);

//! Raw packet `type | seq | payload | crc` → COBS + delimiter, ready for the wire.
QByteArray encodePacket(quint8 type, quint8 seq, QByteArrayView payload);
//! Typed message → wire bytes (Refused is not encodable and yields an empty array).
QByteArray encodeFrame(quint8 seq, const Message &message);

//! Which side's messages a decoder accepts.
enum class Direction {
    FromDevice, //!< host side: accepts 0x81…0xE0
    FromHost,   //!< device side: accepts 0x01…0x08
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
QString dropReasonName(DropReason reason);

struct DecoderStats
{
    quint64 bytes = 0;  //!< bytes fed
    quint64 frames = 0; //!< frames yielded with a known message
    std::array<quint64, kDropReasonCount> drops{};

    quint64 dropped(DropReason r) const { return drops[static_cast<int>(r)]; }
    quint64 totalDropped() const;
    friend bool operator==(const DecoderStats &, const DecoderStats &) = default;
};

//! Incremental decoder: accepts bytes in any chunking, yields typed frames.
//!
//! Memory is bounded: at most kMaxFrameBytes are buffered; a longer run without a delimiter is
//! discarded (counted once as Overflow) and decoding resumes after the next 0x00.
class FrameDecoder
{
public:
    static constexpr int kMaxFrameBytes = 256;

    explicit FrameDecoder(Direction direction) : m_direction(direction) {}

    //! Decodes what `bytes` completes and appends the frames to `out`. Frames that fail
    //! COBS/length/CRC are counted and dropped; unknown type or bad length are counted as
    //! dropped *and* appended as a Refused message so that a device can answer them.
    void feed(QByteArrayView bytes, QList<Frame> &out);

    const DecoderStats &stats() const { return m_stats; }
    void resetStats() { m_stats = {}; }
    //! Forgets a partial frame (e.g. after reopening a port).
    void clear();
    //! Bytes of an unfinished frame held right now; never more than kMaxFrameBytes.
    qsizetype pendingBytes() const { return m_buffer.size(); }

private:
    void finishFrame(QList<Frame> &out);

    Direction m_direction;
    QByteArray m_buffer;
    bool m_overflowing = false;
    DecoderStats m_stats;
};

} // namespace hatpic::v2
