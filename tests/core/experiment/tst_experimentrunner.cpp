// ExperimentRunner end to end: a DeviceClient on a real pseudo-terminal whose other side is the
// simulated joystick with its real plant (servo lag, quantisation, load noise), hosted as
// hatpic-sim hosts it (SimulatorHost). The measured figures must come out near the model's.
// On the in-process simulator ("sim") the simulated hand goes idle for the run and comes back.
#include "experiment/experimentrunner.h"
#include "session/deviceclient.h"
#include "sim/simulatorhost.h"
#include "simulatoroptions.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <numbers>
#include <optional>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

constexpr int kConnectMs = 5000;
constexpr int kRunMs = 15000;
constexpr double kHatpicSimNoise = 0.0005; //!< what hatpic-sim runs with [N·m]

SimulatedDevice::Config deviceConfig(WireProtocol protocol = WireProtocol::V2)
{
    SimulatedDevice::Config c;
    c.protocol = protocol;
    c.noise = kHatpicSimNoise;
    return c;
}

//! A simulated joystick on a pty and a connected client.
struct Bench
{
    explicit Bench(WireProtocol protocol = WireProtocol::V2) : host(deviceConfig(protocol)) {}

    bool connect()
    {
        if (const QString error = host.start(); !error.isEmpty()) {
            qWarning("%s", qPrintable(error));
            return false;
        }
        ConnectOptions o;
        o.port = host.slavePath();
        o.protocol = host.device().config().protocol == WireProtocol::V2 ? ProtocolChoice::V2
                                                                         : ProtocolChoice::Legacy;
        o.autoReconnect = false;
        QObject::connect(&client, &DeviceClient::samplesReady,
                         [this](const SampleBatch &b) { samples.append(b); });
        client.connectDevice(o);
        return QTest::qWaitFor([this] { return client.state() == SessionState::Connected; },
                               kConnectMs);
    }

    //! Sends `params` and waits for the device's acknowledgement.
    bool push(const DeviceParams &params)
    {
        QObject caller;
        std::optional<Outcome> done;
        client.request(request::Push{{params, std::nullopt}},
                       {&caller, [&done](const Outcome &o) { done = o; }});
        return QTest::qWaitFor([&] { return done.has_value(); }, kConnectMs) && done->ok();
    }

    SimulatorHost host;
    DeviceClient client;
    QList<Sample> samples;
};

ExperimentResult run(ExperimentRunner &runner, const ExperimentPlan &plan)
{
    QSignalSpy finished(&runner, &ExperimentRunner::finished);
    const QString why = runner.start(plan);
    if (!why.isEmpty())
        qFatal("%s", qPrintable(why));
    if (!finished.wait(kRunMs))
        qFatal("the experiment did not finish");
    return finished.first().first().value<ExperimentResult>();
}

} // namespace

class TestExperimentRunner : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void stepRecoversTheModel_data();
    void stepRecoversTheModel();
    void simulatedHandIsIdleForTheRun_data();
    void simulatedHandIsIdleForTheRun();
    void passivityIsOffForTheRun();
    void bodeMatchesTheModelBelowTheBandwidth();
    void spectrumShowsTheKnobAtRest();
    void cancelRestoresZeroFeedback();
    void lostDeviceFailsTheRun();
    void refusesALegacyDevice();
    void refusesWithoutADevice();
};

void TestExperimentRunner::stepRecoversTheModel_data()
{
    QTest::addColumn<double>("D");
    QTest::addColumn<double>("M");
    // ω_n = √(0.4/2e-3) = 14.1 rad/s, ζ = 0.04/(2·√(0.4·2e-3)) = 0.707: a knob well within
    // what the servo follows (see the tolerance below).
    QTest::newRow("slow knob") << 2e-3 << 4e-2;
}

