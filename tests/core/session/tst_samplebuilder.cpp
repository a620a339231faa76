// SampleBuilder: session clock, reference model per sample, legacy estimation.
#include "model/reference.h"
#include "model/stiffness.h"
#include "session/samplebuilder.h"

#include <QTest>

#include <cmath>

using namespace hatpic;

namespace {

v2::Telemetry telemetry(quint32 tUs, float theta, quint8 flags = 0)
{
    v2::Telemetry t;
    t.t_us = tUs;
    t.theta = theta;
    t.omega = 0.5f;
    t.tau = -0.01f;
    t.tau_rec = -0.02f;
    t.tau_ext = 0.01f;
    t.flags = flags;
    return t;
}

} // namespace

class TestSampleBuilder : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void clockFollowsDeviceSteps_data();
    void clockFollowsDeviceSteps();
    void gapUsesHostTimeAndHoldsReference();
    void unfollowedStepHoldsReferenceEvenWhenHostStepIsShort_data();
    void unfollowedStepHoldsReferenceEvenWhenHostStepIsShort();
    void reconnectUsesHostTime();
    void referenceIntegratesOverDeviceTime();
    void resetReference();
    void tauTotalIsClamped();
    void quantitiesAsSent_data();
    void quantitiesAsSent();
    void legacyIsEstimatedFromTheModel_data();
    void legacyIsEstimatedFromTheModel();
};

void TestSampleBuilder::clockFollowsDeviceSteps_data()
{
    QTest::addColumn<quint32>("first");
    QTest::addColumn<quint32>("second");
    QTest::addColumn<qint64>("hostStep"); // [µs], ignored while the device step is valid
    QTest::addColumn<double>("expected");
    QTest::newRow("1 ms") << 1000u << 2000u << qint64(5000) << 0.001;
    QTest::newRow("wraps at 2^32") << 0xFFFFFC18u << 1000u << qint64(1) << 0.002;
    QTest::newRow("same timestamp") << 5000u << 5000u << qint64(1000) << 0.0;
    QTest::newRow("250 ms is still followed") << 0u << 250000u << qint64(900000) << 0.25;
    QTest::newRow("gap: host time") << 0u << 1000000u << qint64(1200000) << 1.2;
    QTest::newRow("clock went back: host time") << 5000000u << 1000u << qint64(30000) << 0.03;
}

void TestSampleBuilder::clockFollowsDeviceSteps()
{
    QFETCH(quint32, first);
    QFETCH(quint32, second);
    QFETCH(qint64, hostStep);
    QFETCH(double, expected);
    SampleBuilder b;
    const Sample a = b.fromTelemetry(telemetry(first, 0), 10'000'000);
    QCOMPARE(a.t_s, 0.0);
    QCOMPARE(a.t_us, first);
    const Sample c = b.fromTelemetry(telemetry(second, 0), 10'000'000 + hostStep);
    QCOMPARE(c.t_s, expected);
    QCOMPARE(c.t_us, second);
}

void TestSampleBuilder::gapUsesHostTimeAndHoldsReference()
{
    SampleBuilder b;
    b.fromTelemetry(telemetry(0, 0.5f), 0);
    const Sample s1 = b.fromTelemetry(telemetry(1000, 0.5f), 1000);
    QVERIFY(s1.p_ref > 0);
    QCOMPARE(s1.flags & kFlagReferenceGap, 0);
    const Sample s2 = b.fromTelemetry(telemetry(501000, 0.5f), 600000);
    QCOMPARE(s2.t_s, 0.001 + 0.599);
    QVERIFY(s2.flags & kFlagReferenceGap);
    QCOMPARE(s2.p_ref, s1.p_ref); // held across the gap
    QCOMPARE(b.referenceGaps(), quint64(1));
    const Sample s3 = b.fromTelemetry(telemetry(502000, 0.5f), 601000);
    QCOMPARE(s3.flags & kFlagReferenceGap, 0);
    QVERIFY(s3.p_ref > s2.p_ref);
}

