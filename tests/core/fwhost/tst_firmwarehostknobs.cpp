// Four knobs on one bus, end to end: hatpic-fw-host --servos 4 (the device core with one
// controller per knob) driving hatpic-servo-sim --servos 4 over a real pty, served to a v2 host
// (a real QSerialPort) and to hatpicctl over another. Each knob feels its own hand, tuning and
// feedback; SAVE_PARAMS keeps every knob's block; the session records every knob.
#include "fwhosttest.h"

#include "model/params.h"
#include "model/stiffness.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

constexpr int kTimeoutMs = 5000;
constexpr int kSettleMs = 1500; //!< from a change to the window [ms]
constexpr int kWindowMs = 500;  //!< window a rest point is averaged over [ms]

QStringList fourServos(const QString &servoPath)
{
    return QStringList{u"--servo"_s, servoPath, u"--servos"_s, u"4"_s, u"--quiet"_s} + patientBus();
}

//! Knob k's θ (0 = knob 1) averaged over kWindowMs of telemetry, after kSettleMs.
std::array<double, 4> settledThetas(V2Client &client)
{
    QTest::qWait(kSettleMs); // the knobs need the time: nothing to poll for
    const qsizetype from = client.frames.size();
    QTest::qWait(kWindowMs);
    std::array<double, 4> sum{};
    int n = 0;
    for (qsizetype i = from; i < client.frames.size(); ++i) {
        const auto *t = std::get_if<v2::Telemetry>(&client.frames.at(i).message);
        if (!t || !t->more[2])
            continue;
        sum[0] += t->theta;
        for (int k = 1; k < 4; ++k)
            sum[std::size_t(k)] += t->more[std::size_t(k - 1)]->theta;
        ++n;
    }
    for (double &s : sum)
        s = n > 0 ? s / n : std::nan("");
    return sum;
}

//! What a hatpicctl run said.
struct CtlRun
{
    int exitCode = -1;
    QString out, err;
};

CtlRun hatpicctl(const QStringList &arguments)
{
    QProcess ctl;
    ctl.start(QStringLiteral(HATPICCTL_PATH), arguments);
    CtlRun run;
    if (!ctl.waitForFinished(15000))
        return run;
    run.exitCode = ctl.exitCode();
    run.out = QString::fromUtf8(ctl.readAllStandardOutput());
    run.err = QString::fromUtf8(ctl.readAllStandardError());
    return run;
}

//! The device block of the profile hatpicctl printed with --json.
QJsonObject deviceBlock(const CtlRun &run)
{
    return QJsonDocument::fromJson(run.out.toUtf8()).object().value(u"device"_s).toObject();
}

//! The θ where the model holds a hand torque `push` [rad] (bisection over ±1 rad).
double restPoint(const DeviceParams &p, double push)
{
    double lo = -1, hi = 1;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (recenteringTorque(p, mid) + push > 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

} // namespace

class TestFirmwareHostKnobs : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void fourKnobsEachTheirOwn();
    void everyKnobIsSavedAndRecorded();
    void hatpicctlTunesOneKnob();
    void idsPastTheBusAreRefused();
};

