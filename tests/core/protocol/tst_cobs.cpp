// Consistent Overhead Byte Stuffing of protocol v2 (protocol.md § 2).
#include "protocol/v2codec.h"

#include <QRandomGenerator>
#include <QTest>

#include <algorithm>
#include <optional>
#include <span>

using namespace hatpic::v2;

namespace {

QByteArray run(int first, int last)
{
    QByteArray b;
    for (int v = first; v <= last; ++v)
        b.append(static_cast<char>(v));
    return b;
}

QByteArray hex(const char *h)
{
    return QByteArray::fromHex(h);
}

template<typename... Parts> QByteArray join(const Parts &...parts)
{
    QByteArray out;
    (out.append(parts), ...);
    return out;
}

std::span<std::uint8_t> bytesOf(QByteArray &b)
{
    return {reinterpret_cast<std::uint8_t *>(b.data()), std::size_t(b.size())};
}

//! The textbook decoder, one byte at a time, as the reference for the word-at-a-time one:
//! nullopt for a malformed body or when `room` bytes are too few.
std::optional<QByteArray> referenceDecode(const QByteArray &encoded, qsizetype room)
{
    QByteArray out;
    qsizetype i = 0;
    while (i < encoded.size()) {
        const auto code = static_cast<std::uint8_t>(encoded[i]);
        if (code == 0 || i + code > encoded.size())
            return std::nullopt;
        for (qsizetype k = i + 1; k < i + code; ++k) {
            if (encoded[k] == 0 || out.size() >= room)
                return std::nullopt;
            out.append(encoded[k]);
        }
        i += code;
        if (code != 0xFF && i < encoded.size()) {
            if (out.size() >= room)
                return std::nullopt;
            out.append('\0');
        }
    }
    return out;
}

} // namespace

