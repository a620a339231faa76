// The STS3032 packet layer (servo.md § 1–3): byte-exact packets against hand-computed hex,
// sign-magnitude words, the SI conversions, and the parser's resynchronisation.
#include "firmware/sts3032.h"

#include <QTest>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

using namespace hatpic::fw;

namespace {

std::span<const std::uint8_t> bytesOf(const QByteArray &a)
{
    return {reinterpret_cast<const std::uint8_t *>(a.constData()), std::size_t(a.size())};
}

QByteArray toBytes(std::span<const std::uint8_t> s)
{
    return QByteArray(reinterpret_cast<const char *>(s.data()), qsizetype(s.size()));
}

QByteArray encode(std::uint8_t id, std::uint8_t code, const QByteArray &params)
{
    std::array<std::uint8_t, sts::kMaxPacketBytes> out{};
    const std::size_t n = sts::encodePacket(id, code, bytesOf(params), out);
    return toBytes(std::span<const std::uint8_t>(out.data(), n));
}

//! Feeds `input` byte by byte; returns every packet reported, raw.
QList<QByteArray> parseAll(StsPacketParser &parser, const QByteArray &input)
{
    QList<QByteArray> packets;
    for (const char c : input) {
        bool have = parser.push(std::uint8_t(c));
        while (have) {
            packets.append(toBytes(parser.packetBytes()));
            have = parser.next();
        }
    }
    return packets;
}

// The simulator's quantisation before the bus was emulated (simulateddevice.cpp).
float simulatorTau(double load, double tauLimit)
{
    const double quantum = tauLimit * 1e-3;
    return float(std::clamp(std::round(load / quantum) * quantum, -tauLimit, tauLimit));
}

} // namespace

class TestSts3032 : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void encodesPackets_data();
    void encodesPackets();
    void refusesOversizePackets();
    void signMagnitude_data();
    void signMagnitude();
    void decodesSignMagnitude_data();
    void decodesSignMagnitude();
    void words();
    void positionAndSpeed_data();
    void positionAndSpeed();
    void loadMatchesSimulatorGrid_data();
    void loadMatchesSimulatorGrid();
    void goalTick_data();
    void goalTick();
    void parserResynchronises_data();
    void parserResynchronises();
    void parserReportsOnlyOnLastByte();
    void parserNeverOverflows();
};

