// StsBus (servo.md § 1): against a scripted ServoPort for every kind of bad reply (counted by
// kind, never acted on as data), half-duplex echo, broadcast, and the emulated STS3032.
#include "stsbustest.h"

#include "firmware/stsactuator.h"
#include "firmware/stsbus.h"

#include <QTest>

#include <array>

using namespace hatpic;
using namespace ststest;
using fw::StsBus;
using fw::StsBusError;
namespace sts = fw::sts;

Q_DECLARE_METATYPE(hatpic::fw::StsBusError)

class TestStsBus : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void readReplies_data();
    void readReplies();
    void discardsStaleInput();
    void writeAndPing();
    void broadcastAwaitsNothing();
    void rejectsImpossibleRequests();
    void emulatedBus();
    void emulatedBusWithEcho();
    void missingServoTimesOut();
};

void TestStsBus::readReplies_data()
{
    QTest::addColumn<QByteArray>("reply");
    QTest::addColumn<StsBusError>("error");
    QTest::addColumn<int>("echoes");

    const QByteArray ok = kFeedback;
    QTest::newRow("good") << ok << StsBusError::None << 0;
    QTest::newRow("echo, then reply") << kRead6 + ok << StsBusError::None << 1;
    QTest::newRow("noise, then reply") << QByteArray::fromHex("00") + ok << StsBusError::None << 0;
    QTest::newRow("missing") << QByteArray() << StsBusError::Timeout << 0;
    QTest::newRow("echo only") << kRead6 << StsBusError::Timeout << 1;
    QTest::newRow("short: cut after 7 bytes") << ok.left(7) << StsBusError::Short << 0;
    QTest::newRow("short: header only") << ok.left(2) << StsBusError::Short << 0;
    QTest::newRow("short: echo, then cut reply") << kRead6 + ok.left(11) << StsBusError::Short << 1;
    // Valid packets of the wrong size: 2 params (1+4+0+0xE8+0x03 = 0xF0 → 0F), 8 params.
    QTest::newRow("short: two params")
        << QByteArray::fromHex("ffff010400e8030f") << StsBusError::Short << 0;
    QTest::newRow("corrupt: eight params")
        << QByteArray::fromHex("ffff010a00e8030a80f405000086") << StsBusError::Corrupt << 0;
    QTest::newRow("corrupt: checksum")
        << QByteArray::fromHex("ffff010800e8030a80f40589") << StsBusError::Corrupt << 0;
    QTest::newRow("corrupt: flipped data bit")
        << QByteArray::fromHex("ffff010800e9030a80f40588") << StsBusError::Corrupt << 0;
    QTest::newRow("corrupt: LEN 1")
        << QByteArray::fromHex("ffff010100e8030a80f40588") << StsBusError::Corrupt << 0;
    // Id 2: 2+8+0+… = 0x278 → 78 → 87
    QTest::newRow("foreign id") << QByteArray::fromHex("ffff020800e8030a80f40587")
                                << StsBusError::ForeignId << 0;
}

void TestStsBus::readReplies()
{
    QFETCH(QByteArray, reply);
    QFETCH(StsBusError, error);
    QFETCH(int, echoes);

    ScriptedPort port;
    port.script = {reply};
    StsBus bus(port, 700);
    std::array<std::uint8_t, 6> out;
    out.fill(0xAA);
    const bool ok = bus.read(1, sts::kRegPresentPosition, out);

    QCOMPARE(port.writes, QList<QByteArray>{kRead6});
    QCOMPARE(port.lastTimeoutUs, std::uint32_t(700));
    QCOMPARE(ok, error == StsBusError::None);
    QCOMPARE(bus.lastError(), error);
    const fw::StsBusStats &s = bus.stats();
    QCOMPARE(int(s.requests), 1);
    QCOMPARE(int(s.echoesSkipped), echoes);
    QCOMPARE(int(s.replies), ok ? 1 : 0);
    QCOMPARE(int(s.timeouts), error == StsBusError::Timeout ? 1 : 0);
    QCOMPARE(int(s.shortReplies), error == StsBusError::Short ? 1 : 0);
    QCOMPARE(int(s.corrupt), error == StsBusError::Corrupt ? 1 : 0);
    QCOMPARE(int(s.foreignId), error == StsBusError::ForeignId ? 1 : 0);
    QCOMPARE(int(s.errors()), ok ? 0 : 1);
    if (ok) {
        QCOMPARE(toBytes(out).toHex(), QByteArray("e8030a80f405"));
    } else {
        QCOMPARE(toBytes(out), QByteArray(6, char(0xAA))); // never acted on as data
    }
    QVERIFY(port.rx.isEmpty() || !ok); // nothing left for the next transaction on success
}

