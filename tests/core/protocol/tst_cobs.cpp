// Consistent Overhead Byte Stuffing of protocol v2 (protocol.md § 2).
#include "protocol/v2codec.h"

#include <QRandomGenerator>
#include <QTest>

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
};

QTEST_GUILESS_MAIN(TestCobs)
#include "tst_cobs.moc"