void TestExperimentRunner::stepRecoversTheModel()
{
    QFETCH(double, D);
    QFETCH(double, M);
    Bench bench;
    QVERIFY(bench.connect());
    QTRY_VERIFY_WITH_TIMEOUT(ExperimentRunner::refusal(bench.client).isEmpty(), kConnectMs);
    DeviceParams params = bench.client.deviceTuning().params.value();
    params.D_adm = D;
    params.M_adm = M;
    QVERIFY(bench.push(params));
    ExperimentRunner runner(bench.client);
    const ExperimentPlan plan = ExperimentPlan::defaults(ExperimentKind::Step, params);
    const ExperimentResult r = run(runner, plan);
    QVERIFY2(r.completed() && r.problem.isEmpty(), qPrintable(r.problem));
    QVERIFY(r.fitMeasured.ok);
    QCOMPARE(r.hand, RunHand::User); // a device on a port: nothing lifts a person's hand
    const double omegaN = r.fitMeasured.omegaN, zeta = r.fitMeasured.zeta;
    qInfo("model ω_n %.2f rad/s ζ %.3f; measured ω_n %.2f rad/s ζ %.3f (rms %.2g rad); ideal "
          "ω_n %.2f ζ %.3f; rise %.4f s overshoot %.3f settling %.4f s",
          r.figures.omega_n, r.figures.zeta, omegaN, zeta, r.fitMeasured.rmsResidual,
          r.fitIdeal.omegaN, r.fitIdeal.zeta, r.stepMeasured.riseTime, r.stepMeasured.overshoot,
          r.stepMeasured.settlingTime);
    // The tolerance, 10 %: the knob is a servo tracking the admittance's command, not the
    // admittance itself. The simulated STS3032 follows it about 9 ms late, which makes the knob
    // slower than the model by roughly 0.45 % per rad/s of ω_n (measured: −6 % at 14 rad/s,
    // −8 % at 20, −13 % at 28, −30 % at the defaults' 63 rad/s; ζ within 3 % throughout;
    // docs/experiments.md). The fit itself adds nothing measurable (the ideal model's run fits
    // to 0.1 %). So on a knob the servo can follow, 10 % holds with a margin, and it is about
    // what a user can tell apart from a deliberate change (20 % on D_adm moves ω_n by 10 %).
    QVERIFY2(std::abs(omegaN / r.figures.omega_n - 1) < 0.10, qPrintable(QString::number(omegaN)));
    QVERIFY2(std::abs(zeta / r.figures.zeta - 1) < 0.10, qPrintable(QString::number(zeta)));
    QVERIFY(std::abs(r.fitIdeal.omegaN / r.figures.omega_n - 1) < 0.01);
    QVERIFY(std::abs(r.fitIdeal.zeta / r.figures.zeta - 1) < 0.05);
    // The model's gain: the step moves θ by Δτ/K_max.
    QVERIFY(std::abs(r.fitMeasured.gain / ((plan.tauTo - plan.tauFrom) / params.K_max) - 1) < 0.1);
    // When it ends, τ_ext is back to 0 on the device.
    QTRY_VERIFY_WITH_TIMEOUT(!bench.samples.isEmpty() && bench.samples.last().tau_ext == 0,
                             kConnectMs);
}

void TestExperimentRunner::simulatedHandIsIdleForTheRun_data()
{
    QTest::addColumn<QString>("hand");
    QTest::newRow("the tuner's gentle sine") << u"sine:0.06:0.2"_s;
    QTest::newRow("a virtual hand pulling") << u"hand:0.3"_s;
    QTest::newRow("idle already") << u"idle"_s;
    // Far out beyond the notch: with no time to come back ω_n read 33 rad/s, with 0.5 s 12.6.
    QTest::newRow("a hand holding it far out") << u"const:1.5"_s;
}

