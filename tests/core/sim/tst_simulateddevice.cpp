// SimulatedDevice offline (no pty): protocol v2's commands and replies (HELLO, GET_PARAMS,
// SET_PARAMS, feedback, ZERO, PING, SAVE_PARAMS), sequence numbers and retries, refused frames,
// and the state file. Telemetry, the watchdog and the link: tst_simulateddevicelink; the ideal
// model, the servo plant and the legacy firmware: tst_simulateddevicemodel.
#include "devicehost.h"
#include "profile/profile.h"
#include "session/sessiontypes.h"
#include "sim/simulateddevice.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace Qt::StringLiterals;
using test::f32Params;
using test::fastConfig;
using test::handOf;
using test::Host;
using test::kTwoPi;

Q_DECLARE_METATYPE(hatpic::v2::AckStatus)

class TestSimulatedDevice : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void hello_data();
    void hello();
    void getParamsGivesPowerUpBlock();
    void setParams_data();
    void setParams();
    void setParamsTakesEffectNextCycle();
    void feedbackAppliedWhateverSeq();
    void zeroAndRepeatedSeq();
    void repeatedCommandAnsweredNotApplied();
    void refusedFrames_data();
    void refusedFrames();
    void pingPong();
    void saveParamsPersistsAndReloads();
    void saveParamsWithoutStateFile();
    void saveParamsStorageError();
    void invalidStateFileIgnored();
};

void TestSimulatedDevice::hello_data()
{
    QTest::addColumn<double>("rate");
    QTest::addColumn<int>("maxStream");
    QTest::newRow("1 kHz control") << 1000.0 << 1000;
    QTest::newRow("500 Hz control") << 500.0 << 500;
    QTest::newRow("2.5 kHz control") << 2500.0 << 2500;
}

void TestSimulatedDevice::hello()
{
    QFETCH(double, rate);
    QFETCH(int, maxStream);
    SimulatedDevice::Config c = fastConfig();
    c.controlRateHz = rate;
    c.deviceId = 0x12345678;
    c.tauLimit = 0.5;
    Host host(c);
    host.send(0, v2::Hello{});
    const std::optional<v2::Frame> f = host.reply<v2::HelloReply>();
    QVERIFY(f);
    const auto r = std::get<v2::HelloReply>(f->message);
    QCOMPARE(r.protocolVersion, quint8(2));
    QCOMPARE(int(r.maxStreamHz), maxStream);
    QCOMPARE(r.deviceId, 0x12345678u);
    QCOMPARE(r.tauLimit, 0.5f);
    QCOMPARE(r.firmware, u"hatpic-sim 0.1"_s);
    QCOMPARE(host.device.streamRate(), quint16(0)); // off after power-up
}

void TestSimulatedDevice::getParamsGivesPowerUpBlock()
{
    SimulatedDevice::Config c = fastConfig();
    c.params.K_max = 0.9;
    c.params.theta0 = 0.1;
    Host host(c);
    QCOMPARE(host.params(), f32Params(c.params));
    QCOMPARE(host.device.params(), f32Params(c.params));
}

void TestSimulatedDevice::setParams_data()
{
    QTest::addColumn<DeviceParams>("block");
    QTest::addColumn<int>("field"); // -1 = accepted
    const DeviceParams ok;
    auto with = [&](int index, double value) {
        DeviceParams p = ok;
        p.setField(index, value);
        return p;
    };
    QTest::newRow("defaults accepted") << ok << -1;
    DeviceParams stiff = ok;
    stiff.K_max = 2.0;
    stiff.K_min = 1.0;
    stiff.theta0 = -0.3;
    QTest::newRow("stiffer block accepted") << stiff << -1;
    QTest::newRow("D_adm too small") << with(0, 1e-7) << 0;
    QTest::newRow("M_adm zero") << with(1, 0.0) << 1;
    QTest::newRow("K_min above K_max") << with(2, 0.5) << 2;
    QTest::newRow("K_max above 50") << with(3, 60.0) << 3;
    QTest::newRow("N zero") << with(4, 0.0) << 4;
    QTest::newRow("N is NaN") << with(4, std::nan("")) << 4;
    QTest::newRow("Q_dz equal to N") << with(5, ok.N) << 5;
    QTest::newRow("theta0 above pi") << with(6, 3.5) << 6;
    QTest::newRow("theta0 = pi, above pi as f32") << with(6, std::numbers::pi) << 6;
    QTest::newRow("theta0 infinite") << with(6, INFINITY) << 6;
    DeviceParams two = with(1, -1.0);
    two.theta0 = 9;
    QTest::newRow("two violations name the first") << two << 1;
}

