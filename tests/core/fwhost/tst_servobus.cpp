// hatpic-servo-sim with several servos on one bus (issue 36: the IMU branch's four), driven
// through a real pty the way hatpic-fw-host drives a servo: the firmware's own bus code
// (fw::StsBus) over SerialServoPort. Each id answers for itself, a broadcast reaches them all,
// each knob moves on its own, and a count or id range that cannot be is refused.
#include "firmware/sts3032.h"
#include "firmware/stsbus.h"
#include "fwhost/serialservoport.h"
#include "fwhosttest.h"

#include <QTest>

#include <cstdint>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

QString servoSim()
{
    return QStringLiteral(HATPIC_SERVO_SIM_PATH);
}

//! A register word as the STS3032 stores it: little-endian, sign in bit `signBit`.
int word(const std::uint8_t *bytes, int signBit)
{
    const int raw = bytes[0] | (bytes[1] << 8);
    const int magnitude = raw & ((1 << signBit) - 1);
    return (raw & (1 << signBit)) ? -magnitude : magnitude;
}

struct Feedback
{
    int position = 0; //!< [tick]
    int load = 0;     //!< [0.1 %]
};

std::optional<Feedback> feedbackOf(fw::StsBus &bus, std::uint8_t id)
{
    std::uint8_t bytes[fw::sts::kFeedbackBytes]{};
    if (!bus.read(id, fw::sts::kRegPresentPosition, bytes))
        return std::nullopt;
    return Feedback{word(bytes, 15), word(bytes + 4, 10)};
}

} // namespace

class TestServoBus : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void fourServosOnOneBus()
    {
        PtyProgram sim(servoSim(), {u"--servos"_s, u"4"_s, u"--hand-3"_s, u"const:0.05"_s});
        QVERIFY2(!sim.path().isEmpty(), qPrintable(sim.errors()));
        QTRY_VERIFY(sim.errors().contains(u"STS3032 id 4, center tick 1000, hand idle"_s));
        QVERIFY(sim.errors().contains(u"STS3032 id 3, center tick 1000, hand const:0.05"_s));
        SerialServoPort port;
        QCOMPARE(port.open(sim.path(), 1000000), QString());
        fw::StsBus bus(port, 100000); // patient: a loaded machine's pty, not a timing test

        for (std::uint8_t id = 1; id <= 4; ++id)
            QVERIFY2(bus.ping(id), qPrintable(QString::number(id)));
        QVERIFY(!bus.ping(5)); // no such servo: silence, as on a real bus
        QCOMPARE(bus.lastError(), fw::StsBusError::Timeout);

        // One SYNC_WRITE switches every torque off, another on again (broadcasts: nobody
        // answers, every servo obeys).
        const std::uint8_t off[] = {1, 0, 2, 0, 3, 0, 4, 0};
        QVERIFY(bus.syncWrite(fw::sts::kRegTorqueEnable, 1, off));
        for (int id = 1; id <= 4; ++id)
            QTRY_VERIFY(sim.errors().contains(u"id %1 torque off"_s.arg(id)));
        const std::uint8_t on[] = {1, 1, 2, 1, 3, 1, 4, 1};
        QVERIFY(bus.syncWrite(fw::sts::kRegTorqueEnable, 1, on));
        for (int id = 1; id <= 4; ++id)
            QTRY_VERIFY(sim.errors().contains(u"id %1 torque on"_s.arg(id)));

        // Servo 2 alone is sent to 1200 ticks; the others stay where their hands leave them.
        const std::uint8_t goal[] = {1200 & 0xFF, 1200 >> 8};
        QVERIFY(bus.write(2, fw::sts::kRegGoalPosition, goal));
        QTest::qWait(500);
        std::array<Feedback, 4> f{};
        for (int k = 0; k < 4; ++k) {
            const auto got = feedbackOf(bus, std::uint8_t(k + 1));
            QVERIFY(got);
            f[std::size_t(k)] = *got;
            qInfo("id %d: position %d tick, load %d", k + 1, got->position, got->load);
        }
        QVERIFY2(std::abs(f[1].position - 1200) <= 10, qPrintable(QString::number(f[1].position)));
        QVERIFY(std::abs(f[0].position - 1000) <= 10 && std::abs(f[3].position - 1000) <= 10);
        // Knob 3's hand pushes against its servo: a load the idle knobs do not show.
        QVERIFY2(std::abs(f[2].load) > 50 && std::abs(f[0].load) < 30,
                 qPrintable(u"%1 vs %2"_s.arg(f[2].load).arg(f[0].load)));
        QVERIFY(sim.terminate());
        QCOMPARE(sim.process().exitCode(), 0);
    }

    void countsThatCannotBeAreRefused_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("sentence");
        QTest::newRow("five") << QStringList{u"--servos"_s, u"5"_s} << u"servo count"_s;
        QTest::newRow("past 253") << QStringList{u"--servos"_s, u"4"_s, u"--servo-id"_s, u"252"_s}
                                  << u"4 servos from id 252 would end at id 255, beyond 253"_s;
        QTest::newRow("bad hand") << QStringList{u"--servos"_s, u"2"_s, u"--hand-2"_s, u"push"_s}
                                  << u"--hand-2:"_s;
    }
    void countsThatCannotBeAreRefused()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, sentence);
        QProcess sim;
        sim.start(servoSim(), arguments);
        QVERIFY(sim.waitForFinished(kStartTimeoutMs));
        QCOMPARE(sim.exitCode(), 4);
        const QString error = QString::fromLocal8Bit(sim.readAllStandardError());
        QVERIFY2(error.contains(sentence), qPrintable(error));
        QVERIFY(sim.readAllStandardOutput().isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestServoBus)
#include "tst_servobus.moc"