class TestCobs : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void vectors_data()
    {
        QTest::addColumn<QByteArray>("plain");
        QTest::addColumn<QByteArray>("encoded");
        QTest::newRow("empty") << QByteArray() << hex("01");
        QTest::newRow("one zero") << hex("00") << hex("0101");
        QTest::newRow("two zeros") << hex("0000") << hex("010101");
        QTest::newRow("zero data zero") << hex("001100") << hex("01021101");
        QTest::newRow("zero in the middle") << hex("11220033") << hex("0311220233");
        QTest::newRow("no zero") << hex("11223344") << hex("0511223344");
        QTest::newRow("trailing zeros") << hex("11000000") << hex("0211010101");
        QTest::newRow("254 non-zero bytes: one full block, no trailing code")
            << run(0x01, 0xFE) << join(hex("ff"), run(0x01, 0xFE));
        QTest::newRow("zero then 254 non-zero bytes")
            << join(hex("00"), run(0x01, 0xFE)) << join(hex("01ff"), run(0x01, 0xFE));
        QTest::newRow("255 non-zero bytes: full block then a new one")
            << run(0x01, 0xFF) << join(hex("ff"), run(0x01, 0xFE), hex("02ff"));
        QTest::newRow("254 non-zero then a zero")
            << join(run(0x02, 0xFF), hex("00")) << join(hex("ff"), run(0x02, 0xFF), hex("0101"));
        QTest::newRow("253 non-zero, zero, one")
            << join(run(0x03, 0xFF), hex("0001")) << join(hex("fe"), run(0x03, 0xFF), hex("0201"));
        QTest::newRow("508 non-zero bytes: two full blocks")
            << join(run(0x01, 0xFE), run(0x01, 0xFE))
            << join(hex("ff"), run(0x01, 0xFE), hex("ff"), run(0x01, 0xFE));
        QTest::newRow("HELLO seq 0 packet (protocol.md § 5)")
            << hex("01003e2e") << hex("0201033e2e");
    }
    void vectors()
    {
        QFETCH(QByteArray, plain);
        QFETCH(QByteArray, encoded);
        QCOMPARE(cobsEncode(plain).toHex(' '), encoded.toHex(' '));
        QByteArray decoded("stale content is replaced");
        QVERIFY(cobsDecode(encoded, decoded));
        QCOMPARE(decoded.toHex(' '), plain.toHex(' '));
    }

    void malformed_data()
    {
        QTest::addColumn<QByteArray>("encoded");
        QTest::newRow("code points past the end") << hex("051122");
        QTest::newRow("code points one past the end") << hex("03aa");
        QTest::newRow("zero code byte") << hex("00");
        QTest::newRow("zero inside a block") << hex("03aa00");
        QTest::newRow("zero code after a block") << hex("02aa00");
        QTest::newRow("full block cut short") << join(hex("ff"), run(0x01, 0x80));
    }
    void malformed()
    {
        QFETCH(QByteArray, encoded);
        QByteArray decoded;
        QVERIFY(!cobsDecode(encoded, decoded));
    }

    //! Some encoders end a full final block with an extra 0x01; the decoder accepts that
    //! form as the same data (the CRC, not COBS, guards integrity).
    void acceptsTrailingEmptyBlockAfterFullBlock()
    {
        QByteArray decoded;
        QVERIFY(cobsDecode(join(hex("ff"), run(0x01, 0xFE), hex("01")), decoded));
        QCOMPARE(decoded, run(0x01, 0xFE));
    }

    void randomRoundTrip_data()
    {
        QTest::addColumn<int>("length");
        QTest::addColumn<int>("zeroPercent");
        for (const int n : {0, 1, 2, 253, 254, 255, 256, 600})
            for (const int z : {0, 5, 50, 100})
                QTest::addRow("%d bytes, %d%% zeros", n, z) << n << z;
    }
    void randomRoundTrip()
    {
        QFETCH(int, length);
        QFETCH(int, zeroPercent);
        QRandomGenerator rng(quint32(length * 1000 + zeroPercent));
        for (int round = 0; round < 50; ++round) {
            QByteArray plain(length, Qt::Uninitialized);
            for (char &c : plain)
                c = int(rng.bounded(100)) < zeroPercent ? '\0'
                                                        : static_cast<char>(1 + rng.bounded(255));
            const QByteArray encoded = cobsEncode(plain);
            QVERIFY(!encoded.contains('\0'));
            // Standard COBS overhead: one code byte, plus one per further 254-byte run.
            QVERIFY(encoded.size() >= plain.size() + 1);
            QVERIFY(encoded.size() <= plain.size() + 1 + plain.size() / 254);
            QByteArray decoded;
            QVERIFY(cobsDecode(encoded, decoded));
            QCOMPARE(decoded, plain);
        }
    }

    //! Encoding in place (what the frame encoder does) writes exactly cobsEncode()'s bytes,
    //! for every length one block holds and zeros in every position of a machine word.
    void inPlaceEncodingMatches()
    {
        QRandomGenerator rng(7);
        for (int n = 0; n <= int(kCobsBlockBytes); ++n) {
            for (const int zeroPercent : {0, 3, 30, 100}) {
                QByteArray plain(n, Qt::Uninitialized);
                for (char &c : plain)
                    c = int(rng.bounded(100)) < zeroPercent
                            ? '\0'
                            : static_cast<char>(1 + rng.bounded(255));
                QByteArray frame = QByteArray(1, 'x') + plain;
                QCOMPARE(cobsEncodeInPlace(bytesOf(frame)), std::size_t(n + 1));
                QCOMPARE(frame.toHex(' '), cobsEncode(plain).toHex(' '));
            }
        }
        QByteArray tooLong(int(kCobsBlockBytes) + 2, '\x11');
        QCOMPARE(cobsEncodeInPlace(bytesOf(tooLong)), std::size_t(0));
        QCOMPARE(cobsEncodeInPlace({}), std::size_t(0));
    }

    //! Any body without a delimiter (valid or not, full blocks or not) decodes as the textbook
    //! decoder says, into a separate buffer or in place, with room to spare or too little.
    void decodeBodyMatchesReference()
    {
        QRandomGenerator rng(11);
        for (int round = 0; round < 20000; ++round) {
            const int n = int(rng.bounded(300));
            QByteArray encoded(n, Qt::Uninitialized);
            const bool codesFit = rng.bounded(2) == 0; // mostly valid chains, or pure noise
            for (int i = 0; i < n; ++i)
                encoded[i] = static_cast<char>(1 + rng.bounded(255));
            if (codesFit) {
                for (int at = 0; at < n;) {
                    const int code = rng.bounded(8) == 0 ? 0xFF : 1 + int(rng.bounded(40));
                    encoded[at] = static_cast<char>(std::min(code, n - at));
                    at += std::max(1, std::min(code, n - at));
                }
            }
            const qsizetype room = rng.bounded(4) == 0 ? qsizetype(rng.bounded(n + 1)) : n;
            const std::optional<QByteArray> want = referenceDecode(encoded, room);

            QByteArray out(room, '\x55');
            const auto got = cobsDecodeBody(
                {reinterpret_cast<const std::uint8_t *>(encoded.constData()), std::size_t(n)},
                bytesOf(out));
            QCOMPARE(got.has_value(), want.has_value());
            if (got)
                QCOMPARE(out.left(qsizetype(*got)).toHex(' '), want->toHex(' '));

            if (room == n) {
                QByteArray inPlace = encoded;
                const auto same = cobsDecodeBody(bytesOf(inPlace), bytesOf(inPlace));
                QCOMPARE(same.has_value(), want.has_value());
                if (same)
                    QCOMPARE(inPlace.left(qsizetype(*same)).toHex(' '), want->toHex(' '));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestCobs)
#include "tst_cobs.moc"