void TestSampleBuilder::unfollowedStepHoldsReferenceEvenWhenHostStepIsShort_data()
{
    QTest::addColumn<quint32>("second"); // device clock of the second sample; first is 1000 µs
    QTest::addColumn<bool>("reconnect");
    QTest::addColumn<qint64>("hostStep"); // [µs]
    QTest::newRow("device clock jumped 1 s, host 10 ms") << 1'001'000u << false << qint64(10'000);
    QTest::newRow("device clock went back, host 30 ms") << 0u << false << qint64(30'000);
    QTest::newRow("reconnect 1 ms ahead, host 100 ms") << 2000u << true << qint64(100'000);
}

void TestSampleBuilder::unfollowedStepHoldsReferenceEvenWhenHostStepIsShort()
{
    // model.md § 4: a device step over 0.25 s (or a new connection's unrelated clock) is not
    // integrated, whatever the host time between the two receptions.
    QFETCH(quint32, second);
    QFETCH(bool, reconnect);
    QFETCH(qint64, hostStep);
    SampleBuilder b;
    b.fromTelemetry(telemetry(0, 0.5f), 0);
    const Sample s1 = b.fromTelemetry(telemetry(1000, 0.5f), 1000);
    QVERIFY(s1.p_ref > 0);
    if (reconnect)
        b.markDiscontinuity();
    const Sample s2 = b.fromTelemetry(telemetry(second, 0.5f), 1000 + hostStep);
    QCOMPARE(s2.t_s, (1000 + hostStep) * 1e-6); // t_s follows the host here
    QVERIFY(s2.flags & kFlagReferenceGap);
    QCOMPARE(s2.p_ref, s1.p_ref);
    QCOMPARE(b.referenceGaps(), quint64(1));
    const Sample s3 = b.fromTelemetry(telemetry(second + 1000, 0.5f), 2000 + hostStep);
    QCOMPARE(s3.flags & kFlagReferenceGap, 0);
    QVERIFY(std::abs(s3.p_ref - s2.p_ref - 0.25 * 0.001) < 1e-12); // v_ref = v_max/2·θ, 1 ms
}

void TestSampleBuilder::reconnectUsesHostTime()
{
    SampleBuilder b;
    b.fromTelemetry(telemetry(7'000'000, 0), 0);
    b.markDiscontinuity();
    // A restarted device whose clock happens to be only 1 ms ahead: not comparable.
    const Sample s = b.fromTelemetry(telemetry(7'001'000, 0), 800'000);
    QCOMPARE(s.t_s, 0.8);
    QVERIFY(s.flags & kFlagReferenceGap);
    const Sample next = b.fromTelemetry(telemetry(7'002'000, 0), 800'050);
    QCOMPARE(next.t_s, 0.801); // and device steps again from there
}

void TestSampleBuilder::referenceIntegratesOverDeviceTime()
{
    SampleBuilder b;
    HostParams host;
    host.v_max = 2;
    host.ref_deadzone = false;
    b.setHostParams(host);
    DeviceParams dev;
    dev.theta0 = 0.1;
    b.setDeviceParams(dev);
    ReferenceGenerator ref;
    double p = 0;
    for (int i = 0; i < 100; ++i) {
        const float theta = 0.1f + 0.003f * float(i);
        // Host jitter does not enter: only device timestamps do.
        const Sample s =
            b.fromTelemetry(telemetry(quint32(i) * 1000u, theta), i * 1000 + (i % 3) * 700);
        const auto expected = ref.update(quint32(i) * 1000u, host, dev, theta);
        QCOMPARE(s.v_ref, expected.v_ref);
        QCOMPARE(s.p_ref, expected.p_ref);
        p = s.p_ref;
    }
    QVERIFY(p > 0);
}

void TestSampleBuilder::resetReference()
{
    SampleBuilder b;
    for (int i = 0; i < 10; ++i)
        b.fromTelemetry(telemetry(quint32(i) * 1000u, 0.5f), i * 1000);
    b.resetReference();
    const Sample s = b.fromTelemetry(telemetry(10000, 0.5f), 10000);
    QCOMPARE(s.p_ref, 0.5 * (s.v_ref + s.v_ref) * 1e-3);
}

void TestSampleBuilder::tauTotalIsClamped()
{
    SampleBuilder b;
    b.setTauLimit(0.02);
    const Sample s = b.fromTelemetry(telemetry(0, 0), 0); // τ_rec −0.02 + τ_ext 0.01
    QCOMPARE(s.tau_total, double(-0.02f) + double(0.01f));
    v2::Telemetry big = telemetry(1000, 0);
    big.tau_ext = 0.5f;
    QCOMPARE(b.fromTelemetry(big, 1000).tau_total, 0.02);
}

void TestSampleBuilder::quantitiesAsSent_data()
{
    QTest::addColumn<bool>("effects");
    QTest::addColumn<bool>("passivity");
    QTest::newRow("no capability: 25 bytes") << false << false;
    QTest::newRow("effects: 29 bytes") << true << false;
    QTest::newRow("passivity: 37 bytes") << true << true;
}

void TestSampleBuilder::quantitiesAsSent()
{
    QFETCH(bool, effects);
    QFETCH(bool, passivity);
    v2::Telemetry t = telemetry(4000, 0.25f, v2::kFlagNotch | v2::kFlagFeedbackStale);
    if (effects)
        t.tau_fx = 0.03f;
    if (passivity) {
        t.tau_pc = -0.004f;
        t.pc_reserve = 0.0125f;
    }
    SampleBuilder b;
    const Sample s = b.fromTelemetry(t, 0);
    QCOMPARE(s.t_us, 4000u);
    QCOMPARE(s.theta, double(0.25f));
    QCOMPARE(s.omega, double(0.5f));
    QCOMPARE(s.tau, double(-0.01f));
    QCOMPARE(s.tau_rec, double(-0.02f));
    QCOMPARE(s.tau_ext, double(0.01f));
    QCOMPARE(int(s.flags & 0xFF), int(v2::kFlagNotch | v2::kFlagFeedbackStale));
    // Not sent: unknown (NaN), not zero; τ_total counts τ_fx only where it is known.
    QCOMPARE(std::isnan(s.tau_fx), !effects);
    QCOMPARE(std::isnan(s.tau_pc), !passivity);
    QCOMPARE(std::isnan(s.pc_reserve), !passivity);
    const double fx = effects ? double(0.03f) : 0.0;
    QCOMPARE(s.tau_total, double(-0.02f) + fx + double(0.01f));
    if (effects)
        QCOMPARE(s.tau_fx, double(0.03f));
    if (passivity) {
        QCOMPARE(s.tau_pc, double(-0.004f));
        QCOMPARE(s.pc_reserve, double(0.0125f));
    }
}

void TestSampleBuilder::legacyIsEstimatedFromTheModel_data()
{
    QTest::addColumn<int>("ticks");
    QTest::addColumn<double>("tauExt");
    QTest::addColumn<int>("zoneFlag");
    QTest::addColumn<bool>("saturated");
    QTest::newRow("center: dead zone") << 1000 << 0.0 << int(v2::kFlagDeadZone) << false;
    QTest::newRow("notch band") << 1040 << 0.0 << int(v2::kFlagNotch) << false;
    QTest::newRow("outer band") << 1200 << 0.0 << 0 << false;
    QTest::newRow("saturated by feedback") << 1040 << 0.5 << int(v2::kFlagNotch) << true;
}

void TestSampleBuilder::legacyIsEstimatedFromTheModel()
{
    QFETCH(int, ticks);
    QFETCH(double, tauExt);
    QFETCH(int, zoneFlag);
    QFETCH(bool, saturated);
    SampleBuilder b;
    legacy::Conversion conv;
    const Sample s = b.fromLegacy({ticks, 1000, 1000, 1000}, conv, {tauExt}, 123456);
    QCOMPARE(s.theta, conv.ticksToRad(ticks));
    QVERIFY(std::isnan(s.omega));
    QVERIFY(std::isnan(s.tau));
    QVERIFY(std::isnan(s.tau_fx) && std::isnan(s.tau_pc) && std::isnan(s.pc_reserve));
    QCOMPARE(s.tau_rec, recenteringTorque(DeviceParams(), s.theta));
    QCOMPARE(s.tau_ext, tauExt);
    QCOMPARE(s.tau_total, std::clamp(s.tau_rec + tauExt, -0.44, 0.44));
    QCOMPARE(s.t_us, 123456u);
    QVERIFY(s.flags & kFlagModelEstimated);
    QCOMPARE(int(s.flags & (v2::kFlagDeadZone | v2::kFlagNotch)), zoneFlag);
    QCOMPARE(bool(s.flags & v2::kFlagSaturated), saturated);
    // The host clock drives t_s: 200 ms later.
    const Sample next = b.fromLegacy({ticks, 1000, 1000, 1000}, conv, {tauExt}, 323456);
    QCOMPARE(next.t_s, 0.2);
}

QTEST_GUILESS_MAIN(TestSampleBuilder)
#include "tst_samplebuilder.moc"
