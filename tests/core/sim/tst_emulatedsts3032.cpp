// EmulatedSts3032 at the byte level (servo.md § 1–2, docs/simulator.md § 3): register map,
// READ/WRITE/REG_WRITE/ACTION/SYNC_WRITE, silence towards other ids and broadcasts, torque
// off, and a load noise that replays the simulator's seeded sequence.
#include "sim/emulatedsts3032.h"
#include "sim/servoplant.h"

#include <QTest>

#include <array>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <random>

using namespace hatpic;
namespace sts = fw::sts;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::span<const std::uint8_t> bytesOf(const QByteArray &a)
{
    return {reinterpret_cast<const std::uint8_t *>(a.constData()), std::size_t(a.size())};
}

QByteArray bytes(std::initializer_list<int> values)
{
    QByteArray a;
    for (const int v : values)
        a.append(char(v));
    return a;
}

QByteArray packet(std::uint8_t id, std::uint8_t code, const QByteArray &params)
{
    std::array<std::uint8_t, sts::kMaxPacketBytes> out{};
    const std::size_t n = sts::encodePacket(id, code, bytesOf(params), out);
    return QByteArray(reinterpret_cast<const char *>(out.data()), qsizetype(n));
}

QByteArray take(EmulatedSts3032 &servo)
{
    std::array<std::uint8_t, 1024> out{};
    const std::size_t n = servo.takeOutput(out);
    return QByteArray(reinterpret_cast<const char *>(out.data()), qsizetype(n));
}

QByteArray send(EmulatedSts3032 &servo, const QByteArray &bytes)
{
    servo.receive(bytesOf(bytes));
    return take(servo);
}

QByteArray readPacket(std::uint8_t id, std::uint8_t addr, std::uint8_t count)
{
    return packet(id, sts::kRead, bytes({addr, count}));
}

int word(const EmulatedSts3032 &servo, std::uint8_t addr, unsigned signBit)
{
    return sts::decodeSignMagnitude(sts::word(servo.reg(addr), servo.reg(addr + 1)), signBit);
}

} // namespace

class TestEmulatedSts3032 : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void staticRegisters();
    void presentPosition_data();
    void presentPosition();
    void speedAndLoadFollowThePlant();
    void answersPingAndRead();
    void writeGoalMovesThePlant();
    void readOnlyAndOutOfRange();
    void otherIdsAndBroadcastsGetNoAnswer();
    void regWriteAndAction();
    void syncWrite();
    void torqueOff();
    void badPacketsCounted();
    void anyChunking();
    void seededNoiseReplaysTheSimulator_data();
    void seededNoiseReplaysTheSimulator();
};

void TestEmulatedSts3032::staticRegisters()
{
    ServoPlant plant(0.44, 0.25);
    EmulatedSts3032 servo(plant, {});
    QCOMPARE(sts::word(servo.reg(3), servo.reg(4)), EmulatedSts3032::kDefaultModelNumber);
    QCOMPARE(int(servo.reg(sts::kRegMode)), 0);
    QCOMPARE(int(servo.reg(sts::kRegTorqueEnable)), 1); // mirrors the plant (on by default)
    QCOMPARE(int(servo.reg(sts::kRegPresentVoltage)), 60);
    QCOMPARE(int(servo.reg(sts::kRegPresentTemperature)), 30);
    const int ticks = int(std::round(0.25 * 4096 / kTwoPi));
    QCOMPARE(word(servo, sts::kRegGoalPosition, 15), 1000 + ticks);
    QCOMPARE(word(servo, sts::kRegPresentPosition, 15), 1000 + ticks);
    QCOMPARE(plant.command(), 0.25); // binding changes nothing in the plant
}

void TestEmulatedSts3032::presentPosition_data()
{
    QTest::addColumn<double>("theta");
    QTest::addColumn<int>("position");
    QTest::addColumn<int>("raw");

    const double tick = kTwoPi / 4096;
    QTest::newRow("center") << 0.0 << 1000 << 0x03E8;
    QTest::newRow("one tick") << tick << 1001 << 0x03E9;
    QTest::newRow("half tick rounds away") << 0.5 * tick << 1001 << 0x03E9;
    QTest::newRow("tick 0") << -1000 * tick << 0 << 0x0000;
    QTest::newRow("below 0: sign bit") << -1001 * tick << -1 << 0x8001;
    QTest::newRow("two turns back") << -2 * kTwoPi << -7192 << 0x9C18;
    QTest::newRow("beyond a turn: not wrapped") << 1.5 * kTwoPi << 7144 << 0x1BE8;
    QTest::newRow("saturates") << 10 * kTwoPi << 32767 << 0x7FFF;
}

