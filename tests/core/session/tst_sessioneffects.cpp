// The effect block (effects.md) through the session, end to end over real pseudo-terminals:
// hatpic-sim (a device core with the effects capability, or the legacy firmware) and a
// scripted v2 device without the capability.
#include "commandwait.h"
#include "scripteddevice.h"
#include "session/deviceclient.h"
#include "session/devicesession.h"
#include "simprocess.h"
#include "simulatoroptions.h"
#include "telemetry/recordingreader.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace hatpic;
using hatpic::test::ScriptedDevice;
using hatpic::test::SimProcess;

namespace {

constexpr int kTimeoutMs = 5000;

EffectParams detentsAndWalls()
{
    return EffectParams{.detent_strength = 0.05,
                        .detent_spacing = 0.2,
                        .detent_range = 0.8,
                        .wall_min = -0.5,
                        .wall_max = 0.5,
                        .wall_stiffness = 2,
                        .wall_damping = 0.01};
}

//! Connects `client` to `sim`; false when the simulator did not start.
bool connectTo(DeviceClient &client, SimProcess &sim,
               ProtocolChoice protocol = ProtocolChoice::Auto)
{
    const QString path = sim.path();
    if (path.isEmpty())
        return false;
    ConnectOptions o;
    o.port = path;
    o.protocol = protocol;
    client.connectDevice(o);
    return true;
}

//! The outcome of the command `issue` gives its CommandDone to.
template<typename Issue> CommandResult waitFor(Issue issue)
{
    return test::waitForCommand(issue, kTimeoutMs);
}

} // namespace

class TestSessionEffects : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void effectsOverPty();
    void invalidEffectsAreRefusedBeforeSending();
    void deviceRejectsVibrationAboveNyquist();
    void legacyDeviceHasNoEffects();
    void deviceWithoutCapabilityHasNoEffects();
    void pushedEffectsAreRecordedEvents();
};

void TestSessionEffects::initTestCase()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not part of this build");
#endif
}

void TestSessionEffects::effectsOverPty()
{
    SimProcess sim({});
    DeviceClient client;
    QList<Sample> samples;
    connect(&client, &DeviceClient::samplesReady, this,
            [&](const SampleBatch &b) { samples.append(b); });
    QVERIFY(connectTo(client, sim));
    // The connect sequence reads the block back: defaults, which render nothing.
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().effects.has_value(), kTimeoutMs);
    QVERIFY(client.deviceInfo().hasEffects());
    QVERIFY(
        sameOnWire(client.deviceTuning().effects.value(), roundedForWire(EffectParams{}, 0.44)));
    QTRY_VERIFY_WITH_TIMEOUT(!samples.isEmpty(), kTimeoutMs);
    QCOMPARE(samples.last().tau_fx, 0.0);

    const EffectParams fx = detentsAndWalls();
    QSignalSpy effectsChanged(&client, &DeviceClient::deviceTuningChanged);
    const CommandResult pushed = waitFor([&](CommandDone then) {
        client.pushTuning({std::nullopt, fx}, std::move(then));
    });
    QVERIFY(pushed.ok());
    QCOMPARE(pushed.command, CommandKind::SetEffects);
    QVERIFY(pushed.readBack && pushed.readBackMatches);
    QVERIFY(sameOnWire(pushed.received.effects.value(), fx));
    QVERIFY(effectsChanged.count() >= 1);
    QVERIFY(sameOnWire(client.deviceTuning().effects.value(), fx));

    const CommandResult read =
        waitFor([&](CommandDone then) { client.readTuning(std::move(then)); });
    QVERIFY(read.ok());
    QCOMPARE(read.command, CommandKind::GetParams); // the tuning: parameters and effects
    QVERIFY(read.received.params.has_value());
    QVERIFY(sameOnWire(read.received.effects.value(), fx));

    // A strong, slow cue shows in τ_fx: the knob rests in a detent, where τ_det ≈ 0.
    samples.clear();
    const CommandResult vibrated = waitFor([&](CommandDone then) {
        client.vibrate({0.2, 20, 0.3}, std::move(then));
    });
    QVERIFY(vibrated.ok());
    QCOMPARE(vibrated.command, CommandKind::Vibrate);
    QCOMPARE(vibrated.vibration, (Vibration{0.2, 20, 0.3}));
    QTRY_VERIFY_WITH_TIMEOUT(std::any_of(samples.cbegin(), samples.cend(),
                                         [](const Sample &s) { return std::abs(s.tau_fx) > 0.1; }),
                             kTimeoutMs);
    // τ_total includes τ_fx.
    const Sample &last = samples.last();
    QVERIFY(std::abs(last.tau_total -
                     std::clamp(last.tau_rec + last.tau_fx + last.tau_ext, -0.44, 0.44)) < 1e-6);
}

void TestSessionEffects::invalidEffectsAreRefusedBeforeSending()
{
    SimProcess sim({});
    DeviceClient client;
    QVERIFY(connectTo(client, sim));
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().effects.has_value(), kTimeoutMs);

    EffectParams bad;
    bad.detent_strength = 1.0; // above tau_limit 0.44
    bad.wall_min = 0.1;        // must be ≤ 0
    const CommandResult r = waitFor([&](CommandDone then) {
        client.pushTuning({std::nullopt, bad}, std::move(then));
    });
    QCOMPARE(r.status, CommandResult::Status::Invalid);
    QCOMPARE(r.reason, CommandResult::Reason::InvalidParams);
    QCOMPARE(r.problems.size(), 2);
    QVERIFY2(r.problems.first().contains(u"detent_strength"), qPrintable(r.problems.join(u';')));
    QVERIFY(sameOnWire(client.deviceTuning().effects.value(),
                       roundedForWire(EffectParams{}, 0.44))); // nothing reached the device

    const CommandResult v = waitFor([&](CommandDone then) {
        client.vibrate({0.1, 0.5, 1}, std::move(then));
    });
    QCOMPARE(v.status, CommandResult::Status::Invalid);
    QVERIFY2(v.problems.join(u';').contains(u"frequency"), qPrintable(v.problems.join(u';')));
}

