// Protocol v2 incremental frame decoder: drops, resynchronisation, bounded memory.
#include "v2testutil.h"

#include <QTest>

#include <bit>

using namespace hatpic;
using namespace hatpic::v2;
using namespace Qt::StringLiterals;

Q_DECLARE_METATYPE(hatpic::v2::Direction)
Q_DECLARE_METATYPE(hatpic::v2::DropReason)
Q_DECLARE_METATYPE(QList<hatpic::v2::Frame>)

namespace {

QByteArray hex(const char *h)
{
    return QByteArray::fromHex(h);
}

const QByteArray kHello0 = hex("02 01 03 3e 2e 00");
const QByteArray kAck = hex("02 83 02 03 02 ff 03 f3 8c 00"); // device seq 0, acks seq 3, OK

template<typename... Parts> QByteArray join(const Parts &...parts)
{
    QByteArray out;
    (out.append(parts), ...);
    return out;
}

QByteArray repeated(char c, int n)
{
    return QByteArray(n, c);
}

} // namespace

class TestV2Decoder : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    //! Each drop reason is counted on its own; a good frame after the bad one still decodes.
    void dropReasons_data()
    {
        QTest::addColumn<Direction>("direction");
        QTest::addColumn<QByteArray>("input");
        QTest::addColumn<int>("reason"); // -1: no drop
        QTest::addColumn<QList<Frame>>("expected");

        const QList<Frame> hello{Frame{0, Hello{}}};
        const auto h = Direction::FromHost;
        const auto d = Direction::FromDevice;

        QTest::newRow("good frame") << h << kHello0 << -1 << hello;
        QTest::newRow("COBS code past the end")
            << h << join(hex("05 11 22 00"), kHello0) << int(DropReason::Cobs) << hello;
        QTest::newRow("COBS code one past the end")
            << h << join(hex("03 11 00"), kHello0) << int(DropReason::Cobs) << hello;
        QTest::newRow("short: 3-byte packet")
            << h << join(cobsEncode(hex("01 00 3e")), '\0', kHello0) << int(DropReason::Short)
            << hello;
        QTest::newRow("short: single byte")
            << h << join(hex("01 00"), kHello0) << int(DropReason::Short) << hello;
        QTest::newRow("CRC: last byte changed")
            << h << join(hex("02 01 03 3e 2f 00"), kHello0) << int(DropReason::Crc) << hello;
        QTest::newRow("CRC: byte order swapped")
            << h << join(hex("02 01 03 2e 3e 00"), kHello0) << int(DropReason::Crc) << hello;
        QTest::newRow("CRC: seq changed")
            << h << hex("05 01 02 1f 3e 00") << int(DropReason::Crc) << QList<Frame>{};

        QTest::newRow("unknown type 0x42 is refused")
            << h << join(encodePacket(0x42, 9, {}), kHello0) << int(DropReason::UnknownType)
            << QList<Frame>{Frame{9, Refused{0x42, AckStatus::UnknownType}}, Frame{0, Hello{}}};
        QTest::newRow("unknown type 0x00")
            << d << join(encodePacket(0x00, 1, hex("01 02")), kAck) << int(DropReason::UnknownType)
            << QList<Frame>{Frame{1, Refused{0x00, AckStatus::UnknownType}},
                            Frame{0, Ack{3, AckStatus::Ok, kNoField}}};
        QTest::newRow("host type at the host")
            << d << kHello0 << int(DropReason::UnknownType)
            << QList<Frame>{Frame{0, Refused{0x01, AckStatus::UnknownType}}};

        QTest::newRow("HELLO with a payload byte")
            << h << encodePacket(0x01, 3, hex("00")) << int(DropReason::BadLength)
            << QList<Frame>{Frame{3, Refused{0x01, AckStatus::BadLength}}};
        QTest::newRow("PING with 3 bytes")
            << h << encodePacket(0x07, 4, hex("01 02 03")) << int(DropReason::BadLength)
            << QList<Frame>{Frame{4, Refused{0x07, AckStatus::BadLength}}};
        QTest::newRow("SET_PARAMS with 27 bytes")
            << h << encodePacket(0x03, 5, repeated(1, 27)) << int(DropReason::BadLength)
            << QList<Frame>{Frame{5, Refused{0x03, AckStatus::BadLength}}};
        QTest::newRow("SET_STREAM with 4 bytes")
            << h << encodePacket(0x04, 6, repeated(1, 4)) << int(DropReason::BadLength)
            << QList<Frame>{Frame{6, Refused{0x04, AckStatus::BadLength}}};
        // TELEMETRY may grow (effects.md § 3): a host reads any length from 25 bytes on.
        QTest::newRow("TELEMETRY with 24 bytes")
            << d << encodePacket(0x90, 7, repeated(1, 24)) << int(DropReason::BadLength)
            << QList<Frame>{Frame{7, Refused{0x90, AckStatus::BadLength}}};
        QTest::newRow("empty LOG") << d << encodePacket(0xE0, 8, {}) << int(DropReason::BadLength)
                                   << QList<Frame>{Frame{8, Refused{0xE0, AckStatus::BadLength}}};
        QTest::newRow("LOG of 241 bytes")
            << d << encodePacket(0xE0, 9, repeated('a', 241)) << int(DropReason::BadLength)
            << QList<Frame>{Frame{9, Refused{0xE0, AckStatus::BadLength}}};

        QTest::newRow("overflow: 300 bytes without delimiter")
            << h << join(repeated(0x55, 300), '\0', kHello0) << int(DropReason::Overflow) << hello;
        QTest::newRow("overflow: 257 bytes")
            << h << join(repeated(0x55, 257), '\0', kHello0) << int(DropReason::Overflow) << hello;
        QTest::newRow("overflow swallows a frame without its leading delimiter")
            << h << join(repeated(0x55, 253), kHello0, kHello0) << int(DropReason::Overflow)
            << hello;
        // 256 bytes is the most a frame may hold: it is decoded (here: fails COBS), not an
        // overflow.
        QTest::newRow("256 bytes is not an overflow")
            << h << join(repeated(0x55, 256), '\0', kHello0) << int(DropReason::Cobs) << hello;
    }
    void dropReasons()
    {
        QFETCH(Direction, direction);
        QFETCH(QByteArray, input);
        QFETCH(int, reason);
        QFETCH(QList<Frame>, expected);

        // Whole, then byte by byte: same result.
        for (const bool byteWise : {false, true}) {
            FrameDecoder decoder(direction);
            QList<Frame> out;
            if (byteWise) {
                for (const char c : input)
                    decoder.feed(QByteArrayView(&c, 1), out);
            } else {
                decoder.feed(input, out);
            }
            QCOMPARE(out, expected);
            const DecoderStats &stats = decoder.stats();
            QCOMPARE(stats.bytes, quint64(input.size()));
            for (int r = 0; r < kDropReasonCount; ++r)
                QCOMPARE(stats.drops[r], quint64(r == reason ? 1 : 0));
            qsizetype refused = 0;
            for (const Frame &f : expected)
                refused += std::holds_alternative<Refused>(f.message) ? 1 : 0;
            QCOMPARE(stats.frames, quint64(expected.size() - refused));
            QCOMPARE(decoder.pendingBytes(), 0);
        }
    }

    //! Two delimiters in a row are an empty frame: skipped, not counted as a drop.
    void emptyFramesAreSkipped_data()
    {
        QTest::addColumn<QByteArray>("input");
        QTest::addColumn<int>("frames");
        QTest::newRow("delimiters only") << repeated(0, 10) << 0;
        QTest::newRow("leading delimiters") << join(hex("00 00"), kHello0) << 1;
        QTest::newRow("between frames") << join(kHello0, hex("00 00 00"), kHello0) << 2;
    }
    void emptyFramesAreSkipped()
    {
        QFETCH(QByteArray, input);
        QFETCH(int, frames);
        FrameDecoder decoder(Direction::FromHost);
        QList<Frame> out;
        decoder.feed(input, out);
        QCOMPARE(out.size(), frames);
        QCOMPARE(decoder.stats().totalDropped(), quint64(0));
        QCOMPARE(decoder.stats().frames, quint64(frames));
    }

    //! A frame that started before we listened (no leading delimiter) is lost; the next is not.
    void joinsMidStream()
    {
        FrameDecoder decoder(Direction::FromDevice);
        QList<Frame> out;
        decoder.feed(join(kAck.mid(4), kAck), out);
        QCOMPARE(out, (QList<Frame>{Frame{0, Ack{3, AckStatus::Ok, kNoField}}}));
        QCOMPARE(decoder.stats().totalDropped(), quint64(1));
    }

    void everySplitPosition()
    {
        const QByteArray stream = join(kHello0, encodeFrame(9, SetParams{}), kHello0);
        for (int a = 0; a <= stream.size(); ++a) {
            for (int b = a; b <= stream.size(); ++b) {
                FrameDecoder decoder(Direction::FromHost);
                QList<Frame> out;
                decoder.feed(QByteArrayView(stream).first(a), out);
                decoder.feed(QByteArrayView(stream).sliced(a, b - a), out);
                decoder.feed(QByteArrayView(stream).sliced(b), out);
                QCOMPARE(out.size(), 3);
                QCOMPARE(decoder.stats().totalDropped(), quint64(0));
            }
        }
    }

    void clearForgetsPartialFrame()
    {
        FrameDecoder decoder(Direction::FromHost);
        QList<Frame> out;
        decoder.feed(kHello0.first(3), out);
        QCOMPARE(decoder.pendingBytes(), 3);
        decoder.clear();
        QCOMPARE(decoder.pendingBytes(), 0);
        decoder.feed(kHello0, out);
        QCOMPARE(out, (QList<Frame>{Frame{0, Hello{}}}));
        QCOMPARE(decoder.stats().totalDropped(), quint64(0));
    }

    void clearEndsOverflow()
    {
        FrameDecoder decoder(Direction::FromHost);
        QList<Frame> out;
        decoder.feed(repeated(0x55, 1000), out);
        decoder.clear();
        decoder.feed(kHello0, out); // would be swallowed if the overflow were still running
        QCOMPARE(out.size(), 1);
    }

    void resetStats()
    {
        FrameDecoder decoder(Direction::FromHost);
        QList<Frame> out;
        decoder.feed(join(hex("05 00"), kHello0), out);
        QVERIFY(decoder.stats() != DecoderStats{});
        decoder.resetStats();
        QCOMPARE(decoder.stats(), DecoderStats{});
    }

    //! A long run without delimiter is one overflow, however long; memory stays bounded.
    void boundedMemory_data()
    {
        QTest::addColumn<int>("chunk");
        QTest::newRow("1-byte chunks") << 1;
        QTest::newRow("100-byte chunks") << 100;
        QTest::newRow("64 KiB chunks") << 65536;
    }
    void boundedMemory()
    {
        QFETCH(int, chunk);
        FrameDecoder decoder(Direction::FromDevice);
        QList<Frame> out;
        const QByteArray block(chunk, char(0xA5));
        qsizetype fed = 0;
        while (fed < 1 << 20) {
            decoder.feed(block, out);
            fed += block.size();
            QVERIFY(decoder.pendingBytes() <= FrameDecoder::kMaxFrameBytes);
        }
        QCOMPARE(decoder.stats().dropped(DropReason::Overflow), quint64(1));
        QCOMPARE(decoder.stats().totalDropped(), quint64(1));
        decoder.feed(join('\0', kAck), out);
        QCOMPARE(out, (QList<Frame>{Frame{0, Ack{3, AckStatus::Ok, kNoField}}}));
    }

    void longerTelemetryIsRead()
    {
        // 25 bytes: no τ_fx; 29: τ_fx; 41: τ_fx, τ_pc and R (the passivity capability) and 4
        // bytes a newer device added, ignored.
        FrameDecoder decoder(Direction::FromDevice);
        Telemetry t;
        t.t_us = 1000;
        t.theta = 0.25f;
        t.flags = 2;
        QByteArray base = encodeFrame(1, t);
        t.tau_fx = -0.125f;
        QByteArray withFx = encodeFrame(2, t);
        QByteArray payload;
        {
            QByteArray p;
            QVERIFY(cobsDecode(QByteArrayView(withFx).chopped(1), p));
            payload = p.mid(2, p.size() - 4) + QByteArray(12, '\x7f');
        }
        QList<Frame> frames;
        decoder.feed(QByteArray(base + withFx + encodePacket(0x90, 3, payload)), frames);
        QCOMPARE(frames.size(), 3);
        QVERIFY(!std::get<Telemetry>(frames[0].message).tau_fx);
        QCOMPARE(std::get<Telemetry>(frames[1].message), t);
        const float f7f = std::bit_cast<float>(0x7f7f7f7fu);
        t.tau_pc = f7f;
        t.pc_reserve = f7f;
        QCOMPARE(std::get<Telemetry>(frames[2].message), t);
        QCOMPARE(decoder.stats().totalDropped(), quint64(0));
    }

    void dropReasonNames()
    {
        QStringList names;
        for (int r = 0; r < kDropReasonCount; ++r) {
            const QString name = dropReasonName(DropReason(r));
            QVERIFY(!name.isEmpty());
            QVERIFY2(!names.contains(name), qPrintable(name));
            names.append(name);
        }
        QCOMPARE(dropReasonName(DropReason::Crc), u"CRC mismatch"_s);
    }
};

QTEST_GUILESS_MAIN(TestV2Decoder)
#include "tst_v2decoder.moc"
