// hatpicctl and the haptic effects (effects.md), run as a real process: curve's tau_det and
// tau_wall against the formulas written out again, simulate --ideal with an effects profile
// against the model with τ_fx row by row, and set / get / vibrate against the in-process
// simulated joystick (`--port sim`) and hatpic-sim's legacy emulation on a pty.
#include "ctlprocess.h"
#include "model/admittance.h"
#include "model/effects.h"
#include "profile/profile.h"

#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

//! Every value exactly a float, so the device's float32 block is the same numbers.
Profile effectsProfile()
{
    Profile p;
    p.name = u"fx"_s;
    p.device = exactParams();
    p.effects = EffectParams{.detent_strength = 0.03125,
                             .detent_spacing = 0.25,
                             .detent_range = 0.5,
                             .wall_min = -0.5,
                             .wall_max = 0.375,
                             .wall_stiffness = 2,
                             .wall_damping = 0.015625};
    return p;
}

// τ_det and τ_wall of effects.md § 1, written out again so the test does not trust the library.
double expectedDetent(const EffectParams &fx, double e)
{
    if (!(fx.detent_strength > 0) || std::abs(e) > fx.detent_range)
        return 0;
    return -fx.detent_strength * std::sin(2 * std::numbers::pi * e / fx.detent_spacing);
}

double expectedWall(const EffectParams &fx, double e, double omega)
{
    double beyond = 0;
    if (e > fx.wall_max)
        beyond = e - fx.wall_max;
    else if (e < fx.wall_min)
        beyond = e - fx.wall_min;
    if (beyond == 0)
        return 0;
    const double spring = -fx.wall_stiffness * beyond;
    return omega * beyond > 0 ? spring - fx.wall_damping * omega : spring;
}

} // namespace

class TestHatpicCtlEffects : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void curveHasStaticEffectTorques();
    void simulateIdealWithEffectsMatchesModel_data();
    void simulateIdealWithEffectsMatchesModel();
    void setAndGetEffects();
    void invalidEffectIsRefusedBeforeSending();
    void unknownNameListsEffects();
    void vibrate();
    void vibrateRefusals_data();
    void vibrateRefusals();
    void legacyDeviceHasNoEffects(); // nor a passivity controller
    void torqueLimitIsTheDevicesFloat();

private:
    QTemporaryDir m_dir;
    QString m_profile;
};

void TestHatpicCtlEffects::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_profile = m_dir.filePath(u"fx.json"_s);
    QCOMPARE(writeProfile(effectsProfile(), m_profile), QString());
}

