// SimulatedDevice offline (no pty): what it renders. The ideal model equal to model.md's
// admittance step by step, the cycle's sample, the hand's time base, the servo plant (the
// spring's equilibrium, quantised measurements, seeded noise), and the legacy firmware's
// emulation (boot text, 5 frames/s, position wrap, feedback, the busy-wait hazard, v2 ignored).
#include "devicehost.h"
#include "model/admittance.h"
#include "model/stiffness.h"
#include "session/sessiontypes.h"
#include "sim/simulateddevice.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace hatpic;
using namespace Qt::StringLiterals;
using test::f32Params;
using test::fastConfig;
using test::handOf;
using test::kTwoPi;

class TestSimulatedDeviceModel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void idealMatchesModel_data();
    void idealMatchesModel();
    void cycleSample_data();
    void cycleSample();
    void setHandRestartsTimeBase();
    void plantSettlesAtSpringEquilibrium_data();
    void plantSettlesAtSpringEquilibrium();
    void plantMeasurementsQuantised();
    void noiseIsSeeded();
    void legacyBootTextAndFrameRate();
    void legacyPositionWraps();
    void legacyFeedback();
    void legacyBusyWaitHazard();
    void legacyIgnoresV2();
};

void TestSimulatedDeviceModel::idealMatchesModel_data()
{
    QTest::addColumn<QString>("hand");
    QTest::addColumn<double>("rate");
    QTest::addColumn<double>("feedback");
    QTest::newRow("step at 1 kHz") << u"step:0.05:-0.01"_s << 1000.0 << 0.0;
    QTest::newRow("chirp at 1 kHz") << u"chirp:0.1:0.5:8"_s << 1000.0 << 0.0;
    QTest::newRow("virtual hand at 250 Hz") << u"hand:0.6"_s << 250.0 << 0.0;
    QTest::newRow("sine with feedback at 2 kHz") << u"sine:0.2:1.5"_s << 2000.0 << 0.5;
}

void TestSimulatedDeviceModel::idealMatchesModel()
{
    QFETCH(QString, hand);
    QFETCH(double, rate);
    QFETCH(double, feedback);
    SimulatedDevice::Config c = fastConfig();
    c.ideal = true;
    c.controlRateHz = rate;
    c.hand = handOf(hand);
    c.params.theta0 = 0.05;
    c.passivity = PassivityParams::off(); // model.md alone (the controller: tst_passivity)
    SimulatedDevice device(c);
    if (feedback != 0)
        device.receive(v2::encodeFrame(0, v2::SetFeedback{float(feedback)}));
    const DeviceParams p = f32Params(c.params);
    const double h = 1.0 / rate;
    const double tauExt = double(float(feedback));
    AdmittanceState s{p.theta0, 0.0};
    int saturated = 0;
    for (int k = 0; k < int(3 * rate); ++k) {
        const double t = k * h;
        const bool stale = feedback == 0 ? t >= 0.2 - 1e-12 : false;
        const double tau = -c.hand.torque(t, s.theta, s.omega);
        const double tauRec = recenteringTorque(p, s.theta);
        const double ext = stale ? 0.0 : tauExt;
        const double total = std::clamp(tauRec + ext, -c.tauLimit, c.tauLimit);
        if (feedback != 0 && k % 100 == 0) // keep the watchdog fed
            device.receive(v2::encodeFrame(0, v2::SetFeedback{float(feedback)}));
        const SimulatedDevice::Cycle cycle = device.step();
        const auto where = qPrintable(u"step %1"_s.arg(k));
        QVERIFY2(cycle.t == t, where);
        QVERIFY2(cycle.theta == s.theta, where);
        QVERIFY2(cycle.omega == s.omega, where);
        QVERIFY2(cycle.tau == tau, where);
        QVERIFY2(cycle.tau_rec == tauRec, where);
        QVERIFY2(cycle.tau_ext == ext, where);
        QVERIFY2(cycle.tau_total == total, where);
        saturated += bool(cycle.flags & v2::kFlagSaturated);
        s = admittanceStep(p, s, -tau + total, h);
    }
    QVERIFY(std::abs(s.theta - p.theta0) > 0.01); // the input actually moved the knob
    if (feedback != 0)
        QVERIFY(saturated > 0);
}

