// hatpicctl simulate, run as a real process: its inputs and refusals, its CSV against an
// independent computation of model.md (the ideal device step by step, the plant settling at
// the spring's equilibrium), and the sample CSV forms read from the column table.
#include "ctlprocess.h"
#include "ctltest.h"
#include "model/admittance.h"
#include "model/params.h"
#include "telemetry/samplecolumns.h"

#include <QStringList>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

class TestHatpicCtlSimulate : public CtlTest
{
    Q_OBJECT

private Q_SLOTS:
    void simulateInputs_data();
    void simulateInputs();
    void simulateBadArguments_data();
    void simulateBadArguments();
    void simulateIdealMatchesModel_data();
    void simulateIdealMatchesModel();
    void simulateSettlesAtSpringEquilibrium_data();
    void simulateSettlesAtSpringEquilibrium();
    void sampleCsvFormsReadTheColumnTable();
};

void TestHatpicCtlSimulate::simulateInputs_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<bool>("ideal");
    QTest::addColumn<QString>("duration");
    QTest::addColumn<QString>("rate");
    QTest::addColumn<int>("rows");

    QTest::newRow("idle, defaults (2 s at 1 kHz)")
        << u"idle"_s << false << QString() << QString() << 2001;
    QTest::newRow("const") << u"const:0.02"_s << false << u"0.5"_s << QString() << 501;
    QTest::newRow("step") << u"step:0.05"_s << true << u"0.3"_s << u"500"_s << 151;
    QTest::newRow("step with offset")
        << u"step:0.05:-0.01"_s << false << u"0.3"_s << u"2000"_s << 601;
    QTest::newRow("sine") << u"sine:0.03:2"_s << true << u"1"_s << u"250"_s << 251;
    QTest::newRow("chirp") << u"chirp:0.03:0.5:5"_s << false << u"1"_s << QString() << 1001;
    QTest::newRow("virtual hand") << u"hand:0.3"_s << false << u"1"_s << QString() << 1001;
    QTest::newRow("zero duration: the start only") << u"idle"_s << true << u"0"_s << QString() << 1;
}

void TestHatpicCtlSimulate::simulateInputs()
{
    QFETCH(QString, spec);
    QFETCH(bool, ideal);
    QFETCH(QString, duration);
    QFETCH(QString, rate);
    QFETCH(int, rows);

    QStringList arguments{u"simulate"_s, u"--profile"_s, m_exact, u"--input"_s, spec};
    if (ideal)
        arguments << u"--ideal"_s;
    if (!duration.isEmpty())
        arguments << u"--duration"_s << duration;
    if (!rate.isEmpty())
        arguments << u"--rate"_s << rate;
    const Run run = runCtl(arguments);
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QString problem;
    const auto table = parseCsv(run.out, kSampleHeader, &problem);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QCOMPARE(table.size(), qsizetype(rows));

    // The first row is the state at t = 0: at rest on the center. Without --ideal the angle
    // is the servo's reading, in whole encoder ticks (4096 per turn).
    const DeviceParams p = exactParams();
    const double halfTick = std::numbers::pi / 4096;
    QCOMPARE(table[0][0], 0.0);
    if (ideal)
        QCOMPARE(table[0][1], p.theta0);
    else
        QVERIFY2(std::abs(table[0][1] - p.theta0) <= halfTick,
                 qPrintable(QString::number(table[0][1], 'g', 17)));
    QCOMPARE(table[0][2], 0.0);
    QCOMPARE(table[0][8], 0.0); // p_ref starts at 0
    const double h = 1.0 / (rate.isEmpty() ? 1000.0 : rate.toDouble());
    for (qsizetype i = 0; i < table.size(); ++i)
        QVERIFY(closeTo(table[i][0], double(i) * h, 1e-12));
}

void TestHatpicCtlSimulate::simulateBadArguments_data()
{
    QTest::addColumn<QStringList>("extra");
    QTest::newRow("empty spec") << QStringList{u"--input"_s, QString()};
    QTest::newRow("unknown kind") << QStringList{u"--input"_s, u"push:1"_s};
    QTest::newRow("const without value") << QStringList{u"--input"_s, u"const"_s};
    QTest::newRow("const not a number") << QStringList{u"--input"_s, u"const:x"_s};
    QTest::newRow("sine missing frequency") << QStringList{u"--input"_s, u"sine:0.1"_s};
    QTest::newRow("sine negative frequency") << QStringList{u"--input"_s, u"sine:0.1:-2"_s};
    QTest::newRow("chirp with two values") << QStringList{u"--input"_s, u"chirp:0.1:1"_s};
    QTest::newRow("step with four values") << QStringList{u"--input"_s, u"step:1:2:3:4"_s};
    QTest::newRow("hand not finite") << QStringList{u"--input"_s, u"hand:nan"_s};
    QTest::newRow("no input") << QStringList{};
    QTest::newRow("rate zero") << QStringList{u"--input"_s, u"idle"_s, u"--rate"_s, u"0"_s};
    // The device core's lowest rate: its feedback watchdog needs a period of at most 0.1 s.
    QTest::newRow("rate below 10 Hz") << QStringList{u"--input"_s, u"idle"_s, u"--rate"_s, u"5"_s};
    QTest::newRow("rate too high") << QStringList{u"--input"_s, u"idle"_s, u"--rate"_s, u"1e7"_s};
    QTest::newRow("negative duration")
        << QStringList{u"--input"_s, u"idle"_s, u"--duration"_s, u"-1"_s};
    QTest::newRow("too many rows")
        << QStringList{u"--input"_s, u"idle"_s, u"--duration"_s, u"1e6"_s};
    QTest::newRow("duration not a number")
        << QStringList{u"--input"_s, u"idle"_s, u"--duration"_s, u"long"_s};
}