void TestHatpicCtlEffects::curveHasStaticEffectTorques()
{
    const Run run = runCtl({u"curve"_s, u"--profile"_s, m_profile, u"--from"_s, u"-1"_s, u"--to"_s,
                            u"1"_s, u"--step"_s, u"0.001"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QString problem;
    const auto rows = parseCsv(run.out, "theta,K_rec,tau_rec,tau_det,tau_wall", &problem);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QCOMPARE(rows.size(), 2001);
    const Profile p = effectsProfile();
    bool sawDetent = false;
    bool sawWall = false;
    for (const auto &row : rows) {
        const double e = row[0] - p.device.theta0;
        QVERIFY2(closeTo(row[3], expectedDetent(p.effects, e), 1e-12),
                 qPrintable(u"tau_det at "_s + QString::number(row[0])));
        QVERIFY2(closeTo(row[4], expectedWall(p.effects, e, 0), 1e-12),
                 qPrintable(u"tau_wall at "_s + QString::number(row[0])));
        sawDetent = sawDetent || std::abs(row[3]) > 0.03;
        sawWall = sawWall || row[4] > 0.2; // below wall_min: pushed back up
    }
    QVERIFY(sawDetent && sawWall);
}

void TestHatpicCtlEffects::simulateIdealWithEffectsMatchesModel_data()
{
    QTest::addColumn<QString>("spec");
    QTest::newRow("into the upper wall through the detents") << u"const:0.15"_s;
    QTest::newRow("into the lower wall") << u"const:-0.2"_s;
    QTest::newRow("back and forth") << u"sine:0.2:1.5"_s;
}

void TestHatpicCtlEffects::simulateIdealWithEffectsMatchesModel()
{
    QFETCH(QString, spec);
    const double rate = 1000;
    const Run run = runCtl({u"simulate"_s, u"--profile"_s, m_profile, u"--input"_s, spec,
                            u"--ideal"_s, u"--duration"_s, u"1"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QString problem;
    const auto table =
        parseCsv(run.out,
                 "t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags,tau_fx,tau_pc,"
                 "pc_reserve",
                 &problem);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QCOMPARE(table.size(), 1001);
    const Profile pr = effectsProfile();
    const DeviceParams &p = pr.device;
    const QStringList parts = spec.split(u':');
    const auto operatorTorque = [&](double t) {
        if (parts[0] == u"const")
            return parts[1].toDouble();
        return parts[1].toDouble() * std::sin(2 * std::numbers::pi * parts[2].toDouble() * t);
    };
    const double h = 1.0 / rate;
    AdmittanceState state{p.theta0, 0.0};
    double deepest = 0;
    for (qsizetype k = 0; k < table.size(); ++k) {
        const auto &row = table[k];
        const double tau = -operatorTorque(double(k) * h);
        const double e = state.theta - p.theta0;
        const double tauRec = -expectedStiffness(p, state.theta) * e;
        const double tauFx =
            expectedDetent(pr.effects, e) + expectedWall(pr.effects, e, state.omega);
        const double tauTotal = std::clamp(tauRec + tauFx, -pr.host.tau_limit, pr.host.tau_limit);
        const QString where = u"row "_s + QString::number(k);
        QVERIFY2(closeTo(row[1], state.theta, 1e-12),
                 qPrintable(where + u": theta "_s + QString::number(row[1], 'g', 17) + u" vs "_s +
                            QString::number(state.theta, 'g', 17)));
        QVERIFY2(closeTo(row[2], state.omega, 1e-9), qPrintable(where + u": omega"_s));
        QVERIFY2(closeTo(row[4], tauRec, 1e-12), qPrintable(where + u": tau_rec"_s));
        QVERIFY2(closeTo(row[10], tauFx, 1e-12),
                 qPrintable(where + u": tau_fx "_s + QString::number(row[10], 'g', 17) + u" vs "_s +
                            QString::number(tauFx, 'g', 17)));
        QVERIFY2(closeTo(row[6], tauTotal, 1e-12), qPrintable(where + u": tau_total"_s));
        deepest = std::max({deepest, e - pr.effects.wall_max, pr.effects.wall_min - e});
        state = admittanceStep(p, state, -tau + tauTotal, h);
    }
    QVERIFY2(deepest > 0, "the knob never reached a wall: the test would not check τ_wall");
}

void TestHatpicCtlEffects::setAndGetEffects()
{
    const Run get = runCtl({u"get"_s, u"--port"_s, u"sim"_s});
    QVERIFY2(get.code == 0, qPrintable(describe(get)));
    // Seven parameter lines, then seven effect lines (the simulator has the capability), then
    // the passivity controller's two (tst_hatpicctlpassivity).
    const QList<QByteArray> lines = get.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 16);
    QVERIFY2(lines[7].startsWith("detent_strength 0 "), lines[7].constData());
    QVERIFY2(lines[13].startsWith("wall_damping "), lines[13].constData());

    const Run set = runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--set"_s, u"detent_strength=0.05"_s,
                            u"--set"_s, u"wall_max=0.5"_s, u"--set"_s, u"K_max=0.5"_s});
    QVERIFY2(set.code == 0, qPrintable(describe(set)));
    QVERIFY(set.err.contains("The device accepted the parameters."));
    QVERIFY(set.err.contains("The device accepted the effects."));
    QVERIFY2(set.out.contains("\nK_max   0.5 "), set.out.constData());
    QVERIFY2(set.out.contains("\ndetent_strength 0.05 "), set.out.constData());
    QVERIFY2(set.out.contains("\nwall_max        0.5 "), set.out.constData());

    // --json: a profile with device.effects that reads back as what was set.
    const Run json =
        runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--set"_s, u"wall_stiffness=3"_s, u"--json"_s});
    QVERIFY2(json.code == 0, qPrintable(describe(json)));
    const ProfileReadResult read = parseProfile(json.out);
    QVERIFY2(read.ok(), qPrintable(read.errors.join(u'\n')));
    QCOMPARE(read.profile->effects.wall_stiffness, 3.0);
    QCOMPARE(read.profile->effects.detent_strength, 0.0); // only the named field changed

    // A profile's effects go whole.
    const Run whole =
        runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--profile"_s, m_profile, u"--json"_s});
    QVERIFY2(whole.code == 0, qPrintable(describe(whole)));
    const ProfileReadResult back = parseProfile(whole.out);
    QVERIFY(back.ok());
    QVERIFY(back.profile->effects == effectsProfile().effects);
}

void TestHatpicCtlEffects::invalidEffectIsRefusedBeforeSending()
{
    const Run run = runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--set"_s, u"detent_strength=1"_s,
                            u"--set"_s, u"wall_min=0.2"_s});
    QCOMPARE(run.code, 4);
    QVERIFY2(run.err.contains("The effects are not valid; nothing was sent:"), run.err.constData());
    QVERIFY(run.err.contains("detent_strength"));
    QVERIFY(run.err.contains("wall_min"));
    QVERIFY(run.out.isEmpty());
}

