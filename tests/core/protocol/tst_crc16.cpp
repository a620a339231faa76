// CRC-16/CCITT-FALSE of protocol v2 (protocol.md § 2).
#include "protocol/v2codec.h"

#include <QRandomGenerator>
#include <QTest>

using namespace hatpic::v2;

namespace {

//! Bit-at-a-time reference, written straight from the parameters (poly 0x1021, init 0xFFFF,
//! MSB first, no reflection, xorout 0), to check the table-driven implementation.
quint16 referenceCrc(QByteArrayView data)
{
    quint16 crc = 0xFFFF;
    for (const char c : data) {
        crc ^= static_cast<quint16>(static_cast<quint8>(c) << 8);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 0x8000) ? static_cast<quint16>((crc << 1) ^ 0x1021)
                                 : static_cast<quint16>(crc << 1);
    }
    return crc;
}

} // namespace

class TestCrc16 : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void knownValues_data()
    {
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<quint16>("crc");
        QTest::newRow("check value 123456789") << QByteArray("123456789") << quint16(0x29B1);
        QTest::newRow("empty is the init value") << QByteArray() << quint16(0xFFFF);
        QTest::newRow("single A") << QByteArray("A") << quint16(0xB915);
        QTest::newRow("single zero byte") << QByteArray(1, '\0') << quint16(0xE1F0);
        // The packets of protocol.md § 5 carry their CRC little-endian in the last two bytes.
        QTest::newRow("HELLO seq 0 packet") << QByteArray::fromHex("0100") << quint16(0x2E3E);
        QTest::newRow("PING seq 4 packet")
            << QByteArray::fromHex("0704efbeadde") << quint16(0xBB3C);
    }
    void knownValues()
    {
        QFETCH(QByteArray, data);
        QFETCH(quint16, crc);
        QCOMPARE(crc16(data), crc);
        QCOMPARE(referenceCrc(data), crc);
    }

    void matchesBitwiseReference_data()
    {
        QTest::addColumn<int>("length");
        for (const int n : {1, 2, 3, 7, 8, 9, 15, 16, 17, 28, 29, 244, 1000})
            QTest::addRow("%d random bytes", n) << n;
    }
    void matchesBitwiseReference()
    {
        QFETCH(int, length);
        QRandomGenerator rng(0xC0FFEEu + quint32(length));
        for (int round = 0; round < 200; ++round) {
            QByteArray data(length, Qt::Uninitialized);
            for (char &c : data)
                c = static_cast<char>(rng.bounded(256));
            QCOMPARE(crc16(data), referenceCrc(data));
        }
    }

    //! A non-reflected CRC with xorout 0 leaves residue 0 after its own value, big-endian.
    void residueIsZero_data() { matchesBitwiseReference_data(); }
    void residueIsZero()
    {
        QFETCH(int, length);
        QRandomGenerator rng(0xBEEFu + quint32(length));
        QByteArray data(length, Qt::Uninitialized);
        for (char &c : data)
            c = static_cast<char>(rng.bounded(256));
        const quint16 crc = crc16(data);
        data.append(static_cast<char>(crc >> 8));
        data.append(static_cast<char>(crc & 0xFF));
        QCOMPARE(crc16(data), quint16(0));
    }

    //! Every single-bit error in a packet changes the CRC (guaranteed for any CRC).
    void detectsEverySingleBitError()
    {
        const QByteArray packet = QByteArray::fromHex("90070000e8030000cdcc4c3d");
        const quint16 good = crc16(packet);
        for (int i = 0; i < packet.size(); ++i) {
            for (int bit = 0; bit < 8; ++bit) {
                QByteArray damaged = packet;
                damaged[i] = static_cast<char>(damaged[i] ^ (1 << bit));
                QVERIFY2(crc16(damaged) != good,
                         qPrintable(QStringLiteral("byte %1 bit %2").arg(i).arg(bit)));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestCrc16)
#include "tst_crc16.moc"