void TestEmulatedSts3032::presentPosition()
{
    QFETCH(double, theta);
    QFETCH(int, position);
    QFETCH(int, raw);
    ServoPlant plant(0.44, theta);
    EmulatedSts3032 servo(plant, {});
    const QByteArray reply = send(servo, readPacket(1, 56, 2));
    QCOMPARE(reply.toHex(), packet(1, 0, bytes({raw & 0xFF, raw >> 8})).toHex());
    QCOMPARE(word(servo, 56, 15), position);
}

void TestEmulatedSts3032::speedAndLoadFollowThePlant()
{
    ServoPlant plant(0.44, 0.0);
    EmulatedSts3032 servo(plant, {});
    plant.setCommand(0.8);
    for (int i = 0; i < 400; ++i) {
        plant.step(1e-4, -0.02);
        if (i % 7 != 0)
            continue;
        const QByteArray reply = send(servo, readPacket(1, 56, 8));
        QCOMPARE(reply.size(), 14);
        QCOMPARE(word(servo, 58, 15), int(std::round(plant.omega() * 4096 / kTwoPi)));
        const double counts = std::round(plant.motorTorque() / (0.44 * 1e-3));
        QCOMPARE(word(servo, 60, 10), int(std::clamp(counts, -1000.0, 1000.0)));
        QCOMPARE(reply.mid(5, 8).toHex(),
                 bytes({servo.reg(56), servo.reg(57), servo.reg(58), servo.reg(59), servo.reg(60),
                        servo.reg(61), 60, 30})
                     .toHex());
    }
    // At the torque limit the register reads −100 %.
    plant.setCommand(-3.0);
    plant.step(1e-4, 0);
    send(servo, readPacket(1, 60, 2));
    QCOMPARE(word(servo, 60, 10), -1000);
}

void TestEmulatedSts3032::answersPingAndRead()
{
    ServoPlant plant(0.44);
    EmulatedSts3032 servo(plant, {});
    QCOMPARE(send(servo, QByteArray::fromHex("ffff010201fb")).toHex(), QByteArray("ffff010200fc"));
    QCOMPARE(send(servo, QByteArray::fromHex("ffff0104020302f3")),
             packet(1, 0, QByteArray::fromHex("0903")));
    QCOMPARE(int(servo.stats().answered), 2);
}

void TestEmulatedSts3032::writeGoalMovesThePlant()
{
    ServoPlant plant(0.44);
    EmulatedSts3032 servo(plant, {});
    // WRITE goal 2048 at 42 (1+5+3+0x2A+0x08 = 0x3B → C4) → status, plant goal 1048 ticks.
    QCOMPARE(send(servo, QByteArray::fromHex("ffff0105032a0008c4")).toHex(),
             QByteArray("ffff010200fc"));
    QCOMPARE(plant.command(), 1048 * (kTwoPi / 4096));
    QCOMPARE(send(servo, QByteArray::fromHex("ffff0105032ae803e1")).toHex(),
             QByteArray("ffff010200fc"));
    QCOMPARE(plant.command(), 0.0);
    // Goal time, speed, acceleration and mode are stored, and only stored.
    send(servo, packet(1, sts::kWrite, QByteArray::fromHex("2905")));
    send(servo, packet(1, sts::kWrite, QByteArray::fromHex("2c0a000c00")));
    send(servo, packet(1, sts::kWrite, QByteArray::fromHex("2100")));
    QCOMPARE(int(servo.reg(41)), 5);
    QCOMPARE(word(servo, 44, 15), 10);
    QCOMPARE(word(servo, 46, 15), 12);
    QCOMPARE(plant.command(), 0.0);
}