void TestHatpicCtlEffects::unknownNameListsEffects()
{
    const Run run = runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--set"_s, u"detents=1"_s});
    QCOMPARE(run.code, 4);
    QVERIFY2(run.err.contains(", the effects detent_strength, detent_spacing"),
             run.err.constData());
}

void TestHatpicCtlEffects::vibrate()
{
    const Run run = runCtl({u"vibrate"_s, u"--port"_s, u"sim"_s, u"--amplitude"_s, u"0.1"_s,
                            u"--frequency"_s, u"80"_s, u"--duration"_s, u"0.5"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QVERIFY2(run.err.contains("The device plays the cue: 0.1 N·m at 80 Hz for 0.5 s."),
             run.err.constData());
}

void TestHatpicCtlEffects::vibrateRefusals_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("message");
    const QStringList base{u"vibrate"_s, u"--port"_s, u"sim"_s};
    QTest::newRow("missing duration")
        << base + QStringList{u"--amplitude"_s, u"0.1"_s, u"--frequency"_s, u"80"_s} << 4
        << u"vibrate needs --amplitude NM, --frequency HZ and --duration S."_s;
    QTest::newRow("not a number") << base + QStringList{u"--amplitude"_s, u"x"_s,
                                                        u"--frequency"_s, u"80"_s,
                                                        u"--duration"_s,  u"1"_s}
                                  << 4 << u"--amplitude must be a number, got 'x'."_s;
    QTest::newRow("above tau_limit (host check)")
        << base + QStringList{u"--amplitude"_s, u"1"_s,          u"--frequency"_s,
                              u"80"_s,          u"--duration"_s, u"1"_s}
        << 4 << u"The vibration cue is not valid: amplitude"_s;
    QTest::newRow("at Nyquist (device check)")
        << base + QStringList{u"--amplitude"_s, u"0.1"_s,        u"--frequency"_s,
                              u"500"_s,         u"--duration"_s, u"1"_s}
        << 2 << u"The device rejected VIBRATE (field 1): OUT_OF_RANGE."_s;
}

void TestHatpicCtlEffects::vibrateRefusals()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, code);
    QFETCH(QString, message);
    const Run run = runCtl(arguments);
    QVERIFY2(run.code == code, qPrintable(describe(run)));
    QVERIFY2(QString::fromUtf8(run.err).contains(message), run.err.constData());
}