void TestSimulatedDevice::setParams()
{
    QFETCH(DeviceParams, block);
    QFETCH(int, field);
    SimulatedDevice::Config c = fastConfig();
    c.params.K_min = 0.2; // differs from every row's block, so a change would show
    Host host(c);
    const DeviceParams before = host.params();
    host.send(17, v2::SetParams{block});
    const std::optional<v2::Ack> ack = host.ack();
    QVERIFY(ack);
    QCOMPARE(ack->ackedSeq, quint8(17));
    if (field < 0) {
        QCOMPARE(ack->status, v2::AckStatus::Ok);
        QCOMPARE(ack->field, v2::kNoField);
        QCOMPARE(host.params(), f32Params(block));
    } else {
        QCOMPARE(ack->status, v2::AckStatus::OutOfRange);
        QCOMPARE(int(ack->field), field);
        QCOMPARE(host.params(), before); // all or nothing
    }
}

void TestSimulatedDevice::setParamsTakesEffectNextCycle()
{
    SimulatedDevice::Config c = fastConfig();
    c.ideal = true;
    c.hand = handOf(u"const:0.03"_s);
    Host host(c);
    for (int i = 0; i < 100; ++i)
        host.device.step();
    DeviceParams next = host.device.params();
    next.K_max = 1.5;
    next.K_min = 0.5;
    next.Q_dz = 0.0;
    next = f32Params(next);
    const SimulatedDevice::Cycle before = host.device.step();
    QCOMPARE(before.tau_rec, recenteringTorque(host.device.params(), before.theta));
    host.send(3, v2::SetParams{next});
    QCOMPARE(host.ack()->status, v2::AckStatus::Ok);
    // Read back at once, in force from the next cycle on, never mixed.
    QCOMPARE(host.device.params(), next);
    const SimulatedDevice::Cycle after = host.device.step();
    QCOMPARE(after.tau_rec, recenteringTorque(next, after.theta));
    QVERIFY(after.tau_rec != recenteringTorque(DeviceParams{}, after.theta));
}

void TestSimulatedDevice::feedbackAppliedWhateverSeq()
{
    SimulatedDevice::Config c = fastConfig();
    c.ideal = true;
    Host host(c);
    host.send(5, v2::SetFeedback{0.02f});
    QCOMPARE(host.device.step().tau_ext, double(0.02f));
    host.send(5, v2::SetFeedback{-0.03f}); // same seq: still applied
    QCOMPARE(host.device.step().tau_ext, double(-0.03f));
    host.send(5, v2::SetFeedback{-0.03f}); // and no reply to feedback
    host.device.advance(0.01);
    QVERIFY(host.take().isEmpty());
}