void TestEmulatedSts3032::readOnlyAndOutOfRange()
{
    ServoPlant plant(0.44);
    EmulatedSts3032 servo(plant, {});
    QCOMPARE(send(servo, packet(1, sts::kWrite, QByteArray::fromHex("03ffff"))).toHex(),
             QByteArray("ffff010200fc"));
    QCOMPARE(sts::word(servo.reg(3), servo.reg(4)), EmulatedSts3032::kDefaultModelNumber);
    send(servo, packet(1, sts::kWrite, QByteArray::fromHex("3e00")));
    QCOMPARE(int(servo.reg(62)), 60);
    // Refused, no answer: past address 255, zero count, wrong parameter counts, unknown code.
    QCOMPARE(send(servo, readPacket(1, 250, 10)), QByteArray());
    QCOMPARE(send(servo, readPacket(1, 56, 0)), QByteArray());
    QCOMPARE(send(servo, packet(1, sts::kRead, QByteArray::fromHex("38"))), QByteArray());
    QCOMPARE(send(servo, packet(1, sts::kWrite, QByteArray::fromHex("2a"))), QByteArray());
    QCOMPARE(send(servo, packet(1, sts::kWrite, QByteArray(10, char(0)).prepend(char(250)))),
             QByteArray());
    QCOMPARE(send(servo, packet(1, 0x42, QByteArray())), QByteArray());
    QCOMPARE(int(servo.stats().refused), 6);
}

void TestEmulatedSts3032::otherIdsAndBroadcastsGetNoAnswer()
{
    ServoPlant plant(0.44);
    EmulatedSts3032 servo(plant, {});
    QCOMPARE(send(servo, QByteArray::fromHex("ffff020201fa")), QByteArray()); // PING id 2
    QCOMPARE(send(servo, readPacket(2, 56, 6)), QByteArray());
    QCOMPARE(send(servo, packet(2, sts::kWrite, QByteArray::fromHex("2a0008"))), QByteArray());
    QCOMPARE(plant.command(), 0.0);
    QCOMPARE(send(servo, packet(0xFE, sts::kPing, {})), QByteArray());
    QCOMPARE(send(servo, readPacket(0xFE, 56, 6)), QByteArray());
    QCOMPARE(int(servo.stats().ignored), 5);
    // A broadcast WRITE is obeyed silently.
    QCOMPARE(send(servo, packet(0xFE, sts::kWrite, QByteArray::fromHex("2a0008"))), QByteArray());
    QCOMPARE(plant.command(), 1048 * (kTwoPi / 4096));
    QCOMPARE(int(servo.stats().answered), 0);
    QCOMPARE(int(servo.stats().received), 6);
}

void TestEmulatedSts3032::regWriteAndAction()
{
    ServoPlant plant(0.44);
    EmulatedSts3032 servo(plant, {});
    QCOMPARE(send(servo, QByteArray::fromHex("ffff0105042a0008c3")).toHex(),
             QByteArray("ffff010200fc"));
    QCOMPARE(plant.command(), 0.0); // registered, not applied
    QCOMPARE(send(servo, QByteArray::fromHex("fffffe0205fa")), QByteArray());
    QCOMPARE(plant.command(), 1048 * (kTwoPi / 4096));
    // ACTION addressed to the servo is answered; with nothing registered it changes nothing.
    QCOMPARE(send(servo, packet(1, sts::kAction, {})).toHex(), QByteArray("ffff010200fc"));
    QCOMPARE(plant.command(), 1048 * (kTwoPi / 4096));
}

void TestEmulatedSts3032::syncWrite()
{
    ServoPlant plant(0.44);
    EmulatedSts3032::Config config;
    config.id = 2;
    EmulatedSts3032 servo(plant, config);
    // Goals: id 1 → 1000, id 2 → 2048; never answered.
    QCOMPARE(send(servo, QByteArray::fromHex("fffffe0a832a0201e80302000852")), QByteArray());
    QCOMPARE(word(servo, 42, 15), 2048);
    QCOMPARE(plant.command(), 1048 * (kTwoPi / 4096));
    QCOMPARE(send(servo, packet(0xFE, sts::kSyncWrite, QByteArray::fromHex("2a0201e803"))),
             QByteArray());
    QCOMPARE(word(servo, 42, 15), 2048);
    // Groups that do not divide evenly are refused.
    send(servo, packet(0xFE, sts::kSyncWrite, QByteArray::fromHex("2a0202e8")));
    QCOMPARE(int(servo.stats().refused), 1);
}