void TestFirmwareHostKnobs::fourKnobsEachTheirOwn()
{
    // Knob 1 pushed one way, knob 2 the other, knob 3 and 4 left alone.
    PtyProgram servo(hatpicServoSim(), {u"--servos"_s, u"4"_s, u"--hand"_s, u"const:0.02"_s,
                                        u"--hand-2"_s, u"const:-0.02"_s});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    PtyProgram host(hatpicFwHost(), fourServos(servo.path()));
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    V2Client client(host.path());
    QVERIFY2(client.open(), qPrintable(client.errorString()));

    client.send(v2::Hello{});
    QTRY_COMPARE_WITH_TIMEOUT(client.all<v2::HelloReply>().size(), 1, kTimeoutMs);
    const v2::HelloReply hello = client.all<v2::HelloReply>().first();
    QVERIFY(hello.capabilities & v2::kCapabilityAxes);
    QCOMPARE(hello.axes, std::optional<std::uint8_t>(4));

    client.send(v2::SetStream{1000});
    const DeviceParams defaults = roundedToFloat(DeviceParams{});
    // The servo reads each hand on its load grid (0.44 mN·m): 0.02 N·m reads 45 quanta.
    const double push = std::round(0.02 / 0.44e-3) * 0.44e-3;
    std::array<double, 4> rest = settledThetas(client);
    qInfo("rest %.5f %.5f %.5f %.5f rad", rest[0], rest[1], rest[2], rest[3]);
    QVERIFY2(std::abs(rest[0] - restPoint(defaults, push)) < 2 * kTick,
             qPrintable(QString::number(rest[0])));
    QVERIFY2(std::abs(rest[1] - restPoint(defaults, -push)) < 2 * kTick,
             qPrintable(QString::number(rest[1])));
    // The idle knobs rest where they are, inside the dead zone (no re-centering torque there).
    QVERIFY(std::abs(rest[2]) < defaults.Q_dz && std::abs(rest[3]) < defaults.Q_dz);

    // Knob 2 alone made stiffer: its rest point moves, knob 1's does not.
    DeviceParams stiff = defaults;
    stiff.K_max = 0.5;
    const quint8 set = client.send(v2::SetParams{stiff, 1});
    QTRY_VERIFY_WITH_TIMEOUT(client.ack(set).has_value(), kTimeoutMs);
    QCOMPARE(client.ack(set)->status, v2::AckStatus::Ok);
    rest = settledThetas(client);
    qInfo("knob 2 with K_max 0.5: %.5f rad (model %.5f)", rest[1], restPoint(stiff, -push));
    QVERIFY2(std::abs(rest[1] - restPoint(roundedToFloat(stiff), -push)) < 2 * kTick,
             qPrintable(QString::number(rest[1])));
    QVERIFY2(std::abs(rest[0] - restPoint(defaults, push)) < 2 * kTick,
             qPrintable(QString::number(rest[0])));

    // Each knob reads back its own block, naming it.
    client.send(v2::GetParams{1});
    client.send(v2::GetParams{});
    QTRY_COMPARE_WITH_TIMEOUT(client.all<v2::Params>().size(), 2, kTimeoutMs);
    QCOMPARE(client.all<v2::Params>().at(0).params, roundedToFloat(stiff));
    QCOMPARE(client.all<v2::Params>().at(0).axis, std::optional<std::uint8_t>(1));
    QCOMPARE(client.all<v2::Params>().at(1).params, defaults);
    QCOMPARE(client.all<v2::Params>().at(1).axis, std::nullopt);

    // A knob the device does not have is refused, naming the axis.
    const quint8 fifth = client.send(v2::SetParams{stiff, 4});
    QTRY_VERIFY_WITH_TIMEOUT(client.ack(fifth).has_value(), kTimeoutMs);
    QCOMPARE(client.ack(fifth)->status, v2::AckStatus::OutOfRange);
    QCOMPARE(client.ack(fifth)->field, v2::kAxisField);

    // One SET_FEEDBACK carries every knob's τ_ext; knob 4's pushes knob 4 alone.
    v2::SetFeedback feedback{0.0f};
    feedback.more = {0.0f, 0.0f, 0.01f};
    QTimer stream;
    connect(&stream, &QTimer::timeout, this, [&] { client.send(feedback); });
    stream.start(20);
    rest = settledThetas(client);
    stream.stop();
    qInfo("knob 4 with τ_ext 0.01 N·m: %.5f rad (model %.5f)", rest[3], restPoint(defaults, 0.01));
    QVERIFY2(std::abs(rest[3] - restPoint(defaults, 0.01)) < 2 * kTick,
             qPrintable(QString::number(rest[3])));
    QVERIFY(std::abs(rest[2]) < defaults.Q_dz);
    const QList<v2::Telemetry> telemetry = client.all<v2::Telemetry>();
    QVERIFY(!telemetry.isEmpty());
    QCOMPARE(telemetry.last().more[2]->tau_ext, 0.01f);
    QCOMPARE(telemetry.last().more[1]->tau_ext, 0.0f);
}