void TestHatpicCtlEffects::legacyDeviceHasNoEffects()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not built");
#else
    QProcess sim;
    sim.setProgram(QStringLiteral(HATPIC_SIM_PATH));
    sim.setArguments({u"--protocol"_s, u"legacy"_s});
    sim.start();
    QVERIFY2(sim.waitForStarted(5000), qPrintable(sim.errorString()));
    QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
    const QString path = QString::fromLocal8Bit(sim.readLine()).trimmed();
    const QStringList legacy{u"--port"_s, path, u"--protocol"_s, u"legacy"_s};
    const Run cue = runCtl(QStringList{u"vibrate"_s} + legacy +
                           QStringList{u"--amplitude"_s, u"0.1"_s, u"--frequency"_s, u"80"_s,
                                       u"--duration"_s, u"1"_s});
    QVERIFY2(cue.code == 2, qPrintable(describe(cue)));
    QVERIFY2(cue.err.contains("VIBRATE is not available: the device runs the published firmware "
                              "(legacy protocol), which cannot render effects."),
             cue.err.constData());
    const Run set =
        runCtl(QStringList{u"set"_s} + legacy + QStringList{u"--set"_s, u"detent_strength=0.05"_s});
    QVERIFY2(set.code == 2, qPrintable(describe(set)));
    QVERIFY2(set.err.contains("SET_EFFECTS is not available"), set.err.constData());
    // Nor a passivity controller: named fields are refused before anything is sent.
    const Run pc =
        runCtl(QStringList{u"set"_s} + legacy + QStringList{u"--set"_s, u"pc_damping_max=0"_s});
    QVERIFY2(pc.code == 2, qPrintable(describe(pc)));
    QVERIFY2(pc.err.contains("SET_PASSIVITY is not available"), pc.err.constData());
    sim.terminate();
    QVERIFY(sim.waitForFinished(10000));
#endif
}

// The device reports tau_limit as the float 0.44f = 0.4399999976158142 and takes 0.44 (the
// same float); validate, set and vibrate compare alike and quote what the user wrote
// (issue 21).
void TestHatpicCtlEffects::torqueLimitIsTheDevicesFloat()
{
    const QStringList cue{u"vibrate"_s, u"--port"_s,     u"sim"_s, u"--frequency"_s,
                          u"80"_s,      u"--duration"_s, u"0.1"_s, u"--amplitude"_s};
    const Run atLimit = runCtl(cue + QStringList{u"0.44"_s});
    QVERIFY2(atLimit.code == 0, qPrintable(describe(atLimit)));
    QVERIFY(atLimit.err.contains("The device plays the cue: 0.44 N·m"));
    const Run beyond = runCtl(cue + QStringList{u"0.45"_s});
    QVERIFY2(beyond.code == 4, qPrintable(describe(beyond)));
    QVERIFY2(beyond.err.contains("amplitude: must be ≤ tau_limit (0.44), got 0.45;"),
             beyond.err.constData());

    const Run set =
        runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--set"_s, u"detent_strength=0.44"_s});
    QVERIFY2(set.code == 0, qPrintable(describe(set)));

    Profile profile = effectsProfile();
    profile.effects.detent_strength = 0.44; // at host.tau_limit 0.44
    const QString path = m_dir.filePath(u"limit.json"_s);
    QCOMPARE(writeProfile(profile, path), QString());
    const Run validate = runCtl({u"validate"_s, path});
    QVERIFY2(validate.code == 0, qPrintable(describe(validate)));
    const Run setProfile = runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--profile"_s, path});
    QVERIFY2(setProfile.code == 0, qPrintable(describe(setProfile)));
}

QTEST_GUILESS_MAIN(TestHatpicCtlEffects)
#include "tst_hatpicctleffects.moc"