void TestEmulatedSts3032::torqueOff()
{
    ServoPlant plant(0.44, 0.0);
    EmulatedSts3032 servo(plant, {});
    plant.setCommand(0.5);
    plant.step(1e-4, 0);
    QVERIFY(plant.motorTorque() != 0);
    QCOMPARE(send(servo, QByteArray::fromHex("ffff0104032800cf")).toHex(),
             QByteArray("ffff010200fc"));
    QVERIFY(!plant.torqueEnabled());
    const double omega = plant.omega();
    for (int i = 0; i < 100; ++i) {
        plant.step(1e-4, 0);
        QCOMPARE(plant.motorTorque(), 0.0);
    }
    QVERIFY(std::abs(plant.omega()) < std::abs(omega)); // friction alone slows it
    send(servo, readPacket(1, 60, 2));
    QCOMPARE(word(servo, 60, 10), 0);
    send(servo, QByteArray::fromHex("ffff0104032801ce"));
    QVERIFY(plant.torqueEnabled());
}

void TestEmulatedSts3032::badPacketsCounted()
{
    ServoPlant plant(0.44);
    EmulatedSts3032 servo(plant, {});
    QCOMPARE(send(servo, QByteArray::fromHex("ffff010201fa")), QByteArray()); // checksum
    QCOMPARE(send(servo, QByteArray::fromHex("ffff0101")), QByteArray());     // LEN
    QCOMPARE(send(servo, QByteArray::fromHex("00ffff010201fb")).toHex(),
             QByteArray("ffff010200fc"));
    QCOMPARE(int(servo.stats().badPackets), 2);
    QCOMPARE(int(servo.stats().answered), 1);
}

void TestEmulatedSts3032::anyChunking()
{
    const QByteArray stream = QByteArray::fromHex("ffff010201fb") + readPacket(1, 56, 6) +
                              QByteArray::fromHex("ffff0105032ae803e1") +
                              QByteArray::fromHex("fffffe0205fa") + readPacket(1, 62, 2);
    ServoPlant reference(0.44, 0.3);
    EmulatedSts3032 whole(reference, {});
    const QByteArray expected = send(whole, stream);
    QCOMPARE(int(whole.stats().answered), 4);
    for (qsizetype split = 0; split <= stream.size(); ++split) {
        ServoPlant plant(0.44, 0.3);
        EmulatedSts3032 servo(plant, {});
        servo.receive(bytesOf(stream.left(split)));
        servo.receive(bytesOf(stream.mid(split)));
        QCOMPARE(take(servo).toHex(), expected.toHex());
    }
}

void TestEmulatedSts3032::seededNoiseReplaysTheSimulator_data()
{
    QTest::addColumn<double>("sigma");
    QTest::addColumn<quint64>("seed");
    QTest::newRow("0.01 N·m, seed 1") << 0.01 << quint64(1);
    QTest::newRow("0.05 N·m, seed 99") << 0.05 << quint64(99);
    QTest::newRow("no noise") << 0.0 << quint64(1);
}

void TestEmulatedSts3032::seededNoiseReplaysTheSimulator()
{
    QFETCH(double, sigma);
    QFETCH(quint64, seed);
    EmulatedSts3032::Config config;
    config.noise = sigma;
    config.seed = seed;
    ServoPlant plant(0.44, 0.0);
    plant.setCommand(0.05);
    EmulatedSts3032 servo(plant, config);
    EmulatedSts3032 twin(plant, config);
    // SimulatedDevice::measureTau: one normal draw per measurement.
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise{0.0, 1.0};
    for (int cycle = 0; cycle < 300; ++cycle) {
        plant.step(1e-4, 0.01);
        if (cycle % 3 == 0) // reads that miss the load register draw nothing
            send(servo, readPacket(1, 56, 4));
        const QByteArray a = send(servo, readPacket(1, 56, 6));
        QCOMPARE(send(twin, readPacket(1, 56, 6)), a);
        double load = plant.motorTorque();
        if (sigma > 0)
            load += sigma * noise(rng);
        const double counts = std::clamp(std::round(load / (0.44 * 1e-3)), -1000.0, 1000.0);
        QCOMPARE(word(servo, 60, 10), int(counts));
    }
}

QTEST_GUILESS_MAIN(TestEmulatedSts3032)
#include "tst_emulatedsts3032.moc"