void TestSts3032::encodesPackets_data()
{
    QTest::addColumn<int>("id");
    QTest::addColumn<int>("code");
    QTest::addColumn<QByteArray>("params");
    QTest::addColumn<QByteArray>("expected");

    // CHK = ~(ID + LEN + CODE + params) & 0xFF, worked out by hand in the comments.
    // 1+2+1 = 0x04 → FB
    QTest::newRow("PING id 1") << 1 << 0x01 << QByteArray() << QByteArray::fromHex("ffff010201fb");
    // 1+4+2+0x38+6 = 0x45 → BA
    QTest::newRow("READ 6 at 56") << 1 << 0x02 << QByteArray::fromHex("3806")
                                  << QByteArray::fromHex("ffff0104023806ba");
    // 1+4+2+0x38+2 = 0x41 → BE
    QTest::newRow("READ 2 at 56") << 1 << 0x02 << QByteArray::fromHex("3802")
                                  << QByteArray::fromHex("ffff0104023802be");
    // 1+4+2+3+2 = 0x0C → F3
    QTest::newRow("READ model number")
        << 1 << 0x02 << QByteArray::fromHex("0302") << QByteArray::fromHex("ffff0104020302f3");
    // 1+5+3+0x2A+0xE8+0x03 = 0x11E → 1E → E1
    QTest::newRow("WRITE goal 1000")
        << 1 << 0x03 << QByteArray::fromHex("2ae803") << QByteArray::fromHex("ffff0105032ae803e1");
    // 1+5+3+0x2A+0xFF+0x0F = 0x141 → 41 → BE
    QTest::newRow("WRITE goal 4095")
        << 1 << 0x03 << QByteArray::fromHex("2aff0f") << QByteArray::fromHex("ffff0105032aff0fbe");
    // 1+4+3+0x28+1 = 0x31 → CE
    QTest::newRow("WRITE torque enable 1")
        << 1 << 0x03 << QByteArray::fromHex("2801") << QByteArray::fromHex("ffff0104032801ce");
    // 1+4+3+0x28 = 0x30 → CF
    QTest::newRow("WRITE torque enable 0")
        << 1 << 0x03 << QByteArray::fromHex("2800") << QByteArray::fromHex("ffff0104032800cf");
    // 1+4+3+0x21 = 0x29 → D6
    QTest::newRow("WRITE mode 0") << 1 << 0x03 << QByteArray::fromHex("2100")
                                  << QByteArray::fromHex("ffff0104032100d6");
    // 1+5+4+0x2A+0x00+0x08 = 0x3C → C3
    QTest::newRow("REG_WRITE goal 2048")
        << 1 << 0x04 << QByteArray::fromHex("2a0008") << QByteArray::fromHex("ffff0105042a0008c3");
    // 0xFE+2+5 = 0x105 → 05 → FA
    QTest::newRow("ACTION broadcast")
        << 0xFE << 0x05 << QByteArray() << QByteArray::fromHex("fffffe0205fa");
    // SYNC_WRITE goal (2 bytes) to id 1 = 1000 and id 2 = 2048; LEN = (2+1)·2 + 4 = 10.
    // 0xFE+0x0A+0x83+0x2A+2 + 1+0xE8+0x03 + 2+0x00+0x08 = 0x2AD → AD → 52
    QTest::newRow("SYNC_WRITE two goals") << 0xFE << 0x83 << QByteArray::fromHex("2a0201e803020008")
                                          << QByteArray::fromHex("fffffe0a832a0201e80302000852");
    // Status packets share the layout; CODE is the error byte.
    // 1+2+0 = 3 → FC
    QTest::newRow("status, no params")
        << 1 << 0x00 << QByteArray() << QByteArray::fromHex("ffff010200fc");
    // position 1000 (E8 03), speed −10 (0A 80), load −500 (F4 05):
    // 1+8+0+0xE8+0x03+0x0A+0x80+0xF4+0x05 = 0x277 → 77 → 88
    QTest::newRow("status, feedback") << 1 << 0x00 << QByteArray::fromHex("e8030a80f405")
                                      << QByteArray::fromHex("ffff010800e8030a80f40588");
    // 1+2+0x20 = 0x23 → DC
    QTest::newRow("status, overload flag")
        << 1 << 0x20 << QByteArray() << QByteArray::fromHex("ffff010220dc");
}

void TestSts3032::encodesPackets()
{
    QFETCH(int, id);
    QFETCH(int, code);
    QFETCH(QByteArray, params);
    QFETCH(QByteArray, expected);

    QCOMPARE(encode(std::uint8_t(id), std::uint8_t(code), params).toHex(), expected.toHex());
    QCOMPARE(sts::checksum(std::uint8_t(id), std::uint8_t(code), bytesOf(params)),
             std::uint8_t(expected.back()));

    StsPacketParser parser;
    const QList<QByteArray> parsed = parseAll(parser, expected);
    QCOMPARE(parsed.size(), 1);
    QCOMPARE(parsed.front().toHex(), expected.toHex());
}

void TestSts3032::refusesOversizePackets()
{
    std::array<std::uint8_t, sts::kMaxPacketBytes + 8> out{};
    const std::vector<std::uint8_t> tooMany(sts::kMaxParams + 1, 0);
    QCOMPARE(sts::encodePacket(1, sts::kWrite, tooMany, out), std::size_t(0));
    const std::vector<std::uint8_t> most(sts::kMaxParams, 0);
    QCOMPARE(sts::encodePacket(1, sts::kWrite, most, out), sts::kMaxPacketBytes);
    std::array<std::uint8_t, 5> small{};
    QCOMPARE(sts::encodePacket(1, sts::kPing, {}, small), std::size_t(0));
    QCOMPARE(small, (std::array<std::uint8_t, 5>{}));
}

