// The passivity block (passivity.md) through the session, end to end over real
// pseudo-terminals: hatpic-sim (a device core with the passivity capability) and a scripted v2
// device without it, which is told apart and sent nothing.
#include "commandwait.h"
#include "model/passivity.h"
#include "scripteddevice.h"
#include "session/deviceclient.h"
#include "session/devicesession.h"
#include "session/request.h"
#include "session/sessionwording.h"
#include "simprocess.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <variant>
#include <vector>

using namespace hatpic;
using hatpic::test::ScriptedDevice;
using hatpic::test::SimProcess;

namespace {

constexpr int kTimeoutMs = 5000;

//! The outcome of `request` sent through `client`.
Outcome waitFor(DeviceClient &client, const Request &request)
{
    return test::waitForOutcome(client, request, kTimeoutMs);
}

//! Why `o` failed, for QVERIFY2.
QString failure(const Outcome &o)
{
    return SessionWording::commandFailure(o);
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
    // τ_pc and R arrive: at rest with no hand, no damping, the tank at its floor's level.
    QTRY_VERIFY_WITH_TIMEOUT(!samples.isEmpty(), kTimeoutMs);
    QCOMPARE(samples.last().tau_pc, 0.0);
    QCOMPARE(samples.last().pc_reserve, double(float(passivity::kLevelFloor)));

    const PassivityParams pc{.pc_damping_max = 0.25, .pc_reserve_max = 0.004};
    const Outcome pushed = waitFor(client, request::Push{{std::nullopt, std::nullopt, pc}});
    QVERIFY2(pushed.ok(), qPrintable(failure(pushed)));
    // A passivity-only push: SET_PASSIVITY, then its read-back, and nothing else.
    QVERIFY(pushed.pushed());
    QVERIFY(!pushed.pushed()->params && !pushed.pushed()->effects);
    QVERIFY(sameOnWire(pushed.pushed()->passivity.value(), pc));
    QVERIFY((stepKinds(wireSteps(pushed.request, client.deviceInfo())) ==
             std::vector{CommandKind::SetPassivity, CommandKind::GetPassivity}));
    QCOMPARE(std::get<outcome::Done>(pushed.result).readBack, outcome::ReadBack::Matches);
    QVERIFY(sameOnWire(pushed.received.passivity.value(), pc));
    QVERIFY(sameOnWire(client.deviceTuning().passivity.value(), pc));
    // An R_max below the reserve caps it at once.
    QTRY_COMPARE_WITH_TIMEOUT(samples.last().pc_reserve, double(0.004f), kTimeoutMs);

    // A push of every part: each sent and read back.
    const PassivityParams off = PassivityParams::off();
    const Outcome all =
        waitFor(client, request::Push{{client.deviceTuning().params, EffectParams{}, off}});
    QVERIFY2(all.ok(), qPrintable(failure(all)));
    QVERIFY(all.pushed() && all.pushed()->params && all.pushed()->effects &&
            all.pushed()->passivity);
    QCOMPARE(std::get<outcome::Done>(all.result).readBack, outcome::ReadBack::Matches);
    QVERIFY(sameOnWire(all.received.passivity.value(), off));

    const Outcome read = waitFor(client, request::Read{});
    QVERIFY2(read.ok(), qPrintable(failure(read)));
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
    const Outcome r =
        waitFor(client, request::Push{{std::nullopt, std::nullopt, PassivityParams{2.0, 0.02}}});
    const auto *invalid = std::get_if<outcome::Invalid>(&r.result);
    QVERIFY2(invalid, qPrintable(failure(r)));
    QCOMPARE(invalid->problems.size(), 1);
    QVERIFY2(invalid->problems.first().contains(QLatin1String("pc_damping_max")),
             qPrintable(invalid->problems.first()));
    QVERIFY(sameOnWire(client.deviceTuning().passivity.value(), PassivityParams{}));
}

void TestSessionPassivity::deviceWithoutCapabilityIsSentNothing()
{
    ScriptedDevice device; // a v2 device whose HELLO_REPLY has no capability bits
    QVERIFY(device.isValid());
    DeviceSession session;
    QList<Outcome> results;
    QList<Sample> samples;
    connect(&session.samples(), &SamplePipeline::samplesReady, this,
            [&](const SampleBatch &b) { samples.append(b); });
    ConnectOptions o;
    o.port = device.path();
    o.protocol = ProtocolChoice::V2;
    o.feedbackRateHz = 0;
    session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(session.state(), SessionState::Connected, kTimeoutMs);
    QVERIFY(!session.deviceInfo().hasPassivity());
    session.request(request::Push{{std::nullopt, std::nullopt, PassivityParams{}}},
                    [&](const Outcome &r) { results.append(r); });
    QCOMPARE(results.size(), 1);
    const auto *u = std::get_if<outcome::Unsupported>(&results.first().result);
    QVERIFY2(u, qPrintable(failure(results.first())));
    QCOMPARE(u->why, outcome::Unsupported::Why::NoPassivityCapability);
    QCOMPARE(u->step, CommandKind::SetPassivity);
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