void TestStsBus::discardsStaleInput()
{
    ScriptedPort port;
    port.rx = QByteArray::fromHex("ffff010800000000000000f6"); // an old, valid reply
    port.script = {kFeedback};
    StsBus bus(port);
    std::array<std::uint8_t, 6> out{};
    QVERIFY(bus.read(1, sts::kRegPresentPosition, out));
    QCOMPARE(port.discards, 1);
    QCOMPARE(toBytes(out).toHex(), QByteArray("e8030a80f405"));
}

void TestStsBus::writeAndPing()
{
    ScriptedPort port;
    // A status error byte (0x20, overload) is data, not a bus error.
    port.script = {QByteArray::fromHex("ffff010200fc"), QByteArray::fromHex("ffff010220dc")};
    StsBus bus(port);
    QVERIFY(bus.ping(1));
    const std::array<std::uint8_t, 2> goal{0xE8, 0x03};
    QVERIFY(bus.write(1, sts::kRegGoalPosition, goal));
    QCOMPARE(port.writes, (QList<QByteArray>{QByteArray::fromHex("ffff010201fb"),
                                             QByteArray::fromHex("ffff0105032ae803e1")}));
    QCOMPARE(int(bus.stats().replies), 2);
    QCOMPARE(int(bus.stats().statusErrors), 1);
    QCOMPARE(int(bus.stats().lastStatusError), 0x20);

    // A reply with params to a WRITE is not the expected status packet.
    port.script = {kFeedback};
    QVERIFY(!bus.write(1, sts::kRegGoalPosition, goal));
    QCOMPARE(bus.lastError(), StsBusError::Corrupt);
}

void TestStsBus::broadcastAwaitsNothing()
{
    ScriptedPort port;
    port.script = {QByteArray::fromHex("ffff010200fc")}; // a servo that should not answer
    StsBus bus(port);
    QVERIFY(bus.action(sts::kBroadcastId));
    QCOMPARE(port.writes, QList<QByteArray>{QByteArray::fromHex("fffffe0205fa")});
    QCOMPARE(port.reads, 0);
    const std::array<std::uint8_t, 6> groups{1, 0xE8, 0x03, 2, 0x00, 0x08};
    QVERIFY(bus.syncWrite(sts::kRegGoalPosition, 2, groups));
    QCOMPARE(port.writes.back().toHex(), QByteArray("fffffe0a832a0201e80302000852"));
    const std::array<std::uint8_t, 1> off{0};
    QVERIFY(bus.write(sts::kBroadcastId, sts::kRegTorqueEnable, off));
    QCOMPARE(port.reads, 0);
    QCOMPARE(int(bus.stats().broadcasts), 3);
    QCOMPARE(int(bus.stats().errors()), 0);
}