// Once, the simulated hand went on pushing during a step: ω_n 27.5 rad/s measured against 63.3
// for the model, ζ 1.30 against 0.79, and nothing said so.
void TestExperimentRunner::simulatedHandIsIdleForTheRun()
{
    QFETCH(QString, hand);
    const HandInput input = *HandInput::parse(hand);
    DeviceClient client;
    SimulatedDevice::Config config = deviceConfig();
    config.hand = input;
    const ConnectOptions o = test::simulatorOptions(config, ProtocolChoice::V2);
    SimulatedJoystick &joystick = *test::joystickOf(o);
    QList<Sample> samples;
    QObject::connect(&client, &DeviceClient::samplesReady,
                     [&samples](const SampleBatch &b) { samples.append(b); });
    client.connectDevice(o);
    QTRY_VERIFY_WITH_TIMEOUT(ExperimentRunner::refusal(client).isEmpty(), kConnectMs);
    DeviceParams params = client.deviceTuning().params.value();
    params.D_adm = 2e-3; // the slow knob of stepRecoversTheModel: 14.1 rad/s, ζ 0.707
    params.M_adm = 4e-2;
    QObject caller;
    bool pushed = false;
    client.request(request::Push{{params, std::nullopt}},
                   {&caller, [&pushed](const Outcome &) { pushed = true; }});
    QTRY_VERIFY_WITH_TIMEOUT(pushed, kConnectMs);
    QTRY_VERIFY_WITH_TIMEOUT(
        std::abs(client.deviceTuning().params.value().D_adm - params.D_adm) < 1e-9, kConnectMs);

    QCOMPARE(ExperimentRunner(client).handFor(), RunHand::User); // the hand is not the runner's
    ExperimentRunner runner(client, &joystick);
    QCOMPARE(runner.handFor(), RunHand::SimulatedIdle);
    const ExperimentResult r = run(runner, ExperimentPlan::defaults(ExperimentKind::Step, params));
    QVERIFY2(r.completed() && r.problem.isEmpty(), qPrintable(r.problem));
    QCOMPARE(r.hand, RunHand::SimulatedIdle);
    QCOMPARE(runHandText(r.hand), u"idle (simulated)"_s);
    qInfo("hand %s: measured ω_n %.2f rad/s ζ %.3f, model %.2f rad/s ζ %.3f", qPrintable(hand),
          r.fitMeasured.omegaN, r.fitMeasured.zeta, r.figures.omega_n, r.figures.zeta);
    QVERIFY2(std::abs(r.fitMeasured.omegaN / r.figures.omega_n - 1) < 0.10,
             qPrintable(QString::number(r.fitMeasured.omegaN)));
    QVERIFY2(std::abs(r.fitMeasured.zeta / r.figures.zeta - 1) < 0.10,
             qPrintable(QString::number(r.fitMeasured.zeta)));
    // Only τ_ext moved the knob: no sample of the run reports an operator torque beyond the
    // spring's answer to τ_ext (|τ| stays within the step's level plus the load noise).
    for (const Sample &s : r.samples)
        QVERIFY2(std::abs(s.tau) < 0.04, qPrintable(QString::number(s.tau)));

    // The hand is given back as it was.
    QCOMPARE(joystick.hand(), input);
    if (input.kind != HandInput::Kind::Idle) {
        samples.clear();
        QTRY_VERIFY_WITH_TIMEOUT(!samples.isEmpty() && std::abs(samples.last().tau) > 0.04, kRunMs);

        // Cancelled while the knob comes to rest: given back too.
        QSignalSpy finished(&runner, &ExperimentRunner::finished);
        QVERIFY(runner.start(ExperimentPlan::defaults(ExperimentKind::Step, params)).isEmpty());
        QCOMPARE(joystick.hand(), HandInput{});
        runner.cancel();
        QCOMPARE(finished.size(), 1);
        QCOMPARE(joystick.hand(), input);
    }
}

