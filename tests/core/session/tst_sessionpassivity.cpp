// The passivity block (passivity.md) through the session, end to end over real
// pseudo-terminals: hatpic-sim (a device core with the passivity capability) and a scripted v2
// device without it, which is told apart and sent nothing.
#include "commandwait.h"
#include "scripteddevice.h"
#include "session/deviceclient.h"
#include "session/devicesession.h"
#include "simprocess.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace hatpic;
using hatpic::test::ScriptedDevice;
using hatpic::test::SimProcess;

namespace {

constexpr int kTimeoutMs = 5000;

//! The outcome of the command `issue` gives its CommandDone to.
template<typename Issue> CommandResult waitFor(Issue issue)
{
    return test::waitForCommand(issue, kTimeoutMs);
}

} // namespace

class TestSessionPassivity : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void passivityOverPty();
    void invalidPassivityIsRefusedBeforeSending();
    void deviceWithoutCapabilityIsSentNothing();
};

void TestSessionPassivity::initTestCase()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not part of this build");
#endif
}

void TestSessionPassivity::passivityOverPty()
{
    SimProcess sim({});
    DeviceClient client;
    QList<Sample> samples;
    connect(&client, &DeviceClient::samplesReady, this,
            [&](const SampleBatch &b) { samples.append(b); });
    const QString path = sim.path();
    QVERIFY(!path.isEmpty());
    ConnectOptions o;
    o.port = path;
    client.connectDevice(o);
    // The connect sequence reads the block back: the defaults, the controller on.
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().passivity.has_value(), kTimeoutMs);
    QVERIFY(client.deviceInfo().hasPassivity());
    QVERIFY(sameOnWire(client.deviceTuning().passivity.value(), PassivityParams{}));
    // τ_pc and R arrive: at rest, no damping, the tank full.
    QTRY_VERIFY_WITH_TIMEOUT(!samples.isEmpty(), kTimeoutMs);
    QCOMPARE(samples.last().tau_pc, 0.0);
    QCOMPARE(samples.last().pc_reserve, double(float(PassivityParams{}.pc_reserve_max)));

    const PassivityParams pc{.pc_damping_max = 0.25, .pc_reserve_max = 0.01};
    const CommandResult pushed = waitFor([&](CommandDone then) {
        client.pushTuning({std::nullopt, std::nullopt, pc}, std::move(then));
    });
    QVERIFY(pushed.ok());
    QCOMPARE(pushed.command, CommandKind::SetPassivity);
    QVERIFY(pushed.readBack && pushed.readBackMatches);
    QVERIFY(sameOnWire(pushed.received.passivity.value(), pc));
    QVERIFY(sameOnWire(client.deviceTuning().passivity.value(), pc));
    // A smaller R_max caps the reserve at once.
    QTRY_COMPARE_WITH_TIMEOUT(samples.last().pc_reserve, double(0.01f), kTimeoutMs);

    // A push of every part: each sent and read back.
    const PassivityParams off = PassivityParams::off();
    const CommandResult all = waitFor([&](CommandDone then) {
        client.pushTuning({client.deviceTuning().params, EffectParams{}, off}, std::move(then));
    });
    QVERIFY(all.ok());
    QVERIFY(all.readBack && all.readBackMatches);
    QVERIFY(sameOnWire(all.received.passivity.value(), off));

    const CommandResult read =
        waitFor([&](CommandDone then) { client.readTuning(std::move(then)); });
    QVERIFY(read.ok());
    QVERIFY(read.received.params && read.received.effects);
    QVERIFY(sameOnWire(read.received.passivity.value(), off));
}

void TestSessionPassivity::invalidPassivityIsRefusedBeforeSending()
{
    SimProcess sim({});
    DeviceClient client;
    ConnectOptions o;
    o.port = sim.path();
    QVERIFY(!o.port.isEmpty());
    client.connectDevice(o);
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().passivity.has_value(), kTimeoutMs);
    const CommandResult r = waitFor([&](CommandDone then) {
        client.pushTuning({std::nullopt, std::nullopt, PassivityParams{2.0, 0.02}},
                          std::move(then));
    });
    QCOMPARE(r.status, CommandResult::Status::Invalid);
    QCOMPARE(r.reason, CommandResult::Reason::InvalidParams);
    QCOMPARE(r.problems.size(), 1);
    QVERIFY2(r.problems.first().contains(QLatin1String("pc_damping_max")),
             qPrintable(r.problems.first()));
    QVERIFY(sameOnWire(client.deviceTuning().passivity.value(), PassivityParams{}));
}

void TestSessionPassivity::deviceWithoutCapabilityIsSentNothing()
{
    ScriptedDevice device; // a v2 device whose HELLO_REPLY has no capability bits
    QVERIFY(device.isValid());
    DeviceSession session;
    QList<CommandResult> results;
    QList<Sample> samples;
    connect(&session, &DeviceSession::commandFinished, this,
            [&](quint64, const CommandResult &r) { results.append(r); });
    connect(&session.samples(), &SamplePipeline::samplesReady, this,
            [&](const SampleBatch &b) { samples.append(b); });
    ConnectOptions o;
    o.port = device.path();
    o.protocol = ProtocolChoice::V2;
    o.feedbackRateHz = 0;
    session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(session.state(), SessionState::Connected, kTimeoutMs);
    QVERIFY(!session.deviceInfo().hasPassivity());
    session.pushTuning(1, {std::nullopt, std::nullopt, PassivityParams{}});
    QCOMPARE(results.size(), 1);
    QCOMPARE(results.first().status, CommandResult::Status::Unsupported);
    QCOMPARE(results.first().reason, CommandResult::Reason::NoPassivityCapability);
    // A 37-byte TELEMETRY from it: the bytes after the flags are not read as τ_pc and R.
    v2::Telemetry t;
    t.t_us = 1000;
    t.tau_fx = 0.0f;
    t.tau_pc = 0.2f;
    t.pc_reserve = 0.01f;
    device.send(t);
    QTRY_VERIFY_WITH_TIMEOUT(!samples.isEmpty(), kTimeoutMs);
    QVERIFY(std::isnan(samples.last().tau_pc));
    QVERIFY(std::isnan(samples.last().pc_reserve));
}

QTEST_GUILESS_MAIN(TestSessionPassivity)
#include "tst_sessionpassivity.moc"