void TestStsBus::rejectsImpossibleRequests()
{
    ScriptedPort port;
    StsBus bus(port);
    std::array<std::uint8_t, 2> out{};
    QVERIFY(!bus.ping(sts::kBroadcastId));
    QVERIFY(!bus.read(sts::kBroadcastId, 56, out));
    QVERIFY(!bus.read(1, 56, {}));
    std::array<std::uint8_t, sts::kMaxParams> big{};
    QVERIFY(!bus.write(1, 0, big));
    QVERIFY(!bus.syncWrite(42, 2, std::span<const std::uint8_t>(big.data(), 4)));
    // Found by fuzz_sts_bus: id 0xFF went on the wire as FF FF FF …, which every servo reads as
    // preamble, and the call then waited out its timeout.
    const std::array<std::uint8_t, 1> one{0};
    QVERIFY(!bus.write(0xFF, 0, one));
    QVERIFY(!bus.regWrite(0xFF, 0, one));
    QVERIFY(!bus.ping(0xFF));
    QVERIFY(!bus.read(0xFF, 56, out));
    QVERIFY(!bus.action(0xFF));
    QCOMPARE(bus.lastError(), StsBusError::Rejected);
    QCOMPARE(int(bus.stats().rejected), 10);
    QCOMPARE(int(bus.stats().errors()), 0);
    QVERIFY(port.writes.isEmpty());
}

void TestStsBus::emulatedBus()
{
    Rig rig(0.5);
    QVERIFY(rig.bus.ping(1));
    std::array<std::uint8_t, 2> model{};
    QVERIFY(rig.bus.read(1, sts::kRegModelNumber, model));
    QCOMPARE(sts::word(model[0], model[1]), EmulatedSts3032::kDefaultModelNumber);
    const std::array<std::uint8_t, 2> goal = sts::wordBytes(2000);
    QVERIFY(rig.bus.write(1, sts::kRegGoalPosition, goal));
    QCOMPARE(rig.plant.command(), (2000 - 1000) * kTwoPi / 4096);
    QVERIFY(rig.bus.regWrite(1, sts::kRegGoalPosition, sts::wordBytes(1500)));
    QCOMPARE(rig.plant.command(), (2000 - 1000) * kTwoPi / 4096);
    QVERIFY(rig.bus.action(sts::kBroadcastId));
    QCOMPARE(rig.plant.command(), (1500 - 1000) * kTwoPi / 4096);
    QCOMPARE(int(rig.bus.stats().errors()), 0);
    QCOMPARE(int(rig.servo.stats().answered), 4);
}

void TestStsBus::emulatedBusWithEcho()
{
    Rig rig(0.5);
    rig.port.setEcho(true);
    std::array<std::uint8_t, 6> out{};
    QVERIFY(rig.bus.read(1, sts::kRegPresentPosition, out));
    QVERIFY(rig.bus.ping(1));
    QVERIFY(rig.bus.action(sts::kBroadcastId)); // the echo of a broadcast is discarded next time
    QVERIFY(rig.bus.write(1, sts::kRegGoalPosition, sts::wordBytes(1200)));
    QCOMPARE(int(rig.bus.stats().echoesSkipped), 3);
    QCOMPARE(int(rig.bus.stats().errors()), 0);
    QCOMPARE(sts::decodeSignMagnitude(sts::word(out[0], out[1]), 15),
             1000 + int(std::round(0.5 * 4096 / kTwoPi)));
}

void TestStsBus::missingServoTimesOut()
{
    EmulatedSts3032::Config config;
    config.id = 2;
    Rig rig(0.0, config);
    fw::StsActuator<double> actuator(rig.bus, {});
    double theta = 42;
    QVERIFY(!actuator.start(theta));
    QCOMPARE(theta, 42.0);
    QCOMPARE(rig.bus.lastError(), StsBusError::Timeout);
    QCOMPARE(int(rig.bus.stats().timeouts), 1);
    QCOMPARE(int(rig.servo.stats().ignored), 1);
    QCOMPARE(int(rig.servo.stats().answered), 0);
}

QTEST_GUILESS_MAIN(TestStsBus)
#include "tst_stsbus.moc"
