// The effect block (effects.md) through the session, end to end over real pseudo-terminals:
// hatpic-sim (a device core with the effects capability, or the legacy firmware) and a
// scripted v2 device without the capability.
#include "commandwait.h"
#include "scripteddevice.h"
#include "session/deviceclient.h"
#include "session/devicesession.h"
#include "session/request.h"
#include "session/sessionwording.h"
#include "simprocess.h"
#include "simulatoroptions.h"
#include "telemetry/recordingreader.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <variant>
#include <vector>

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
    const Outcome pushed = waitFor(client, request::Push{{std::nullopt, fx}});
    QVERIFY2(pushed.ok(), qPrintable(failure(pushed)));
    // An effects-only push: SET_EFFECTS, then its read-back, and nothing else.
    QVERIFY(pushed.pushed());
    QVERIFY(!pushed.pushed()->params && !pushed.pushed()->passivity);
    QVERIFY(sameOnWire(pushed.pushed()->effects.value(), fx));
    QVERIFY((stepKinds(wireSteps(pushed.request, client.deviceInfo())) ==
             std::vector{CommandKind::SetEffects, CommandKind::GetEffects}));
    QCOMPARE(std::get<outcome::Done>(pushed.result).readBack, outcome::ReadBack::Matches);
    QVERIFY(sameOnWire(pushed.received.effects.value(), fx));
    QVERIFY(effectsChanged.count() >= 1);
    QVERIFY(sameOnWire(client.deviceTuning().effects.value(), fx));

    const Outcome read = waitFor(client, request::Read{});
    QVERIFY2(read.ok(), qPrintable(failure(read)));
    // The tuning: parameters and effects.
    QVERIFY(std::holds_alternative<request::Read>(read.request));
    const std::vector<CommandKind> readSteps =
        stepKinds(wireSteps(read.request, client.deviceInfo()));
    QVERIFY(readSteps.size() >= 2);
    QCOMPARE(readSteps.at(0), CommandKind::GetParams);
    QCOMPARE(readSteps.at(1), CommandKind::GetEffects);
    QVERIFY(read.received.params.has_value());
    QVERIFY(sameOnWire(read.received.effects.value(), fx));

    // A strong, slow cue shows in τ_fx: the knob rests in a detent, where τ_det ≈ 0.
    samples.clear();
    const Outcome vibrated = waitFor(client, request::Vibrate{{0.2, 20, 0.3}});
    QVERIFY2(vibrated.ok(), qPrintable(failure(vibrated)));
    QVERIFY(std::holds_alternative<request::Vibrate>(vibrated.request));
    QCOMPARE(std::get<request::Vibrate>(vibrated.request).vibration, (Vibration{0.2, 20, 0.3}));
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
    const Outcome r = waitFor(client, request::Push{{std::nullopt, bad}});
    const auto *invalid = std::get_if<outcome::Invalid>(&r.result);
    QVERIFY2(invalid, qPrintable(failure(r)));
    QCOMPARE(invalid->problems.size(), 2);
    QVERIFY2(invalid->problems.first().contains(u"detent_strength"),
             qPrintable(invalid->problems.join(u';')));
    QVERIFY(sameOnWire(client.deviceTuning().effects.value(),
                       roundedForWire(EffectParams{}, 0.44))); // nothing reached the device

    const Outcome v = waitFor(client, request::Vibrate{{0.1, 0.5, 1}});
    const auto *invalidCue = std::get_if<outcome::Invalid>(&v.result);
    QVERIFY2(invalidCue, qPrintable(failure(v)));
    QVERIFY2(invalidCue->problems.join(u';').contains(u"frequency"),
             qPrintable(invalidCue->problems.join(u';')));
}

void TestSessionEffects::deviceRejectsVibrationAboveNyquist()
{
    // The simulator controls at 1 kHz: 500 Hz passes the table (≤ 500) but not f < rate/2,
    // which only the device can check.
    SimProcess sim({});
    DeviceClient client;
    QVERIFY(connectTo(client, sim));
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().effects.has_value(), kTimeoutMs);
    const Outcome r = waitFor(client, request::Vibrate{{0.1, 500, 1}});
    const auto *refused = std::get_if<outcome::Refused>(&r.result);
    QVERIFY2(refused, qPrintable(failure(r)));
    QCOMPARE(refused->step, CommandKind::Vibrate);
    QCOMPARE(refused->status, v2::AckStatus::OutOfRange);
    QCOMPARE(refused->field, 1);
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
    for (const Outcome &r : {waitFor(client, request::Push{{std::nullopt, detentsAndWalls()}}),
                             waitFor(client, request::Vibrate{{0.1, 20, 1}})}) {
        const auto *u = std::get_if<outcome::Unsupported>(&r.result);
        QVERIFY2(u, qPrintable(failure(r)));
        QCOMPARE(u->why, outcome::Unsupported::Why::NoEffects);
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
    QList<Outcome> results;
    QList<Sample> samples;
    const OutcomeHandler collect = [&](const Outcome &r) { results.append(r); };
    connect(&session.samples(), &SamplePipeline::samplesReady, this,
            [&](const SampleBatch &b) { samples.append(b); });
    ConnectOptions o;
    o.port = device.path();
    o.protocol = ProtocolChoice::V2;
    o.feedbackRateHz = 0;
    session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(session.state(), SessionState::Connected, kTimeoutMs);
    QVERIFY(!session.deviceInfo().hasEffects());
    session.request(request::Push{{std::nullopt, detentsAndWalls()}}, collect);
    session.request(request::Push{{DeviceParams{}, detentsAndWalls()}},
                    collect); // not half of it either
    session.request(request::Vibrate{{0.1, 20, 1}}, collect);
    QCOMPARE(results.size(), 3);
    for (const Outcome &r : std::as_const(results)) {
        const auto *u = std::get_if<outcome::Unsupported>(&r.result);
        QVERIFY2(u, qPrintable(failure(r)));
        QCOMPARE(u->why, outcome::Unsupported::Why::NoEffectsCapability);
        QVERIFY(isEffectCommand(u->step));
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
    QList<Outcome> results;
    bool haveEffects = false;
    connect(&session.samples(), &SamplePipeline::deviceTuningChanged, this,
            [&](const DeviceTuning &t) { haveEffects = t.effects.has_value(); });
    session.connectDevice(test::simulatorOptions());
    QTRY_VERIFY_WITH_TIMEOUT(haveEffects, kTimeoutMs);
    session.startRecording(csv, QStringLiteral("test"));
    QTest::qWait(50);
    EffectParams fx;
    fx.detent_strength = 0.05;
    fx.detent_range = 0.8;
    session.request(request::Push{{std::nullopt, fx}},
                    [&](const Outcome &r) { results.append(r); });
    QTRY_COMPARE_WITH_TIMEOUT(results.size(), 1, kTimeoutMs);
    QVERIFY2(results.first().ok(), qPrintable(failure(results.first())));
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