void TestFirmwareHostKnobs::everyKnobIsSavedAndRecorded()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString state = dir.filePath(u"state.json"_s);
    PtyProgram servo(hatpicServoSim(), {u"--servos"_s, u"4"_s, u"--hand-3"_s, u"const:0.02"_s});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    DeviceParams stiff = roundedToFloat(DeviceParams{});
    stiff.K_max = 0.5;
    {
        PtyProgram host(hatpicFwHost(),
                        fourServos(servo.path()) + QStringList{u"--state"_s, state});
        QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
        V2Client client(host.path());
        QVERIFY(client.open());
        const quint8 set = client.send(v2::SetParams{stiff, 2});
        const quint8 save = client.send(v2::SaveParams{});
        QTRY_VERIFY_WITH_TIMEOUT(client.ack(save).has_value(), kTimeoutMs);
        QCOMPARE(client.ack(set)->status, v2::AckStatus::Ok);
        QCOMPARE(client.ack(save)->status, v2::AckStatus::Ok);
        for (const char *file :
             {"state.json", "state.knob2.json", "state.knob3.json", "state.knob4.json"})
            QVERIFY2(QFileInfo::exists(dir.filePath(QString::fromLatin1(file))), file);
        QVERIFY(host.terminate());
        QCOMPARE(host.process().exitCode(), 0);
    }

    // Power-up finds knob 3's block again; hatpicctl sees four knobs and records them all.
    PtyProgram host(hatpicFwHost(), fourServos(servo.path()) + QStringList{u"--state"_s, state});
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    {
        V2Client client(host.path());
        QVERIFY(client.open());
        client.send(v2::GetParams{2});
        QTRY_COMPARE_WITH_TIMEOUT(client.all<v2::Params>().size(), 1, kTimeoutMs);
        QCOMPARE(client.all<v2::Params>().first().params, stiff);
    }
    QProcess info;
    info.start(QStringLiteral(HATPICCTL_PATH), {u"info"_s, u"--port"_s, host.path()});
    QVERIFY(info.waitForFinished(10000));
    const QString said = QString::fromUtf8(info.readAllStandardOutput());
    QVERIFY2(info.exitCode() == 0, qPrintable(QString::fromUtf8(info.readAllStandardError())));
    QVERIFY2(said.contains(u"knobs"_s) && said.contains(u"4"_s), qPrintable(said));

    const QString csv = dir.filePath(u"four.csv"_s);
    QProcess stream;
    stream.start(QStringLiteral(HATPICCTL_PATH),
                 {u"stream"_s, u"--port"_s, host.path(), u"--duration"_s, u"1"_s, u"--csv"_s, csv});
    QVERIFY(stream.waitForFinished(15000));
    QVERIFY2(stream.exitCode() == 0, qPrintable(QString::fromUtf8(stream.readAllStandardError())));
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QList<QByteArray> lines = file.readAll().split('\n');
    while (!lines.isEmpty() && (lines.first().startsWith('#') || lines.first().isEmpty()))
        lines.removeFirst();
    QVERIFY(lines.size() > 100);
    const QList<QByteArray> header = lines.first().split(',');
    const qsizetype theta3 = header.indexOf("theta_3");
    QVERIFY2(theta3 >= 0 && header.contains("theta_4") && header.contains("tau_ext_4"),
             lines.first().constData());
    // Knob 3's hand holds it where its K_max 0.5 block says (0.0396 rad), row after row.
    const QList<QByteArray> row = lines.at(lines.size() / 2).split(',');
    const double theta = row.at(theta3).toDouble();
    QVERIFY2(std::abs(theta - 0.0396) < 3 * kTick, row.at(theta3).constData());
}