void TestHatpicCtlSimulate::simulateBadArguments()
{
    QFETCH(QStringList, extra);
    const Run run = runCtl(QStringList{u"simulate"_s, u"--profile"_s, m_exact} + extra);
    QVERIFY2(run.code == 4, qPrintable(describe(run)));
    QVERIFY2(isOneLine(run.err), qPrintable(describe(run)));
    QVERIFY2(run.out.isEmpty(), qPrintable(describe(run)));
}

void TestHatpicCtlSimulate::simulateIdealMatchesModel_data()
{
    QTest::addColumn<QString>("profile");
    QTest::addColumn<QString>("spec");
    QTest::addColumn<double>("rate");

    // Operator torques chosen to end in each zone of exactParams() (K_max 0.375, N 0.125):
    // 0.004 N·m stays in the dead zone, 0.03 settles in the notch band, 0.07 goes beyond N.
    QTest::newRow("const, dead zone") << m_exact << u"const:0.004"_s << 1000.0;
    QTest::newRow("const, notch") << m_exact << u"const:0.03"_s << 1000.0;
    QTest::newRow("const, outer, negative") << m_exact << u"const:-0.07"_s << 1000.0;
    QTest::newRow("const, saturates tau_limit") << m_exact << u"const:0.6"_s << 1000.0;
    QTest::newRow("const, slow control rate") << m_exact << u"const:0.03"_s << 50.0;
    QTest::newRow("const, off-center, rotation mode") << m_shifted << u"const:0.05"_s << 2000.0;
    QTest::newRow("step with offset") << m_exact << u"step:0.05:-0.02"_s << 1000.0;
    QTest::newRow("sine") << m_exact << u"sine:0.04:3"_s << 1000.0;
}

void TestHatpicCtlSimulate::simulateIdealMatchesModel()
{
    QFETCH(QString, profile);
    QFETCH(QString, spec);
    QFETCH(double, rate);

    const double duration = 1.0;
    const Run run =
        runCtl({u"simulate"_s, u"--profile"_s, profile, u"--input"_s, spec, u"--ideal"_s,
                u"--duration"_s, QString::number(duration), u"--rate"_s, QString::number(rate)});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QString problem;
    const auto table = parseCsv(run.out, kSampleHeader, &problem);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QCOMPARE(table.size(), qsizetype(std::llround(duration * rate)) + 1);

    const ProfileReadResult read = readProfile(profile);
    QVERIFY(read.ok());
    const DeviceParams p = read.profile->device;
    const HostParams host = read.profile->host;

    // The operator's torque τ_op(t) of each SPEC form, as docs/cli.md defines it.
    const QStringList parts = spec.split(u':');
    const auto operatorTorque = [&](double t) {
        if (parts[0] == u"const")
            return parts[1].toDouble();
        if (parts[0] == u"step")
            return t < 0.1 ? parts.value(2, u"0"_s).toDouble() : parts[1].toDouble();
        return parts[1].toDouble() * std::sin(2 * std::numbers::pi * parts[2].toDouble() * t);
    };

    const double h = 1.0 / rate;
    AdmittanceState state{p.theta0, 0.0};
    double vPrevious = 0;
    double pRef = 0;
    for (qsizetype k = 0; k < table.size(); ++k) {
        const auto &row = table[k];
        const double t = double(k) * h;
        const double tau = -operatorTorque(t); // measured τ is the operator's, negated
        const double e = state.theta - p.theta0;
        const double tauRec = -expectedStiffness(p, state.theta) * e;
        const double tauTotal = std::clamp(tauRec, -host.tau_limit, host.tau_limit);
        double v = std::clamp(host.v_max / 2 * e, -host.v_max, host.v_max);
        if (host.ref_deadzone && std::abs(e) < p.Q_dz)
            v = 0;
        if (k > 0)
            pRef += (vPrevious + v) / 2 * h;
        vPrevious = v;

        const QString where = u"row "_s + QString::number(k) + u" (t = "_s + QString::number(t) +
                              u", "_s + stiffnessName(state.theta, p) + u')';
        QVERIFY2(closeTo(row[0], t, 1e-12), qPrintable(where + u": t_s"_s));
        QVERIFY2(closeTo(row[1], state.theta, 1e-12),
                 qPrintable(where + u": theta "_s + QString::number(row[1], 'g', 17) + u" vs "_s +
                            QString::number(state.theta, 'g', 17)));
        QVERIFY2(closeTo(row[2], state.omega, 1e-9), qPrintable(where + u": omega"_s));
        QVERIFY2(closeTo(row[3], tau, 1e-12), qPrintable(where + u": tau"_s));
        QVERIFY2(closeTo(row[4], tauRec, 1e-12), qPrintable(where + u": tau_rec"_s));
        QCOMPARE(row[5], 0.0); // no external feedback offline
        QVERIFY2(closeTo(row[6], tauTotal, 1e-12), qPrintable(where + u": tau_total"_s));
        QVERIFY2(closeTo(row[7], v, 1e-12), qPrintable(where + u": v_ref"_s));
        QVERIFY2(closeTo(row[8], pRef, 1e-9), qPrintable(where + u": p_ref"_s));
        const int flags = int(row[9]);
        const QString zone = stiffnessName(state.theta, p);
        QVERIFY2(bool(flags & 0x01) == (zone == u"dead zone"),
                 qPrintable(where + u": flags "_s + QString::number(flags)));
        QVERIFY2(bool(flags & 0x02) == (zone == u"notch"),
                 qPrintable(where + u": flags "_s + QString::number(flags)));
        QCOMPARE(bool(flags & 0x04), std::abs(tauRec) > host.tau_limit); // saturated
        QCOMPARE(flags & 0x08, 0);                                       // never stale offline

        state = admittanceStep(p, state, -tau + tauTotal, h);
    }
}