//! The device's passivity controller would damp the response measured (it takes the plan's
//! τ_ext for a robot's port): it is off for the run, on again after it, as it was.
void TestExperimentRunner::passivityIsOffForTheRun()
{
    Bench bench;
    QVERIFY(bench.connect());
    QTRY_VERIFY_WITH_TIMEOUT(ExperimentRunner::refusal(bench.client).isEmpty(), kConnectMs);
    const PassivityParams before = bench.client.deviceTuning().passivity.value();
    QVERIFY(before.enabled());
    // A knob the servo follows closely (stepRecoversTheModel's), so the fit checks the model.
    DeviceParams params = bench.client.deviceTuning().params.value();
    params.D_adm = 2e-3;
    params.M_adm = 4e-2;
    QVERIFY(bench.push(params));
    bool sawOff = false;
    QObject watcher;
    connect(&bench.client, &DeviceClient::deviceTuningChanged, &watcher,
            [&](const DeviceTuning &t) { sawOff |= t.passivity && !t.passivity->enabled(); });
    ExperimentRunner runner(bench.client);
    const ExperimentResult r = run(runner, ExperimentPlan::defaults(ExperimentKind::Step, params));
    QVERIFY2(r.completed() && r.problem.isEmpty(), qPrintable(r.problem));
    QVERIFY(sawOff);
    QVERIFY(!r.samples.isEmpty());
    for (const Sample &s : r.samples)
        QCOMPARE(s.tau_pc, 0.0); // not one damped cycle in the run
    QVERIFY2(std::abs(r.fitMeasured.omegaN / r.figures.omega_n - 1) < 0.10,
             qPrintable(QString::number(r.fitMeasured.omegaN)));
    // On again, as it was.
    QTRY_VERIFY_WITH_TIMEOUT(
        sameOnWire(bench.client.deviceTuning().passivity.value_or(PassivityParams::off()), before),
        kConnectMs);
}

void TestExperimentRunner::bodeMatchesTheModelBelowTheBandwidth()
{
    Bench bench;
    QVERIFY(bench.connect());
    QTRY_VERIFY_WITH_TIMEOUT(ExperimentRunner::refusal(bench.client).isEmpty(), kConnectMs);
    ExperimentRunner runner(bench.client);
    const DeviceParams params = bench.client.deviceTuning().params.value();
    ExperimentPlan plan = ExperimentPlan::defaults(ExperimentKind::Frequency, params);
    // Fewer, higher points than the defaults (which start at a tenth of the bandwidth), so
    // the run stays short.
    plan.frequencies = {3, 5, 8, 12, 18};
    plan.cycles = 3;
    const ExperimentResult r = run(runner, plan);
    QVERIFY2(r.completed() && r.problem.isEmpty(), qPrintable(r.problem));
    QCOMPARE(r.points.size(), std::size_t(5));
    for (const analysis::FrequencyPoint &p : r.points) {
        const std::complex<double> model = analysis::modelGain(params, p.frequency);
        qInfo("%5.1f Hz: measured %.3f rad/Nm %.1f°, model %.3f rad/Nm %.1f°", p.frequency,
              p.magnitude, p.phase * 180 / std::numbers::pi, std::abs(model),
              std::arg(model) * 180 / std::numbers::pi);
        // Below the bandwidth the magnitude is within 1.5 dB (19 %) of the model's: the
        // servo's lag adds phase and a little gain near ω_n, the ticks and the noise a little
        // error on the small swings.
        if (p.frequency < r.modelBandwidth)
            QVERIFY2(std::abs(20 * std::log10(p.magnitude / std::abs(model))) < 1.5,
                     qPrintable(QString::number(p.frequency)));
    }
    qInfo("bandwidth measured %.2f Hz, model %.2f Hz", r.bandwidth, r.modelBandwidth);
    QVERIFY(std::abs(r.bandwidth / r.modelBandwidth - 1) < 0.2);
}