void TestSts3032::signMagnitude_data()
{
    QTest::addColumn<int>("value");
    QTest::addColumn<int>("signBit");
    QTest::addColumn<int>("raw");

    QTest::newRow("bit 15, zero") << 0 << 15 << 0x0000;
    QTest::newRow("bit 15, +1") << 1 << 15 << 0x0001;
    QTest::newRow("bit 15, -1") << -1 << 15 << 0x8001;
    QTest::newRow("bit 15, +1000") << 1000 << 15 << 0x03E8;
    QTest::newRow("bit 15, -1000") << -1000 << 15 << 0x83E8;
    QTest::newRow("bit 15, max") << 32767 << 15 << 0x7FFF;
    QTest::newRow("bit 15, -max") << -32767 << 15 << 0xFFFF;
    QTest::newRow("bit 15, saturates +") << 40000 << 15 << 0x7FFF;
    QTest::newRow("bit 15, saturates -") << -40000 << 15 << 0xFFFF;
    QTest::newRow("bit 15, INT_MIN") << std::numeric_limits<int>::min() << 15 << 0xFFFF;
    QTest::newRow("bit 10, zero") << 0 << 10 << 0x0000;
    QTest::newRow("bit 10, -1") << -1 << 10 << 0x0401;
    QTest::newRow("bit 10, +1000 (100 %)") << 1000 << 10 << 0x03E8;
    QTest::newRow("bit 10, -1000 (-100 %)") << -1000 << 10 << 0x07E8;
    QTest::newRow("bit 10, -500") << -500 << 10 << 0x05F4;
    QTest::newRow("bit 10, max") << 1023 << 10 << 0x03FF;
    QTest::newRow("bit 10, saturates +") << 2000 << 10 << 0x03FF;
    QTest::newRow("bit 10, saturates -") << -2000 << 10 << 0x07FF;
}

void TestSts3032::signMagnitude()
{
    QFETCH(int, value);
    QFETCH(int, signBit);
    QFETCH(int, raw);

    QCOMPARE(int(sts::encodeSignMagnitude(value, unsigned(signBit))), raw);
    const int max = (1 << signBit) - 1;
    QCOMPARE(sts::decodeSignMagnitude(std::uint16_t(raw), unsigned(signBit)),
             std::clamp(value, -max, max));
}

void TestSts3032::decodesSignMagnitude_data()
{
    QTest::addColumn<int>("raw");
    QTest::addColumn<int>("signBit");
    QTest::addColumn<int>("value");

    QTest::newRow("bit 15, -0") << 0x8000 << 15 << 0;
    QTest::newRow("bit 10, -0") << 0x0400 << 10 << 0;
    QTest::newRow("bit 10, bits above the sign ignored") << 0xF801 << 10 << 1;
    QTest::newRow("bit 10, bits above, negative") << 0xFC01 << 10 << -1;
    QTest::newRow("bit 15 read as bit 10") << 0x8001 << 10 << 1;
}

void TestSts3032::decodesSignMagnitude()
{
    QFETCH(int, raw);
    QFETCH(int, signBit);
    QFETCH(int, value);
    QCOMPARE(sts::decodeSignMagnitude(std::uint16_t(raw), unsigned(signBit)), value);
}

void TestSts3032::words()
{
    QCOMPARE(sts::word(0xE8, 0x03), std::uint16_t(1000));
    QCOMPARE(sts::wordBytes(0x83E8), (std::array<std::uint8_t, 2>{0xE8, 0x83}));
    for (int v = 0; v <= 0xFFFF; v += 257) {
        const auto b = sts::wordBytes(std::uint16_t(v));
        QCOMPARE(int(sts::word(b[0], b[1])), v);
    }
}

void TestSts3032::positionAndSpeed_data()
{
    QTest::addColumn<int>("ticks");
    QTest::addColumn<float>("radians");

    // Powers of two times 2π/4096 are exact: the float is that of the exact angle.
    QTest::newRow("center") << 0 << 0.0f;
    QTest::newRow("quarter turn") << 1024 << float(std::numbers::pi / 2);
    QTest::newRow("half turn back") << -2048 << float(-std::numbers::pi);
    QTest::newRow("one turn") << 4096 << float(2 * std::numbers::pi);
    QTest::newRow("one tick") << 1 << float(2 * std::numbers::pi / 4096);
    QTest::newRow("-1000 ticks") << -1000 << float(-1000 * (2 * std::numbers::pi / 4096));
    QTest::newRow("3095 ticks (goal 4095)") << 3095 << float(3095 * (2 * std::numbers::pi / 4096));
}

void TestSts3032::positionAndSpeed()
{
    QFETCH(int, ticks);
    QFETCH(float, radians);
    QCOMPARE(sts::positionToTheta(1000 + ticks, 1000), radians);
    QCOMPARE(sts::positionToTheta(ticks, 0), radians);
    QCOMPARE(sts::speedToOmega(ticks), radians);
}