void TestSimulatedDeviceModel::cycleSample_data()
{
    QTest::addColumn<double>("rate");
    QTest::newRow("1 kHz") << 1000.0;
    QTest::newRow("3 kHz: periods not whole µs") << 3000.0;
    QTest::newRow("70 Hz") << 70.0;
}

void TestSimulatedDeviceModel::cycleSample()
{
    QFETCH(double, rate);
    SimulatedDevice::Config c = fastConfig();
    c.controlRateHz = rate;
    c.hand = handOf(u"sine:0.08:3"_s);
    SimulatedDevice device(c);
    for (int k = 0; k < int(rate); ++k) {
        const SimulatedDevice::Cycle cycle = device.step();
        const Sample s = cycle.toSample();
        const auto where = qPrintable(u"step %1"_s.arg(k));
        QVERIFY2(s.t_s == cycle.t, where);
        // The device clock: 32-bit microseconds of the cycle's time, wrapping.
        QVERIFY2(s.t_us == quint32(quint64(std::llround(cycle.t * 1e6))), where);
        QVERIFY2(s.theta == cycle.theta && s.omega == cycle.omega && s.tau == cycle.tau, where);
        QVERIFY2(s.tau_rec == cycle.tau_rec && s.tau_ext == cycle.tau_ext, where);
        QVERIFY2(s.tau_fx == cycle.tau_fx && s.tau_total == cycle.tau_total, where);
        QVERIFY2(s.tau_pc == cycle.tau_pc && s.pc_reserve == cycle.pc_reserve, where);
        QVERIFY2(s.flags == cycle.flags && s.v_ref == 0 && s.p_ref == 0, where);
    }
}

void TestSimulatedDeviceModel::setHandRestartsTimeBase()
{
    SimulatedDevice::Config c = fastConfig();
    c.ideal = true;
    SimulatedDevice device(c);
    for (int i = 0; i < 1000; ++i)
        device.step();
    HandInput step = handOf(u"step:0.1:0.02"_s);
    device.setHand(step);
    QCOMPARE(device.hand(), step);
    // The step happens kStepTime after setHand, not after power-up (the cycle exactly at
    // the step time is skipped: which side of it a rounded time lands on is not the point).
    const int before = int(std::lround(HandInput::kStepTime * 1000));
    for (int i = 0; i < before; ++i)
        QCOMPARE(device.step().tau, -0.02);
    device.step();
    for (int i = 0; i < 10; ++i)
        QCOMPARE(device.step().tau, -0.1);
}

void TestSimulatedDeviceModel::plantSettlesAtSpringEquilibrium_data()
{
    QTest::addColumn<double>("torque");
    QTest::addColumn<double>("expectedE");
    const DeviceParams p;
    // Notch band: e = τ/K_max. Far side: e = τ/K_min (beyond 2N, where K_rec = K_min).
    QTest::newRow("push +0.03 into notch band") << 0.03 << 0.03 / p.K_max;
    QTest::newRow("push -0.02 into notch band") << -0.02 << -0.02 / p.K_max;
    QTest::newRow("push +0.06 beyond 2N") << 0.06 << 0.06 / p.K_min;
    // Too weak to leave the dead zone: held at its edge, where K_rec jumps to K_max.
    QTest::newRow("push -0.005 held at dead-zone edge") << -0.005 << -p.Q_dz;
}

