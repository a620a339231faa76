// The device core speaks the passivity controller's protocol v2 additions (docs/protocol.md):
// the capability bit, SET_PASSIVITY valid and per bad field, GET_PASSIVITY, τ_pc and R in
// TELEMETRY, SAVE_PARAMS keeping the block in the state file and power-up reading it back.
// Driven through the simulator's ideal mode, which runs this very core.
#include "model/passivity.h"
#include "profile/profile.h"
#include "protocol/v2codec.h"
#include "sim/simulateddevice.h"
#include "simdevicehost.h"

#include <QTemporaryDir>
#include <QTest>

using namespace hatpic;
using namespace Qt::StringLiterals;
using simdevicehost::Host;

namespace {

SimulatedDevice::Config idealConfig()
{
    return simdevicehost::idealConfig(u"const:0.05"_s);
}

PassivityParams pc(double betaMax, double reserveMax)
{
    PassivityParams p;
    p.pc_damping_max = betaMax;
    p.pc_reserve_max = reserveMax;
    return p;
}

} // namespace

class TestDevicePassivity : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void helloAnnouncesPassivity()
    {
        Host host(idealConfig());
        host.send(1, v2::Hello{});
        const auto hello = host.reply<v2::HelloReply>();
        QVERIFY(hello);
        QCOMPARE(hello->capabilities & v2::kCapabilityPassivity, v2::kCapabilityPassivity);
        QCOMPARE(hello->capabilities & v2::kCapabilityEffects, v2::kCapabilityEffects);
    }

    void defaultsAreOnAndReadBack()
    {
        Host host(idealConfig());
        host.send(1, v2::GetPassivity{});
        const auto got = host.reply<v2::Passivity>();
        QVERIFY(got);
        QVERIFY(sameOnWire(got->passivity, PassivityParams{}));
        QVERIFY(got->passivity.enabled());
    }

    void setPassivityValidatesPerField_data()
    {
        QTest::addColumn<double>("beta");
        QTest::addColumn<double>("reserve");
        QTest::addColumn<int>("field");
        QTest::newRow("valid") << 0.3 << 0.01 << -1;
        QTest::newRow("off") << 0.0 << 0.0 << -1;
        QTest::newRow("beta above 1") << 1.5 << 0.01 << 0;
        QTest::newRow("beta negative") << -0.1 << 0.01 << 0;
        QTest::newRow("beta NaN") << std::nan("") << 0.01 << 0;
        QTest::newRow("reserve above 1") << 0.3 << 2.0 << 1;
        QTest::newRow("reserve infinite") << 0.3 << HUGE_VAL << 1;
    }
    void setPassivityValidatesPerField()
    {
        QFETCH(double, beta);
        QFETCH(double, reserve);
        QFETCH(int, field);
        Host host(idealConfig());
        host.send(1, v2::SetPassivity{pc(beta, reserve)});
        const auto ack = host.reply<v2::Ack>();
        QVERIFY(ack);
        host.send(2, v2::GetPassivity{});
        const auto got = host.reply<v2::Passivity>();
        QVERIFY(got);
        if (field < 0) {
            QCOMPARE(ack->status, v2::AckStatus::Ok);
            QVERIFY(sameOnWire(got->passivity, pc(beta, reserve)));
        } else {
            QCOMPARE(ack->status, v2::AckStatus::OutOfRange);
            QCOMPARE(int(ack->field), field);
            QVERIFY(sameOnWire(got->passivity, PassivityParams{})); // unchanged
        }
    }

    void telemetryCarriesTauPcAndReserve()
    {
        Host host(idealConfig());
        host.send(1, v2::SetPassivity{pc(0.5, 0.003)});
        host.send(2, v2::SetStream{100});
        const auto t = host.reply<v2::Telemetry>();
        QVERIFY(t);
        QVERIFY(t->tau_fx);
        QVERIFY(t->tau_pc);
        QVERIFY(t->pc_reserve);
        QCOMPARE(*t->tau_pc, 0.0f); // no τ_ext: nothing to damp
        // The tank at its floor's level for a knob at start, capped at once by an R_max below it.
        QCOMPARE(*t->pc_reserve, float(0.003f));
    }

    void controllerDampsWhatThePortGivesBack()
    {
        // A τ_ext pushing along the knob's motion gives energy: with an empty tank the
        // controller damps at once, and reports it.
        SimulatedDevice::Config c = idealConfig();
        c.passivity = pc(0.5, 0.0);
        SimulatedDevice device(c);
        device.receive(v2::encodeFrame(0, v2::SetFeedback{0.02f}));
        double most = 0, lastReserve = 1;
        for (int k = 0; k < 100; ++k) {
            const SimulatedDevice::Cycle cycle = device.step();
            most = std::min(most, cycle.tau_pc);
            lastReserve = cycle.pc_reserve;
        }
        QVERIFY(most < 0);
        QVERIFY(std::abs(lastReserve) < 1e-9);
        // Off: the same run, nothing.
        c.passivity = pc(0.0, 0.0);
        SimulatedDevice off(c);
        off.receive(v2::encodeFrame(0, v2::SetFeedback{0.02f}));
        for (int k = 0; k < 100; ++k)
            QCOMPARE(off.step().tau_pc, 0.0);
    }

    void saveParamsKeepsTheBlock()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        SimulatedDevice::Config c = idealConfig();
        c.stateFile = dir.filePath(u"state.json"_s);
        const PassivityParams saved = pc(0.25, 0.005);
        {
            Host host(c);
            host.send(1, v2::SetPassivity{saved});
            QCOMPARE(host.reply<v2::Ack>()->status, v2::AckStatus::Ok);
            host.send(2, v2::SaveParams{});
            QCOMPARE(host.reply<v2::Ack>()->status, v2::AckStatus::Ok);
        }
        const ProfileReadResult read = readProfile(c.stateFile);
        QVERIFY2(read.ok(), qPrintable(read.errors.join(u"; "_s)));
        QVERIFY(sameOnWire(read.profile->passivity, saved));
        Host again(c);
        again.send(1, v2::GetPassivity{});
        const auto got = again.reply<v2::Passivity>();
        QVERIFY(got);
        QVERIFY(sameOnWire(got->passivity, saved));
    }

    void profileRoundTripAndErrors()
    {
        Profile p;
        p.passivity = pc(0.0, 0.03);
        const ProfileReadResult back = parseProfile(serializeProfile(p));
        QVERIFY2(back.ok(), qPrintable(back.errors.join(u"; "_s)));
        QCOMPARE(back.profile->passivity, p.passivity);
        // The defaults are not written: a profile without the block stays as it was.
        QVERIFY(!serializeProfile(Profile{}).contains("passivity"));
        const QByteArray bad =
            serializeProfile(p).replace("\"pc_damping_max\": 0.0", "\"pc_damping_max\": 2.0");
        const ProfileReadResult refused = parseProfile(bad);
        QVERIFY(!refused.ok());
        QCOMPARE(refused.errors,
                 QStringList{u"device.passivity.pc_damping_max: must be ≤ 1, got 2"_s});
    }
};

QTEST_GUILESS_MAIN(TestDevicePassivity)
#include "tst_devicepassivity.moc"