void TestExperimentRunner::spectrumShowsTheKnobAtRest()
{
    Bench bench;
    QVERIFY(bench.connect());
    QTRY_VERIFY_WITH_TIMEOUT(ExperimentRunner::refusal(bench.client).isEmpty(), kConnectMs);
    ExperimentRunner runner(bench.client);
    ExperimentPlan plan = ExperimentPlan::defaults(ExperimentKind::Spectrum, {});
    plan.duration = 0.5;
    const ExperimentResult r = run(runner, plan);
    QVERIFY2(r.completed() && r.problem.isEmpty(), qPrintable(r.problem));
    QVERIFY(std::abs(r.sampleRate - 1000) < 1);
    // Half a second at 1 kHz: 2 Hz bins up to 500 Hz.
    QVERIFY(std::abs(r.thetaSpectrum.resolution - 2) < 0.1);
    QVERIFY(r.tauSpectrum.frequency.back() > 495);
}

void TestExperimentRunner::cancelRestoresZeroFeedback()
{
    Bench bench;
    QVERIFY(bench.connect());
    QTRY_VERIFY_WITH_TIMEOUT(ExperimentRunner::refusal(bench.client).isEmpty(), kConnectMs);
    ExperimentRunner runner(bench.client);
    ExperimentPlan plan =
        ExperimentPlan::defaults(ExperimentKind::Step, bench.client.deviceTuning().params.value());
    plan.duration = 10; // would run for 10 s
    QSignalSpy finished(&runner, &ExperimentRunner::finished);
    QSignalSpy progress(&runner, &ExperimentRunner::progress);
    QVERIFY(runner.start(plan).isEmpty());
    QVERIFY(!runner.start(plan).isEmpty()); // one at a time
    // Mid-run: the plan has begun (its progress reported) and its τ_ext is on the knob.
    QTRY_VERIFY_WITH_TIMEOUT(progress.size() > 2 && !bench.samples.isEmpty() &&
                                 bench.samples.last().tau_ext > 0,
                             kConnectMs);
    runner.cancel();
    QCOMPARE(finished.size(), 1);
    const auto r = finished.first().first().value<ExperimentResult>();
    QCOMPARE(r.outcome, ExperimentResult::Outcome::Cancelled);
    QVERIFY(!r.samples.isEmpty());
    QVERIFY(!runner.running());
    QTRY_VERIFY_WITH_TIMEOUT(bench.samples.last().tau_ext == 0, kConnectMs);
}

void TestExperimentRunner::lostDeviceFailsTheRun()
{
    Bench bench;
    QVERIFY(bench.connect());
    QTRY_VERIFY_WITH_TIMEOUT(ExperimentRunner::refusal(bench.client).isEmpty(), kConnectMs);
    ExperimentRunner runner(bench.client);
    ExperimentPlan plan =
        ExperimentPlan::defaults(ExperimentKind::Step, bench.client.deviceTuning().params.value());
    plan.duration = 10;
    QSignalSpy finished(&runner, &ExperimentRunner::finished);
    QVERIFY(runner.start(plan).isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(!bench.samples.isEmpty() && bench.samples.last().tau_ext > 0,
                             kConnectMs);
    bench.host.stop();
    QVERIFY(finished.wait(kRunMs));
    const auto r = finished.first().first().value<ExperimentResult>();
    QCOMPARE(r.outcome, ExperimentResult::Outcome::Failed);
    QCOMPARE(r.problem, QStringLiteral("The device was lost during the experiment."));
    QVERIFY(!runner.running());
}

void TestExperimentRunner::refusesALegacyDevice()
{
    Bench bench(WireProtocol::Legacy);
    QVERIFY(bench.connect());
    ExperimentRunner runner(bench.client);
    const QString why = runner.start(ExperimentPlan::defaults(ExperimentKind::Step, {}));
    QVERIFY2(why.contains(QStringLiteral("legacy")), qPrintable(why));
    QCOMPARE(ExperimentRunner::refusal(bench.client), why);
    QVERIFY(!runner.running());
}

void TestExperimentRunner::refusesWithoutADevice()
{
    DeviceClient client;
    ExperimentRunner runner(client);
    QCOMPARE(runner.start(ExperimentPlan::defaults(ExperimentKind::Step, {})),
             QStringLiteral("No device is connected."));
}

QTEST_GUILESS_MAIN(TestExperimentRunner)
#include "tst_experimentrunner.moc"