void TestSts3032::loadMatchesSimulatorGrid_data()
{
    QTest::addColumn<double>("tauLimit");
    QTest::newRow("0.44 N·m (default)") << 0.44;
    QTest::newRow("0.3 N·m") << 0.3;
    QTest::newRow("1 N·m") << 1.0;
    QTest::newRow("0.123 N·m") << 0.123;
}

void TestSts3032::loadMatchesSimulatorGrid()
{
    QFETCH(double, tauLimit);
    // Every register value gives the float the simulator gave for a torque on that step.
    const double quantum = tauLimit * 1e-3;
    for (int load = -sts::kLoadFullScale; load <= sts::kLoadFullScale; ++load)
        QCOMPARE(sts::loadToTorque(load, tauLimit), simulatorTau(load * quantum, tauLimit));
    // Beyond ±100 % the simulator saturated at ±tauLimit; the register saturates at ±1000.
    QCOMPARE(sts::loadToTorque(1000, tauLimit), float(tauLimit));
    QCOMPARE(sts::loadToTorque(-1000, tauLimit), float(-tauLimit));
    QCOMPARE(sts::loadToTorque(1000, tauLimit), simulatorTau(2 * tauLimit, tauLimit));
    QCOMPARE(sts::loadToTorque(1023, tauLimit), float(tauLimit));
    QCOMPARE(sts::loadToTorque(-1023, tauLimit), float(-tauLimit));
}

void TestSts3032::goalTick_data()
{
    QTest::addColumn<double>("theta");
    QTest::addColumn<int>("center");
    QTest::addColumn<int>("goal");

    const double tick = 2 * std::numbers::pi / 4096;
    const double inf = std::numeric_limits<double>::infinity();
    QTest::newRow("zero") << 0.0 << 1000 << 1000;
    QTest::newRow("one tick") << tick << 1000 << 1001;
    QTest::newRow("half tick rounds away from zero") << 0.5 * tick << 1000 << 1001;
    QTest::newRow("minus half tick rounds away") << -0.5 * tick << 1000 << 999;
    QTest::newRow("just under half a tick") << 0.4999 * tick << 1000 << 1000;
    QTest::newRow("quarter turn") << std::numbers::pi / 2 << 1000 << 2024;
    QTest::newRow("lowest tick") << -1000 * tick << 1000 << 0;
    QTest::newRow("clamped below 0") << -1001 * tick << 1000 << 0;
    QTest::newRow("highest tick") << 3095 * tick << 1000 << 4095;
    QTest::newRow("clamped above 4095") << 3096 * tick << 1000 << 4095;
    QTest::newRow("far above") << 100.0 << 1000 << 4095;
    QTest::newRow("+inf") << inf << 1000 << 4095;
    QTest::newRow("-inf") << -inf << 1000 << 0;
    QTest::newRow("NaN holds the center") << std::nan("") << 1000 << 1000;
    QTest::newRow("NaN, center out of range") << std::nan("") << 5000 << 4095;
    QTest::newRow("other center") << tick << 2048 << 2049;
}

void TestSts3032::goalTick()
{
    QFETCH(double, theta);
    QFETCH(int, center);
    QFETCH(int, goal);
    QCOMPARE(sts::thetaToGoalTick(theta, center), goal);
}