void TestSessionEffects::deviceRejectsVibrationAboveNyquist()
{
    // The simulator controls at 1 kHz: 500 Hz passes the table (≤ 500) but not f < rate/2,
    // which only the device can check.
    SimProcess sim({});
    DeviceClient client;
    QVERIFY(connectTo(client, sim));
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().effects.has_value(), kTimeoutMs);
    const CommandResult r = waitFor([&](CommandDone then) {
        client.vibrate({0.1, 500, 1}, std::move(then));
    });
    QCOMPARE(r.status, CommandResult::Status::Rejected);
    QCOMPARE(r.ackStatus, v2::AckStatus::OutOfRange);
    QCOMPARE(r.field, 1);
}

void TestSessionEffects::legacyDeviceHasNoEffects()
{
    SimProcess sim({QStringLiteral("--protocol"), QStringLiteral("legacy")});
    DeviceClient client;
    QList<Sample> samples;
    connect(&client, &DeviceClient::samplesReady, this,
            [&](const SampleBatch &b) { samples.append(b); });
    QVERIFY(connectTo(client, sim, ProtocolChoice::Legacy));
    QTRY_COMPARE_WITH_TIMEOUT(client.state(), SessionState::Connected, kTimeoutMs);
    QVERIFY(!client.deviceInfo().hasEffects());
    for (const CommandResult &r :
         {waitFor([&](CommandDone then) {
              client.pushTuning({std::nullopt, detentsAndWalls()}, std::move(then));
          }),
          waitFor([&](CommandDone then) {
              client.vibrate({0.1, 20, 1}, std::move(then));
          })}) {
        QCOMPARE(r.status, CommandResult::Status::Unsupported);
        QCOMPARE(r.reason, CommandResult::Reason::NoEffects);
    }
    QTRY_VERIFY_WITH_TIMEOUT(!samples.isEmpty(), kTimeoutMs);
    QVERIFY(std::isnan(samples.last().tau_fx)); // not carried: unknown, not zero
    QVERIFY(!client.deviceTuning().effects.has_value());
}

void TestSessionEffects::deviceWithoutCapabilityHasNoEffects()
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
    QVERIFY(!session.deviceInfo().hasEffects());
    session.pushTuning(1, {std::nullopt, detentsAndWalls()});
    session.pushTuning(2, {DeviceParams{}, detentsAndWalls()}); // not half of it either
    session.vibrate(3, {0.1, 20, 1});
    QCOMPARE(results.size(), 3);
    for (const CommandResult &r : std::as_const(results)) {
        QCOMPARE(r.status, CommandResult::Status::Unsupported);
        QCOMPARE(r.reason, CommandResult::Reason::NoEffectsCapability);
    }
    // A 29-byte TELEMETRY from it: the four bytes after the flags are not read as τ_fx.
    v2::Telemetry t;
    t.t_us = 1000;
    t.tau_rec = 0.1f;
    t.tau_fx = 0.3f;
    device.send(t);
    QTRY_VERIFY_WITH_TIMEOUT(!samples.isEmpty(), kTimeoutMs);
    QVERIFY(std::isnan(samples.last().tau_fx));
    QCOMPARE(samples.last().tau_total, double(0.1f));
}

void TestSessionEffects::pushedEffectsAreRecordedEvents()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString csv = dir.filePath(QStringLiteral("fx.csv"));
    DeviceSession session;
    QList<CommandResult> results;
    bool haveEffects = false;
    connect(&session, &DeviceSession::commandFinished, this,
            [&](quint64, const CommandResult &r) { results.append(r); });
    connect(&session.samples(), &SamplePipeline::deviceTuningChanged, this,
            [&](const DeviceTuning &t) { haveEffects = t.effects.has_value(); });
    session.connectDevice(test::simulatorOptions());
    QTRY_VERIFY_WITH_TIMEOUT(haveEffects, kTimeoutMs);
    session.startRecording(csv, QStringLiteral("test"));
    QTest::qWait(50);
    EffectParams fx;
    fx.detent_strength = 0.05;
    fx.detent_range = 0.8;
    session.pushTuning(1, {std::nullopt, fx});
    QTRY_COMPARE_WITH_TIMEOUT(results.size(), 1, kTimeoutMs);
    QVERIFY(results.first().ok());
    QTest::qWait(50);
    session.stopRecording();
    session.disconnectDevice();

    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording, qPrintable(read.error));
    QVERIFY2(read.warnings.isEmpty(), qPrintable(read.warnings.join(u'\n')));
    const Recording &rec = *read.recording;
    // The block at the start is in the metadata: the device's defaults (±π one float inside).
    QVERIFY(rec.metadata.effects.has_value());
    QVERIFY(sameOnWire(*rec.metadata.effects, roundedForWire(EffectParams{}, 0.44)));
    QCOMPARE(rec.events.size(), 1);
    QCOMPARE(rec.events.first().text,
             QStringLiteral("detent_strength 0 → 0.05; detent_range 0 → 0.8"));
    // τ_fx is recorded: a number on every row (0 before the push, at rest in a detent after).
    QVERIFY(!rec.samples.isEmpty());
    for (const Sample &s : rec.samples)
        QVERIFY(std::isfinite(s.tau_fx));
}

QTEST_GUILESS_MAIN(TestSessionEffects)
#include "tst_sessioneffects.moc"