void TestSimulatedDevice::zeroAndRepeatedSeq()
{
    SimulatedDevice::Config c = fastConfig();
    c.hand = handOf(u"const:0.03"_s);
    Host host(c);
    for (int i = 0; i < 500; ++i)
        host.device.step();
    const SimulatedDevice::Cycle at = host.device.step();
    QVERIFY(at.theta > 0.05); // the hand has moved the knob
    host.send(5, v2::Zero{});
    std::optional<v2::Ack> ack = host.ack();
    QVERIFY(ack);
    QCOMPARE(ack->status, v2::AckStatus::Ok);
    // (Read through the API: a GET_PARAMS would become the last command remembered.)
    const double theta0 = host.device.params().theta0;
    QCOMPARE(theta0, double(float(at.theta)));

    // The knob keeps going (the spring now centres at theta0); a retry of ZERO seq 5 must not
    // move theta0 again, a new ZERO must.
    for (int i = 0; i < 300; ++i)
        host.device.step();
    host.take();
    host.send(5, v2::Zero{});
    ack = host.ack();
    QVERIFY(ack);
    QCOMPARE(ack->status, v2::AckStatus::Ok);
    QCOMPARE(host.device.params().theta0, theta0);
    host.send(6, v2::Zero{});
    QCOMPARE(host.ack()->status, v2::AckStatus::Ok);
    QVERIFY(host.device.params().theta0 > theta0 + 0.01);
}

void TestSimulatedDevice::repeatedCommandAnsweredNotApplied()
{
    Host host(fastConfig());
    DeviceParams first;
    first.K_max = 0.8;
    DeviceParams second;
    second.K_max = 1.6;
    host.send(9, v2::SetParams{first});
    host.device.advance(0.001);
    const QByteArray firstReply = host.device.takeOutput();
    QVERIFY(!firstReply.isEmpty());
    // Same type and seq (a host retry): the same reply bytes, nothing applied.
    host.send(9, v2::SetParams{second});
    host.device.advance(0.001);
    QCOMPARE(host.device.takeOutput(), firstReply);
    QCOMPARE(host.device.params(), f32Params(first));
    // Same seq but another type is a new command.
    host.send(9, v2::SetStream{10});
    QCOMPARE(host.ack()->ackedSeq, quint8(9));
    QCOMPARE(host.device.streamRate(), quint16(10));
    // Then the same SET_PARAMS seq again is new too (only the last command is remembered).
    host.send(9, v2::SetParams{second});
    QCOMPARE(host.ack()->status, v2::AckStatus::Ok);
    QCOMPARE(host.device.params(), f32Params(second));
}

void TestSimulatedDevice::refusedFrames_data()
{
    QTest::addColumn<int>("type");
    QTest::addColumn<QByteArray>("payload");
    QTest::addColumn<v2::AckStatus>("status");
    QTest::newRow("unknown type 0x42") << 0x42 << QByteArray() << v2::AckStatus::UnknownType;
    QTest::newRow("device type TELEMETRY sent to device")
        << 0x90 << QByteArray(25, '\1') << v2::AckStatus::UnknownType;
    QTest::newRow("HELLO with a payload")
        << 0x01 << QByteArray(1, '\0') << v2::AckStatus::BadLength;
    QTest::newRow("SET_PARAMS one byte short")
        << 0x03 << QByteArray(27, '\0') << v2::AckStatus::BadLength;
    QTest::newRow("SET_STREAM one byte")
        << 0x04 << QByteArray(1, '\x10') << v2::AckStatus::BadLength;
    QTest::newRow("PING two bytes") << 0x07 << QByteArray(2, '\x10') << v2::AckStatus::BadLength;
}

void TestSimulatedDevice::refusedFrames()
{
    QFETCH(int, type);
    QFETCH(QByteArray, payload);
    QFETCH(v2::AckStatus, status);
    Host host(fastConfig());
    const DeviceParams before = host.device.params();
    host.sendRaw(v2::encodePacket(quint8(type), 77, payload));
    const std::optional<v2::Ack> ack = host.ack();
    QVERIFY(ack);
    QCOMPARE(ack->ackedSeq, quint8(77));
    QCOMPARE(ack->status, status);
    QCOMPARE(ack->field, v2::kNoField);
    QCOMPARE(host.device.params(), before);
    QCOMPARE(host.device.streamRate(), quint16(0));
}