void TestSts3032::parserResynchronises_data()
{
    QTest::addColumn<QByteArray>("input");
    QTest::addColumn<QList<QByteArray>>("packets");
    QTest::addColumn<int>("badChecksum");
    QTest::addColumn<int>("badLength");
    QTest::addColumn<int>("skipped");

    const QByteArray ping = QByteArray::fromHex("ffff010200fc");
    const QByteArray feedback = QByteArray::fromHex("ffff010800e8030a80f40588");
    QTest::newRow("clean") << ping + feedback << QList{ping, feedback} << 0 << 0 << 0;
    QTest::newRow("leading garbage")
        << QByteArray::fromHex("0012fe") + ping << QList{ping} << 0 << 0 << 3;
    QTest::newRow("lone FF before header")
        << QByteArray::fromHex("ff00") + ping << QList{ping} << 0 << 0 << 2;
    QTest::newRow("FF preamble") << QByteArray::fromHex("ffff") + ping << QList{ping} << 0 << 0
                                 << 2;
    QTest::newRow("bad checksum, then good")
        << QByteArray::fromHex("ffff010200fd") + ping << QList{ping} << 1 << 0 << 6;
    QTest::newRow("LEN 0, then good")
        << QByteArray::fromHex("ffff0100") + ping << QList{ping} << 0 << 1 << 4;
    QTest::newRow("LEN 1, then good")
        << QByteArray::fromHex("ffff0101") + ping << QList{ping} << 0 << 1 << 4;
    QTest::newRow("LEN too long, then good")
        << QByteArray::fromHex("ffff01c8") + feedback << QList{feedback} << 0 << 1 << 4;
    // A 14-byte candidate whose checksum fails hides a valid packet after its header.
    QTest::newRow("valid packet inside a bad one")
        << QByteArray::fromHex("ffff010a03") + ping + QByteArray::fromHex("000000") + ping
        << QList{ping, ping} << 1 << 0 << 8;
    QTest::newRow("truncated packet, then good")
        << QByteArray::fromHex("ffff0108") + feedback << QList{feedback} << 1 << 0 << 4;
    QTest::newRow("garbage only") << QByteArray::fromHex("000102030405") << QList<QByteArray>{} << 0
                                  << 0 << 6;
}

void TestSts3032::parserResynchronises()
{
    QFETCH(QByteArray, input);
    QFETCH(QList<QByteArray>, packets);
    QFETCH(int, badChecksum);
    QFETCH(int, badLength);
    QFETCH(int, skipped);

    StsPacketParser parser;
    QCOMPARE(parseAll(parser, input), packets);
    QCOMPARE(int(parser.stats().packets), int(packets.size()));
    QCOMPARE(int(parser.stats().badChecksum), badChecksum);
    QCOMPARE(int(parser.stats().badLength), badLength);
    QCOMPARE(int(parser.stats().skippedBytes), skipped);
}

void TestSts3032::parserReportsOnlyOnLastByte()
{
    // Every split position of a packet stream: nothing before a packet's last byte, exactly
    // one packet on it, and what follows a reset is parsed afresh.
    const QByteArray a = QByteArray::fromHex("ffff010800e8030a80f40588");
    const QByteArray b = QByteArray::fromHex("ffff0105032ae803e1");
    const QByteArray stream = a + b;
    for (qsizetype split = 0; split <= stream.size(); ++split) {
        StsPacketParser parser;
        QList<QByteArray> seen;
        for (qsizetype i = 0; i < stream.size(); ++i) {
            if (i == split)
                QCOMPARE(parser.pending(),
                         std::size_t(split < a.size() ? split : split - a.size()));
            const bool have = parser.push(std::uint8_t(stream[i]));
            QCOMPARE(have, i == a.size() - 1 || i == stream.size() - 1);
            if (have) {
                seen.append(toBytes(parser.packetBytes()));
                QVERIFY(!parser.next());
            }
        }
        QCOMPARE(seen, (QList<QByteArray>{a, b}));
    }
    StsPacketParser parser;
    parseAll(parser, a.left(5));
    parser.reset();
    for (qsizetype i = 0; i < b.size(); ++i)
        QCOMPARE(parser.push(std::uint8_t(b[i])), i == b.size() - 1);
    const StsPacket p = parser.packet();
    QCOMPARE(int(p.id), 1);
    QCOMPARE(int(p.code), int(sts::kWrite));
    QCOMPARE(toBytes(p.params).toHex(), QByteArray("2ae803"));
}

void TestSts3032::parserNeverOverflows()
{
    // Long runs of headers with the largest LEN, never completed correctly.
    StsPacketParser parser;
    QByteArray noise;
    for (int i = 0; i < 50; ++i)
        noise += QByteArray::fromHex("ffff01") + char(sts::kMaxParams + 2) +
                 QByteArray(int(sts::kMaxParams) + 1, char(0x11)) + char(0x00);
    QCOMPARE(parseAll(parser, noise).size(), 0);
    QCOMPARE(int(parser.stats().badChecksum), 50);
    QVERIFY(parser.pending() < sts::kMaxPacketBytes);
    const QByteArray ping = QByteArray::fromHex("ffff010200fc");
    QCOMPARE(parseAll(parser, ping), QList<QByteArray>{ping});
}

QTEST_GUILESS_MAIN(TestSts3032)
#include "tst_sts3032.moc"