void TestSimulatedDeviceModel::plantSettlesAtSpringEquilibrium()
{
    QFETCH(double, torque);
    QFETCH(double, expectedE);
    SimulatedDevice::Config c = fastConfig();
    c.hand.kind = HandInput::Kind::Constant;
    c.hand.amplitude = torque;
    SimulatedDevice device(c);
    const DeviceParams p = device.params();
    for (int i = 0; i < 3000; ++i)
        device.step();
    // At rest the knob dithers by about a tick around the equilibrium (position and load
    // are quantised, the servo lags); at the notch edge it chatters a little. So judge the
    // last second as a whole.
    const double tick = kTwoPi / 4096;
    const double quantum = 0.44e-3;
    double sumE = 0;
    double sumTau = 0;
    double maxOmega = 0;
    double maxDeviation = 0;
    const int n = 1000;
    for (int i = 0; i < n; ++i) {
        const SimulatedDevice::Cycle cycle = device.step();
        const double e = cycle.theta - p.theta0;
        sumE += e;
        sumTau += cycle.tau;
        maxOmega = std::max(maxOmega, std::abs(cycle.omega));
        maxDeviation = std::max(maxDeviation, std::abs(e - expectedE));
    }
    const double meanE = sumE / n;
    const double meanTau = sumTau / n;
    // Equilibrium of the spring: K_rec(θ)·e = τ_op, to within a tick and a load quantum.
    const double tolerance = 1.5 * tick + quantum / p.K_min;
    QVERIFY2(std::abs(meanE - expectedE) < tolerance,
             qPrintable(u"mean e = %1, expected %2"_s.arg(meanE).arg(expectedE)));
    QVERIFY2(maxDeviation <= 4 * tick, qPrintable(QString::number(maxDeviation)));
    QVERIFY2(maxOmega < 0.5, qPrintable(QString::number(maxOmega)));
    // The servo's load balances the hand: τ ≈ −τ_op.
    QVERIFY2(std::abs(meanTau + torque) <= 2 * quantum, qPrintable(QString::number(meanTau)));
}

void TestSimulatedDeviceModel::plantMeasurementsQuantised()
{
    SimulatedDevice::Config c = fastConfig();
    c.hand = handOf(u"sine:0.1:2"_s);
    SimulatedDevice device(c);
    bool moved = false;
    for (int i = 0; i < 1000; ++i) {
        const SimulatedDevice::Cycle cycle = device.step();
        const double ticks = cycle.theta * 4096 / kTwoPi;
        QVERIFY2(std::abs(ticks - std::round(ticks)) < 1e-3, qPrintable(QString::number(ticks)));
        const double loads = cycle.tau / 0.44e-3;
        QVERIFY2(std::abs(loads - std::round(loads)) < 1e-3, qPrintable(QString::number(loads)));
        QVERIFY(std::abs(cycle.tau) <= 0.44 + 1e-6);
        moved = moved || std::abs(cycle.theta) > 0.05;
    }
    QVERIFY(moved);
}

void TestSimulatedDeviceModel::noiseIsSeeded()
{
    auto run = [](quint64 seed) {
        SimulatedDevice::Config c = fastConfig();
        c.noise = 0.003;
        c.seed = seed;
        SimulatedDevice device(c);
        QList<double> taus;
        for (int i = 0; i < 200; ++i)
            taus.append(device.step().tau);
        return taus;
    };
    const QList<double> a = run(7);
    QCOMPARE(run(7), a);
    QVERIFY(run(8) != a);
    QVERIFY(std::any_of(a.begin(), a.end(), [](double v) { return v != 0; }));
}

void TestSimulatedDeviceModel::legacyBootTextAndFrameRate()
{
    SimulatedDevice::Config c;
    c.protocol = WireProtocol::Legacy;
    SimulatedDevice device(c);
    QCOMPARE(device.baud(), 115200);
    legacy::Decoder decoder;
    QList<legacy::Frame> frames;
    QStringList text;
    int firstFrameMs = -1;
    for (int ms = 0; ms < 3100; ++ms) { // frames at 0.2 s, 0.4 s, … 3.0 s
        device.advance(1e-3);
        decoder.feed(device.takeOutput(), frames, &text);
        if (firstFrameMs < 0 && !frames.isEmpty())
            firstFrameMs = ms;
    }
    QCOMPARE(text.value(0), u"STS3032 Torque control"_s);
    QCOMPARE(text.value(1), u"Current pos motor : 1000"_s);
    QCOMPARE(text.value(2), u"1000"_s);
    QCOMPARE(frames.size(), 15); // 5 frames/s
    QVERIFY(firstFrameMs >= 195 && firstFrameMs <= 210);
    for (const legacy::Frame &f : frames)
        QCOMPARE(f, (legacy::Frame{1000, 1000, 1000, 1000})); // at rest, centre tick
    QCOMPARE(decoder.stats().malformed, 0u);
}