void TestSimulatedDevice::pingPong()
{
    Host host(fastConfig());
    host.send(4, v2::Ping{0xDEADBEEF});
    const std::optional<v2::Frame> f = host.reply<v2::Pong>();
    QVERIFY(f);
    QCOMPARE(std::get<v2::Pong>(f->message).token, 0xDEADBEEFu);
}

void TestSimulatedDevice::saveParamsPersistsAndReloads()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"state.json"_s);
    SimulatedDevice::Config c = fastConfig();
    c.stateFile = path;
    DeviceParams saved;
    saved.D_adm = 3e-4;
    saved.K_max = 1.2;
    saved.theta0 = -0.25;
    {
        Host host(c);
        QCOMPARE(host.params(), f32Params(DeviceParams{})); // no file yet: the defaults
        host.send(1, v2::SetParams{saved});
        QCOMPARE(host.ack()->status, v2::AckStatus::Ok);
        QVERIFY(!QFile::exists(path)); // only SAVE_PARAMS writes
        host.send(2, v2::SaveParams{});
        QCOMPARE(host.ack()->status, v2::AckStatus::Ok);
    }
    const ProfileReadResult read = readProfile(path);
    QVERIFY2(read.ok(), qPrintable(read.errors.join(u"; "_s)));
    // The file holds each float's shortest decimal (1.2, not 1.2000000476837158).
    QCOMPARE(read.profile->device, tidyDeviceParams(f32Params(saved)));
    QCOMPARE(read.profile->device.K_max, 1.2);
    // Power-up again: the saved block is restored and the device starts at its theta0.
    Host again(c);
    QVERIFY(again.device.stateWarning().isEmpty());
    QCOMPARE(again.params(), f32Params(saved));
    const double ticks = std::round(double(float(saved.theta0)) * 4096 / kTwoPi);
    QCOMPARE(again.device.step().theta, double(float(ticks * kTwoPi / 4096.0)));
}

void TestSimulatedDevice::saveParamsWithoutStateFile()
{
    Host host(fastConfig());
    host.send(1, v2::SaveParams{});
    QCOMPARE(host.ack()->status, v2::AckStatus::Ok); // kept in the process's "flash"
}

void TestSimulatedDevice::saveParamsStorageError()
{
    QTemporaryDir dir;
    SimulatedDevice::Config c = fastConfig();
    c.stateFile = dir.filePath(u"missing-dir/state.json"_s);
    Host host(c);
    // Known at start…
    QCOMPARE(host.device.saveWarning(), u"SAVE_PARAMS cannot write state file " + c.stateFile +
                                            u": its folder " + dir.filePath(u"missing-dir"_s) +
                                            u" does not exist.");
    // …and said with the system's words when it happens: the LOG first, then the ACK.
    host.send(1, v2::SaveParams{});
    host.device.advance(1e-3);
    const QList<v2::Frame> frames = host.take();
    QCOMPARE(frames.size(), 2);
    const auto *log = std::get_if<v2::Log>(&frames.at(0).message);
    QVERIFY(log);
    QCOMPARE(v2::toQString(log->text), u"SAVE_PARAMS failed: cannot write profile \""_s +
                                           c.stateFile + u"\": No such file or directory"_s);
    const auto *ack = std::get_if<v2::Ack>(&frames.at(1).message);
    QVERIFY(ack);
    QCOMPARE(ack->status, v2::AckStatus::StorageError);
}

void TestSimulatedDevice::invalidStateFileIgnored()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"state.json"_s);
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{ this is not a profile");
    file.close();
    SimulatedDevice::Config c = fastConfig();
    c.stateFile = path;
    c.params.K_max = 0.7;
    Host host(c);
    QVERIFY(host.device.stateWarning().contains(path));
    QCOMPARE(host.params(), f32Params(c.params));
}

QTEST_GUILESS_MAIN(TestSimulatedDevice)
#include "tst_simulateddevice.moc"