void TestHatpicCtlSimulate::simulateSettlesAtSpringEquilibrium_data()
{
    QTest::addColumn<double>("torque");
    // With exactParams() the notch band holds K_max = 0.375 N·m/rad for |θ−θ0| in
    // [0.015625, 0.125]; τ_op/K_max lands inside it for both of these.
    QTest::newRow("push up") << 0.03;
    QTest::newRow("push down") << -0.02;
}

void TestHatpicCtlSimulate::simulateSettlesAtSpringEquilibrium()
{
    QFETCH(double, torque);
    // Not ideal: the servo lags, angles are whole ticks, load readings are quantised.
    const Run run = runCtl({u"simulate"_s, u"--profile"_s, m_exact, u"--input"_s,
                            u"const:"_s + QString::number(torque), u"--duration"_s, u"3"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QString problem;
    const auto table = parseCsv(run.out, kSampleHeader, &problem);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));

    const DeviceParams p = exactParams();
    const double equilibrium = p.theta0 + torque / p.K_max; // τ_op = K_max·(θ−θ0)
    const double tick = 2 * std::numbers::pi / 4096;
    const auto &last = table.last();
    QVERIFY2(std::abs(last[1] - equilibrium) < 3 * tick,
             qPrintable(u"theta "_s + QString::number(last[1]) + u", expected about "_s +
                        QString::number(equilibrium)));
    QVERIFY2(std::abs(last[2]) < 0.05, qPrintable(u"omega "_s + QString::number(last[2])));
    // The measured torque is the operator's, negated, up to the load register's resolution.
    QVERIFY2(std::abs(last[3] + torque) < 0.01, qPrintable(u"tau "_s + QString::number(last[3])));
    QVERIFY(int(last[9]) & 0x02); // in the notch band
}

void TestHatpicCtlSimulate::sampleCsvFormsReadTheColumnTable()
{
    // simulate prints the table's header and rows in the one number format (the servo's
    // readings are floats: float digits), and both help texts name the table's header.
    QCOMPARE(kSampleHeader, sampleCsvHeader());
    const Run run = runCtl({u"simulate"_s, u"--profile"_s, m_exact, u"--input"_s, u"sine:0.05:2"_s,
                            u"--duration"_s, u"0.2"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    int floatDigits = 0;
    const QString problem = sampleCsvFormProblem(run.out, floatDigits);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QVERIFY(floatDigits > 0); // float values, written with their float digits
    for (const QString &command : {u"simulate"_s, u"stream"_s}) {
        const Run help = runCtl({command, u"--help"_s});
        QVERIFY2(help.code == 0, qPrintable(describe(help)));
        QVERIFY2(help.out.contains(sampleCsvHeader()), qPrintable(describe(help)));
    }
}

QTEST_GUILESS_MAIN(TestHatpicCtlSimulate)
#include "tst_hatpicctlsimulate.moc"