void TestSimulatedDeviceModel::legacyPositionWraps()
{
    // Pushed 2 rad negative (K_min region): tick 1000 − 1304 wraps to 4096 − 304.
    SimulatedDevice::Config c;
    c.protocol = WireProtocol::Legacy;
    c.hand = handOf(u"const:-0.3"_s);
    SimulatedDevice device(c);
    legacy::Decoder decoder;
    QList<legacy::Frame> frames;
    SimulatedDevice::Cycle cycle;
    for (int i = 0; i < 8000; ++i) {
        cycle = device.step();
        decoder.feed(device.takeOutput(), frames);
    }
    QVERIFY(cycle.theta < -1.6);
    QVERIFY(!frames.isEmpty());
    const int expected = int(std::lround(cycle.theta * 4096 / kTwoPi)) + 1000 + 4096;
    QVERIFY(frames.last().a >= 0 && frames.last().a < 4096);
    QVERIFY2(std::abs(frames.last().a - expected) <= 2,
             qPrintable(u"%1 vs %2"_s.arg(frames.last().a).arg(expected)));
}

void TestSimulatedDeviceModel::legacyFeedback()
{
    SimulatedDevice::Config c;
    c.protocol = WireProtocol::Legacy;
    c.ideal = true;
    SimulatedDevice device(c);
    QCOMPARE(device.step().tau_ext, 0.0);
    device.receive("ia1350b0c0d0o");
    SimulatedDevice::Cycle cycle = device.step();
    QVERIFY(std::abs(cycle.tau_ext - 0.35 * 0.44) < 1e-12);
    // No watchdog in the published firmware: the force stays.
    for (int i = 0; i < 1000; ++i)
        cycle = device.step();
    QVERIFY(std::abs(cycle.tau_ext - 0.35 * 0.44) < 1e-12);
    QVERIFY(!(cycle.flags & v2::kFlagFeedbackStale));
    // Split over several writes, negative offset.
    device.receive("ia8");
    device.receive("00b0c0d0o");
    QVERIFY(std::abs(device.step().tau_ext + 0.2 * 0.44) < 1e-12);
    // A malformed frame is ignored.
    device.receive("iaxyzb0c0d0o");
    QVERIFY(std::abs(device.step().tau_ext + 0.2 * 0.44) < 1e-12);
}

void TestSimulatedDeviceModel::legacyBusyWaitHazard()
{
    SimulatedDevice::Config c;
    c.protocol = WireProtocol::Legacy;
    c.hand = handOf(u"const:0.05"_s);
    SimulatedDevice device(c);
    legacy::Decoder decoder;
    QList<legacy::Frame> frames;
    device.advance(1.05); // frames at 0.2 s … 1.0 s
    decoder.feed(device.takeOutput(), frames);
    QCOMPARE(frames.size(), 5);

    device.receive("i"); // an 'i' without its 'o': the firmware waits
    const SimulatedDevice::Cycle frozen = device.step();
    frames.clear();
    device.advance(2.0);
    decoder.feed(device.takeOutput(), frames);
    QCOMPARE(frames.size(), 0);
    QCOMPARE(device.step().t, frozen.t); // no control cycle ran

    device.receive("a1000b0c0d0o"); // the 'o' releases it
    device.advance(1.0);
    decoder.feed(device.takeOutput(), frames);
    QVERIFY(frames.size() >= 4 && frames.size() <= 6);
    QVERIFY(device.step().t > frozen.t + 2.9);
}

void TestSimulatedDeviceModel::legacyIgnoresV2()
{
    SimulatedDevice::Config c;
    c.protocol = WireProtocol::Legacy;
    SimulatedDevice device(c);
    device.advance(0.05);
    device.takeOutput();
    // HELLO seq 0 (no 0x69 byte) and a SET_STREAM: no reply, frames keep coming.
    device.receive(QByteArray::fromHex("0201033e2e00"));
    device.receive(v2::encodeFrame(2, v2::SetStream{1000}));
    legacy::Decoder decoder;
    QList<legacy::Frame> frames;
    QStringList text;
    device.advance(1.0);
    const QByteArray out = device.takeOutput();
    decoder.feed(out, frames, &text);
    QCOMPARE(frames.size(), 5);
    QVERIFY(text.isEmpty());
    QVERIFY(!out.contains('\0'));
}

QTEST_GUILESS_MAIN(TestSimulatedDeviceModel)
#include "tst_simulateddevicemodel.moc"
