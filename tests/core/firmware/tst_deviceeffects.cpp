// The device core renders effects.md's effects in its control cycle and speaks their protocol
// v2 additions (§ 3): the capability bit, SET_EFFECTS valid and per bad field, GET_EFFECTS,
// VIBRATE, τ_fx in TELEMETRY and in τ_total, SAVE_PARAMS keeping the block. Driven through the
// simulator's ideal mode, which runs this very core with the model as its actuator.
#include "model/effects.h"
#include "model/stiffness.h"
#include "protocol/v2codec.h"
#include "sim/simulateddevice.h"
#include "simdevicehost.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace hatpic;
using simdevicehost::Host;
using simdevicehost::idealConfig;

namespace {

EffectParams wallsAt(double half, double k)
{
    EffectParams fx;
    fx.wall_min = -half;
    fx.wall_max = half;
    fx.wall_stiffness = k;
    return fx;
}

} // namespace

class TestDeviceEffects : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void helloAnnouncesEffects()
    {
        Host host(idealConfig());
        host.send(1, v2::Hello{});
        const auto hello = host.reply<v2::HelloReply>();
        QVERIFY(hello);
        QCOMPARE(hello->capabilities & v2::kCapabilityEffects, v2::kCapabilityEffects);
    }

    void defaultsAreValidAndRenderNothing()
    {
        Host host(idealConfig(QStringLiteral("sine:0.2:1")));
        host.send(1, v2::GetEffects{});
        const auto fx = host.reply<v2::Effects>();
        QVERIFY(fx);
        QVERIFY(validate(fx->effects, 0.44).empty()); // ±π kept inside the range as floats
        for (int i = 0; i < 2000; ++i) {
            const SimulatedDevice::Cycle c = host.device.step();
            QCOMPARE(c.tau_total, std::clamp(c.tau_rec + c.tau_ext, -0.44, 0.44));
        }
    }

    void setEffectsRejectsEachBadField_data()
    {
        QTest::addColumn<int>("field");
        QTest::addColumn<double>("value");
        QTest::newRow("detent_strength above tau_limit") << 0 << 0.5;
        QTest::newRow("detent_spacing below 0.01") << 1 << 0.005;
        QTest::newRow("detent_range negative") << 2 << -0.1;
        QTest::newRow("wall_min positive") << 3 << 0.1;
        QTest::newRow("wall_max negative") << 4 << -0.1;
        QTest::newRow("wall_stiffness above 50") << 5 << 60.0;
        QTest::newRow("wall_damping NaN") << 6 << std::nan("");
    }
    void setEffectsRejectsEachBadField()
    {
        QFETCH(int, field);
        QFETCH(double, value);
        Host host(idealConfig());
        EffectParams fx = roundedForWire(wallsAt(0.5, 5), 0.44);
        fx.setField(field, value);
        host.send(3, v2::SetEffects{fx});
        const auto ack = host.reply<v2::Ack>();
        QVERIFY(ack);
        QCOMPARE(ack->status, v2::AckStatus::OutOfRange);
        QCOMPARE(int(ack->field), field);
        host.send(4, v2::GetEffects{});
        const auto now = host.reply<v2::Effects>();
        QVERIFY(now);
        QCOMPARE(now->effects, roundedForWire(EffectParams{}, 0.44)); // untouched
    }

    void wallIsRenderedInTauFxAndTelemetry()
    {
        // A hand pushing 0.2 N·m against a wall at 0.3 rad with K_w = 5: the spring, the wall
        // and the hand balance beyond the wall.
        Host host(idealConfig(QStringLiteral("const:0.2")));
        const EffectParams fx = roundedForWire(wallsAt(0.3, 5), 0.44);
        host.send(1, v2::SetEffects{fx});
        const auto ack = host.reply<v2::Ack>();
        QVERIFY(ack && ack->status == v2::AckStatus::Ok);
        host.send(2, v2::SetStream{1000});
        QVERIFY(host.reply<v2::Ack>());
        SimulatedDevice::Cycle c;
        for (int i = 0; i < 3000; ++i)
            c = host.device.step();
        const double e = c.theta;
        QVERIFY2(e > 0.3, qPrintable(QString::number(e)));
        const double expectedFx = wallTorque(fx, e, c.omega);
        const double tauRec = recenteringTorque(host.device.params(), c.theta);
        QCOMPARE(c.tau_total, std::clamp(tauRec + expectedFx, -0.44, 0.44));
        // At rest: τ_rec + τ_wall balances the hand.
        QVERIFY(std::abs(tauRec + expectedFx + 0.2) < 1e-3);
        // TELEMETRY carries τ_fx.
        bool seen = false;
        for (const v2::Frame &f : host.take()) {
            if (const auto *t = std::get_if<v2::Telemetry>(&f.message)) {
                QVERIFY(t->tau_fx.has_value());
                seen = true;
            }
        }
        QVERIFY(seen);
    }

    void vibrationBurst()
    {
        Host host(idealConfig());
        host.send(1, v2::Vibrate{0.1f, 50.0f, 0.2f});
        const auto ack = host.reply<v2::Ack>();
        QVERIFY(ack && ack->status == v2::AckStatus::Ok);
        // τ_fx follows a·sin(2π·f·(t − t_start)) for d seconds, then stops.
        double peak = 0;
        int active = 0;
        for (int i = 0; i < 400; ++i) {
            const SimulatedDevice::Cycle c = host.device.step();
            const double fx = c.tau_total - std::clamp(c.tau_rec + c.tau_ext, -0.44, 0.44);
            peak = std::max(peak, std::abs(fx));
            active += std::abs(fx) > 1e-9;
        }
        QVERIFY2(std::abs(peak - 0.1) < 1e-3, qPrintable(QString::number(peak)));
        QVERIFY2(active > 150 && active <= 200, qPrintable(QString::number(active)));
    }

    void vibrateOutOfRange()
    {
        Host host(idealConfig());
        host.send(1, v2::Vibrate{0.1f, 600.0f, 0.2f}); // above 500 Hz and above Nyquist
        auto ack = host.reply<v2::Ack>();
        QVERIFY(ack);
        QCOMPARE(ack->status, v2::AckStatus::OutOfRange);
        QCOMPARE(int(ack->field), 1);
        host.send(2, v2::Vibrate{0.0f, 0.0f, 0.0f}); // a = 0 stops, whatever f and d
        ack = host.reply<v2::Ack>();
        QVERIFY(ack);
        QCOMPARE(ack->status, v2::AckStatus::Ok);
    }

    void detentsPullToRestPositions()
    {
        // No re-centering spring beyond the dead zone (K_min = K_max = 0), detents every
        // 0.2 rad: a knob let go near 0.23 rad settles at the rest position 0.2.
        SimulatedDevice::Config c = idealConfig();
        c.params.K_min = 0;
        c.params.K_max = 0;
        c.params.theta0 = 0.23;
        Host host(c);
        EffectParams fx;
        fx.detent_strength = 0.05;
        fx.detent_spacing = 0.2;
        fx.detent_range = 0.8;
        host.send(1, v2::SetEffects{roundedForWire(fx, 0.44)});
        QVERIFY(host.reply<v2::Ack>());
        DeviceParams p = host.device.params();
        p.theta0 = 0;
        host.send(2, v2::SetParams{p});
        QVERIFY(host.reply<v2::Ack>());
        SimulatedDevice::Cycle cycle;
        for (int i = 0; i < 4000; ++i)
            cycle = host.device.step();
        QVERIFY2(std::abs(cycle.theta - 0.2) < 1e-3, qPrintable(QString::number(cycle.theta)));
    }
};

QTEST_GUILESS_MAIN(TestDeviceEffects)
#include "tst_deviceeffects.moc"