void TestFirmwareHostKnobs::hatpicctlTunesOneKnob()
{
    // Knob 2 pushed by a hand; the others left alone.
    PtyProgram servo(hatpicServoSim(), {u"--servos"_s, u"4"_s, u"--hand-2"_s, u"const:0.02"_s});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    PtyProgram host(hatpicFwHost(), fourServos(servo.path()));
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    const QStringList port{u"--port"_s, host.path()};
    const double defaultKmax = DeviceParams{}.K_max; // printed as its shortest decimal

    // set --knob 2 changes knob 2's block alone, and says what knob 2 now holds.
    const CtlRun set =
        hatpicctl(QStringList{u"set"_s, u"--knob"_s, u"2"_s, u"--set"_s, u"K_max=0.5"_s, u"--set"_s,
                              u"detent_strength=0.04"_s, u"--json"_s} +
                  port);
    QVERIFY2(set.exitCode == 0, qPrintable(set.err));
    QVERIFY2(set.err.contains(u"The device accepted the parameters."_s), qPrintable(set.err));
    QCOMPARE(deviceBlock(set).value(u"K_max"_s).toDouble(), 0.5);
    const CtlRun knob2 = hatpicctl(QStringList{u"get"_s, u"--knob"_s, u"2"_s, u"--json"_s} + port);
    QVERIFY2(knob2.exitCode == 0, qPrintable(knob2.err));
    QCOMPARE(deviceBlock(knob2).value(u"K_max"_s).toDouble(), 0.5);
    QCOMPARE(float(deviceBlock(knob2)
                       .value(u"effects"_s)
                       .toObject()
                       .value(u"detent_strength"_s)
                       .toDouble()),
             0.04f);
    for (const char *other : {"1", "3", "4"}) {
        const CtlRun get = hatpicctl(
            QStringList{u"get"_s, u"--knob"_s, QString::fromLatin1(other), u"--json"_s} + port);
        QVERIFY2(get.exitCode == 0, qPrintable(get.err));
        QCOMPARE(deviceBlock(get).value(u"K_max"_s).toDouble(), defaultKmax);
    }
    const CtlRun plain = hatpicctl(QStringList{u"get"_s, u"--json"_s} + port); // knob 1
    QCOMPARE(deviceBlock(plain).value(u"K_max"_s).toDouble(), defaultKmax);

    // zero --knob 2 moves knob 2's centre to where its hand holds it, and no other's.
    const CtlRun zero = hatpicctl(QStringList{u"zero"_s, u"--knob"_s, u"2"_s, u"--json"_s} + port);
    QVERIFY2(zero.exitCode == 0, qPrintable(zero.err));
    QVERIFY2(zero.err.contains(u"The center of knob 2 is now theta0 = "_s), qPrintable(zero.err));
    DeviceParams stiff = roundedToFloat(DeviceParams{});
    stiff.K_max = 0.5;
    const double theta0 = deviceBlock(zero).value(u"theta0"_s).toDouble();
    QVERIFY2(std::abs(theta0 - restPoint(stiff, 0.02)) < 4 * kTick, qPrintable(zero.out));
    const CtlRun third = hatpicctl(QStringList{u"get"_s, u"--knob"_s, u"3"_s, u"--json"_s} + port);
    QCOMPARE(deviceBlock(third).value(u"theta0"_s).toDouble(), 0.0);

    const CtlRun cue =
        hatpicctl(QStringList{u"vibrate"_s, u"--knob"_s, u"4"_s, u"--amplitude"_s, u"0.05"_s,
                              u"--frequency"_s, u"20"_s, u"--duration"_s, u"0.1"_s} +
                  port);
    QVERIFY2(cue.exitCode == 0, qPrintable(cue.err));
    QVERIFY2(cue.err.contains(u"Knob 4 plays the cue"_s), qPrintable(cue.err));

    // Not a knob number: bad usage before any port is opened.
    const CtlRun fifth = hatpicctl(QStringList{u"get"_s, u"--knob"_s, u"5"_s} + port);
    QCOMPARE(fifth.exitCode, 4);
    QVERIFY2(fifth.err.contains(u"--knob is out of range: it must be a whole number from 1 to 4, "
                                "got '5'."_s),
             qPrintable(fifth.err));
    // A knob the device does not have: refused with the device's count, nothing sent.
    const CtlRun single = hatpicctl(
        {u"set"_s, u"--port"_s, u"sim"_s, u"--knob"_s, u"2"_s, u"--set"_s, u"K_max=0.5"_s});
    QCOMPARE(single.exitCode, 2);
    QVERIFY2(
        single.err.contains(u"GET_PARAMS is not available for knob 2: the device has one knob."_s),
        qPrintable(single.err));
}

void TestFirmwareHostKnobs::idsPastTheBusAreRefused()
{
    QProcess host;
    host.start(hatpicFwHost(),
               {u"--servo"_s, u"/dev/null"_s, u"--servos"_s, u"3"_s, u"--servo-id"_s, u"252"_s});
    QVERIFY(host.waitForFinished(kTimeoutMs));
    QCOMPARE(host.exitCode(), 4);
    const QString said = QString::fromUtf8(host.readAllStandardError());
    QVERIFY2(said.contains(u"3 servos from id 252 would end at id 254, beyond 253"_s),
             qPrintable(said));
}

QTEST_GUILESS_MAIN(TestFirmwareHostKnobs)
#include "tst_firmwarehostknobs.moc"
