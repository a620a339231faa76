// hatpicctl, run as a real process: argument handling, exit codes, the CSV forms against an
// independent computation of model.md, and the device commands against the in-process
// simulated joystick, a hatpic-sim child on a pseudo-terminal and a port that does not exist.
#include "ctlprocess.h"
#include "model/admittance.h"
#include "model/params.h"
#include "profile/profile.h"
#include "telemetry/numbertext.h"
#include "telemetry/recordingreader.h"
#include "telemetry/samplecolumns.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <numbers>
#include <pty.h>
#include <sys/types.h>
#include <unistd.h>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

QString stiffnessName(double theta, const DeviceParams &p)
{
    const double a = std::abs(theta - p.theta0);
    return a < p.Q_dz ? u"dead zone"_s : a <= p.N ? u"notch"_s : u"outer"_s;
}

} // namespace

class TestHatpicCtl : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();

    void usage_data();
    void usage();
    void commandHelp_data();
    void commandHelp();

    void curveDefaults();
    void curveValues_data();
    void curveValues();
    void curveBadRange_data();
    void curveBadRange();

    void simulateInputs_data();
    void simulateInputs();
    void simulateBadArguments_data();
    void simulateBadArguments();
    void simulateIdealMatchesModel_data();
    void simulateIdealMatchesModel();
    void simulateSettlesAtSpringEquilibrium_data();
    void simulateSettlesAtSpringEquilibrium();
    void sampleCsvFormsReadTheColumnTable();

    void validate_data();
    void validate();

    void simDevice_data();
    void simDevice();
    void simGetJsonRoundTrips();
    void simSetChangesParameters();
    void simStreamRecording();
    void simStreamToStdout();
    void deviceRejection();
    void noSuchPort_data();
    void noSuchPort();
    void silentPort_data();
    void silentPort();
    void ptySimulator();
    void ptyLegacySimulator();
    void ptyLinkLostDuringStream();
    void ptySaveStorageError();
    void streamInterruptedEndsCleanly_data();
    void streamInterruptedEndsCleanly();

private:
    QString writeFile(const QString &name, const QByteArray &content);
    QString writeProfileFile(const QString &name, const Profile &profile);

    QTemporaryDir m_dir;
    QString m_default; //!< the default parameters
    QString m_exact;   //!< exactParams(), host defaults
    QString m_shifted; //!< exactParams() with the dead zone and θ0 elsewhere
    QString m_invalid; //!< K_min > K_max and Q_dz > N
    QString m_float;   //!< valid in double, Q_dz = N once rounded to float32
};

QString TestHatpicCtl::writeFile(const QString &name, const QByteArray &content)
{
    const QString path = m_dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write(content);
    return path;
}

QString TestHatpicCtl::writeProfileFile(const QString &name, const Profile &profile)
{
    const QString path = m_dir.filePath(name);
    const QString error = writeProfile(profile, path);
    return error.isEmpty() ? path : QString();
}

void TestHatpicCtl::initTestCase()
{
    QVERIFY(m_dir.isValid());
    Profile profile;
    profile.name = u"Default"_s;
    m_default = writeProfileFile(u"default.json"_s, profile);
    QVERIFY(!m_default.isEmpty());

    profile.name = u"Exact"_s;
    profile.device = exactParams();
    m_exact = writeProfileFile(u"exact.json"_s, profile);
    QVERIFY(!m_exact.isEmpty());

    profile.device.theta0 = -0.5;
    profile.device.Q_dz = 0.0625;
    profile.host.mode = ReferenceMode::Rotation;
    profile.host.v_max = 2.0;
    profile.host.ref_deadzone = false;
    m_shifted = writeProfileFile(u"shifted.json"_s, profile);
    QVERIFY(!m_shifted.isEmpty());

    m_invalid = writeFile(u"invalid.json"_s, R"({
  "format": "hatpic-profile", "version": 1,
  "device": {"D_adm": 0.0001, "M_adm": 0.01, "K_min": 0.9, "K_max": 0.4,
             "N": 0.1, "Q_dz": 0.2, "theta0": 0.0}
})");
    QVERIFY(!m_invalid.isEmpty());

    profile = Profile{};
    profile.device.N = 0.1;
    profile.device.Q_dz = std::nextafter(0.1, 0.0);
    QCOMPARE(float(profile.device.Q_dz), float(profile.device.N)); // the premise of the case
    m_float = writeProfileFile(u"float.json"_s, profile);
    QVERIFY(!m_float.isEmpty());
}

// ---- argument handling ----

void TestHatpicCtl::usage_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("stdoutContains");

    QTest::newRow("no command") << QStringList{} << 4 << QString();
    QTest::newRow("unknown command") << QStringList{u"frobnicate"_s} << 4 << QString();
    QTest::newRow("overview help") << QStringList{u"--help"_s} << 0 << u"Commands:"_s;
    QTest::newRow("version") << QStringList{u"--version"_s} << 0 << u"hatpicctl "_s;
    QTest::newRow("unknown option")
        << QStringList{u"curve"_s, u"--profile"_s, m_default, u"--bogus"_s} << 4 << QString();
    QTest::newRow("option value missing") << QStringList{u"curve"_s, u"--from"_s} << 4 << QString();
    QTest::newRow("stray argument")
        << QStringList{u"get"_s, u"--port"_s, u"sim"_s, u"extra"_s} << 4 << QString();
    QTest::newRow("get without port") << QStringList{u"get"_s} << 4 << QString();
    QTest::newRow("bad protocol") << QStringList{u"info"_s, u"--port"_s, u"sim"_s, u"--protocol"_s,
                                                 u"v3"_s}
                                  << 4 << QString();
    QTest::newRow("bad baud") << QStringList{u"info"_s, u"--port"_s, u"sim"_s, u"--baud"_s,
                                             u"fast"_s}
                              << 4 << QString();
    QTest::newRow("bad timeout") << QStringList{u"info"_s, u"--port"_s, u"sim"_s, u"--timeout"_s,
                                                u"-1"_s}
                                 << 4 << QString();
    QTest::newRow("bad faults") << QStringList{u"info"_s, u"--port"_s, u"sim"_s, u"--faults"_s,
                                               u"cut=3s"_s}
                                << 4 << QString();
    QTest::newRow("faults off the sim port")
        << QStringList{u"info"_s, u"--port"_s, u"/dev/null"_s, u"--faults"_s, u"drop=0.1"_s} << 4
        << QString();
    QTest::newRow("bad seed") << QStringList{u"info"_s, u"--port"_s, u"sim"_s, u"--seed"_s, u"x"_s}
                              << 4 << QString();
    QTest::newRow("ports lists sim") << QStringList{u"ports"_s} << 0 << u"sim\t"_s;
}

void TestHatpicCtl::usage()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, code);
    QFETCH(QString, stdoutContains);
    const Run run = runCtl(arguments);
    QVERIFY2(run.code == code, qPrintable(describe(run)));
    if (code == 0) {
        QVERIFY2(QString::fromUtf8(run.out).contains(stdoutContains), qPrintable(describe(run)));
    } else {
        QVERIFY2(isOneLine(run.err), qPrintable(describe(run)));
        QVERIFY2(run.out.isEmpty(), qPrintable(describe(run)));
    }
}

void TestHatpicCtl::commandHelp_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("option"); // one option its help must mention
    for (const auto &[command, option] :
         {std::pair{u"ports"_s, u"--help"_s}, std::pair{u"info"_s, u"--port"_s},
          std::pair{u"get"_s, u"--json"_s}, std::pair{u"set"_s, u"--set"_s},
          std::pair{u"zero"_s, u"--port"_s}, std::pair{u"save"_s, u"--port"_s},
          std::pair{u"stream"_s, u"--csv"_s}, std::pair{u"curve"_s, u"--step"_s},
          std::pair{u"simulate"_s, u"--ideal"_s}, std::pair{u"validate"_s, u"--profile"_s}})
        QTest::newRow(qPrintable(command)) << command << option;
}

void TestHatpicCtl::commandHelp()
{
    QFETCH(QString, command);
    QFETCH(QString, option);
    const Run run = runCtl({command, u"--help"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    const QString text = QString::fromUtf8(run.out);
    QVERIFY2(text.startsWith(u"Usage: hatpicctl "_s + command), qPrintable(text));
    QVERIFY2(text.contains(option), qPrintable(text));
    QVERIFY(run.err.isEmpty());
}

// ---- curve ----

void TestHatpicCtl::curveDefaults()
{
    const Run run = runCtl({u"curve"_s, u"--profile"_s, m_default});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QString problem;
    const auto rows = parseCsv(run.out, "theta,K_rec,tau_rec,tau_det,tau_wall", &problem);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));

    // −π/2 + i·0.01 while below π/2 (i = 0…314), then π/2 itself.
    const double from = -std::numbers::pi / 2;
    QCOMPARE(rows.size(), 316);
    for (qsizetype i = 0; i + 1 < rows.size(); ++i)
        QCOMPARE(rows[i][0], from + double(i) * 0.01); // no accumulated error: exact
    QCOMPARE(rows.last()[0], std::numbers::pi / 2);
    QVERIFY(run.err.isEmpty());
}

void TestHatpicCtl::curveValues_data()
{
    QTest::addColumn<QString>("profile");
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::addColumn<double>("step");
    QTest::addColumn<int>("rows");

    QTest::newRow("step divides the range") << m_exact << 0.0 << 1.0 << 0.25 << 5;
    QTest::newRow("step does not divide: to is added") << m_exact << 0.0 << 1.0 << 0.3 << 5;
    QTest::newRow("decimal step ends on to once") << m_exact << 0.0 << 1.0 << 0.1 << 11;
    // −3 + 6·0.3 is −1.2000000000000002: one ulp off, it must not add a near-duplicate row.
    QTest::newRow("grid point an ulp from to counts as to") << m_exact << -3.0 << -1.2 << 0.3 << 7;
    QTest::newRow("single angle") << m_exact << 0.2 << 0.2 << 0.01 << 1;
    QTest::newRow("fine grid across every zone") << m_exact << -2.0 << 2.0 << 0.001 << 4001;
    QTest::newRow("theta0 off center, negative angles") << m_shifted << -1.5 << 0.5 << 0.005 << 401;
}

void TestHatpicCtl::curveValues()
{
    QFETCH(QString, profile);
    QFETCH(double, from);
    QFETCH(double, to);
    QFETCH(double, step);
    QFETCH(int, rows);

    const Run run = runCtl({u"curve"_s, u"--profile"_s, profile, u"--from"_s,
                            QString::number(from, 'g', 17), u"--to"_s, QString::number(to, 'g', 17),
                            u"--step"_s, QString::number(step, 'g', 17)});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QString problem;
    const auto table = parseCsv(run.out, "theta,K_rec,tau_rec,tau_det,tau_wall", &problem);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QCOMPARE(table.size(), qsizetype(rows));

    const ProfileReadResult read = readProfile(profile);
    QVERIFY(read.ok());
    const DeviceParams p = read.profile->device;
    QCOMPARE(table.first()[0], from);
    QCOMPARE(table.last()[0], to);
    for (qsizetype i = 0; i < table.size(); ++i) {
        const double theta = table[i][0];
        if (i + 1 < table.size())
            QCOMPARE(theta, from + double(i) * step);
        const double k = expectedStiffness(p, theta);
        QVERIFY2(closeTo(table[i][1], k, 1e-12),
                 qPrintable(u"row "_s + QString::number(i) + u" (" + stiffnessName(theta, p) +
                            u"): K_rec "_s + QString::number(table[i][1], 'g', 17)));
        QVERIFY2(closeTo(table[i][2], -k * (theta - p.theta0), 1e-12),
                 qPrintable(u"row "_s + QString::number(i) + u": tau_rec"_s));
    }
}

void TestHatpicCtl::curveBadRange_data()
{
    QTest::addColumn<QStringList>("arguments");

    const QString profile = m_default;
    const auto args = [&](std::initializer_list<QString> extra) {
        QStringList list{u"curve"_s, u"--profile"_s, profile};
        list << QStringList(extra);
        return list;
    };
    QTest::newRow("step zero") << args({u"--step"_s, u"0"_s});
    QTest::newRow("step negative") << args({u"--step"_s, u"-0.1"_s});
    QTest::newRow("from above to") << args({u"--from"_s, u"1"_s, u"--to"_s, u"0"_s});
    QTest::newRow("too many rows") << args({u"--step"_s, u"1e-9"_s});
    QTest::newRow("not a number") << args({u"--from"_s, u"left"_s});
    QTest::newRow("infinite") << args({u"--to"_s, u"inf"_s});
    QTest::newRow("no profile") << QStringList{u"curve"_s};
    QTest::newRow("missing file") << QStringList{u"curve"_s, u"--profile"_s,
                                                 m_dir.filePath(u"nothing.json"_s)};
    QTest::newRow("not JSON") << QStringList{u"curve"_s, u"--profile"_s,
                                             writeFile(u"garbage.json"_s, "{ nope")};
}

void TestHatpicCtl::curveBadRange()
{
    QFETCH(QStringList, arguments);
    const Run run = runCtl(arguments);
    QVERIFY2(run.code == 4, qPrintable(describe(run)));
    QVERIFY2(isOneLine(run.err), qPrintable(describe(run)));
    QVERIFY2(run.out.isEmpty(), qPrintable(describe(run)));
}

// ---- simulate ----

static const QByteArray kSampleHeader =
    "t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags,tau_fx,tau_pc,pc_reserve";

void TestHatpicCtl::simulateInputs_data()
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

void TestHatpicCtl::simulateInputs()
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

void TestHatpicCtl::simulateBadArguments_data()
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

void TestHatpicCtl::simulateBadArguments()
{
    QFETCH(QStringList, extra);
    const Run run = runCtl(QStringList{u"simulate"_s, u"--profile"_s, m_exact} + extra);
    QVERIFY2(run.code == 4, qPrintable(describe(run)));
    QVERIFY2(isOneLine(run.err), qPrintable(describe(run)));
    QVERIFY2(run.out.isEmpty(), qPrintable(describe(run)));
}

void TestHatpicCtl::simulateIdealMatchesModel_data()
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

void TestHatpicCtl::simulateIdealMatchesModel()
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

void TestHatpicCtl::simulateSettlesAtSpringEquilibrium_data()
{
    QTest::addColumn<double>("torque");
    // With exactParams() the notch band holds K_max = 0.375 N·m/rad for |θ−θ0| in
    // [0.015625, 0.125]; τ_op/K_max lands inside it for both of these.
    QTest::newRow("push up") << 0.03;
    QTest::newRow("push down") << -0.02;
}

void TestHatpicCtl::simulateSettlesAtSpringEquilibrium()
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

// ---- validate ----

void TestHatpicCtl::validate_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("code");
    QTest::addColumn<QStringList>("stderrContains");

    QTest::newRow("valid") << QStringList{u"validate"_s, m_default} << 0 << QStringList{};
    QTest::newRow("valid, --profile form")
        << QStringList{u"validate"_s, u"--profile"_s, m_exact} << 0 << QStringList{};
    QTest::newRow("two errors, both listed")
        << QStringList{u"validate"_s, m_invalid} << 4
        << QStringList{u"2 errors"_s, u"device.K_min"_s, u"device.Q_dz"_s};
    QTest::newRow("valid only in double")
        << QStringList{u"validate"_s, m_float} << 4 << QStringList{u"device.Q_dz"_s, u"32-bit"_s};
    QTest::newRow("unknown key is a warning") << QStringList{u"validate"_s,
                                                             writeFile(u"extra.json"_s, R"({
  "format": "hatpic-profile", "version": 1, "colour": "red",
  "device": {"D_adm": 0.0001, "M_adm": 0.01, "K_min": 0.15, "K_max": 0.4,
             "N": 0.1, "Q_dz": 0.02, "theta0": 0.0}
})")} << 0 << QStringList{u"warning:"_s, u"colour"_s};
    QTest::newRow("not a profile: the error alone, no key warnings")
        << QStringList{u"validate"_s, writeFile(u"other.json"_s, R"({
  "format": "something-else", "version": 1, "colour": "red"
})")} << 4
        << QStringList{};
    QTest::newRow("duplicate key") << QStringList{u"validate"_s, writeFile(u"twice.json"_s, R"({
  "format": "hatpic-profile", "version": 1,
  "device": {"D_adm": 0.0001, "M_adm": 0.01, "K_min": 0.15, "K_max": 0.4,
             "N": 0.1, "Q_dz": 0.02, "theta0": 0.0, "K_max": 0.9}
})")} << 4 << QStringList{u"duplicate key \"device.K_max\""_s};
    QTest::newRow("saturating and ringing are warnings")
        << QStringList{u"validate"_s, writeFile(u"stiff.json"_s, R"({
  "format": "hatpic-profile", "version": 1,
  "device": {"D_adm": 0.0001, "M_adm": 0.001, "K_min": 1, "K_max": 5,
             "N": 0.1, "Q_dz": 0.02, "theta0": 0.0}
})")} << 0
        << QStringList{u"tau_limit"_s, u"ring"_s};
    QTest::newRow("string value") << QStringList{u"validate"_s, writeFile(u"string.json"_s, R"({
  "format": "hatpic-profile", "version": 1,
  "device": {"D_adm": "0.0001", "M_adm": 0.01, "K_min": 0.15, "K_max": 0.4,
             "N": 0.1, "Q_dz": 0.02, "theta0": 0.0}
})")} << 4 << QStringList{u"D_adm"_s};
    QTest::newRow("missing file") << QStringList{u"validate"_s, m_dir.filePath(u"absent.json"_s)}
                                  << 4 << QStringList{};
    QTest::newRow("no file given") << QStringList{u"validate"_s} << 4 << QStringList{};
    QTest::newRow("two files given")
        << QStringList{u"validate"_s, m_default, m_exact} << 4 << QStringList{};
}

void TestHatpicCtl::validate()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, code);
    QFETCH(QStringList, stderrContains);
    const Run run = runCtl(arguments);
    QVERIFY2(run.code == code, qPrintable(describe(run)));
    QCOMPARE(run.out, code == 0 ? QByteArray("OK\n") : QByteArray());
    const QString err = QString::fromUtf8(run.err);
    for (const QString &part : stderrContains)
        QVERIFY2(err.contains(part), qPrintable(describe(run)));
    if (code != 0 && stderrContains.isEmpty())
        QVERIFY2(isOneLine(run.err), qPrintable(describe(run)));
    if (code == 0 && stderrContains.isEmpty())
        QVERIFY2(run.err.isEmpty(), qPrintable(describe(run)));
}

//! Why `csv` is not the sample CSV of the column table (its header, one field per column, every
//! number in the one number format); empty when it is. `floatDigits` counts the values written
//! with a float's digits (they read back as a double that is not a float).
static QString sampleCsvFormProblem(const QByteArray &csv, int &floatDigits)
{
    floatDigits = 0;
    const QList<QByteArray> lines = csv.split('\n');
    if (lines.first() != sampleCsvHeader())
        return u"header: "_s + QString::fromUtf8(lines.first());
    for (qsizetype i = 1; i + 1 < lines.size(); ++i) {
        const QList<QByteArray> fields = lines[i].split(',');
        if (fields.size() != qsizetype(kSampleColumns.size()))
            return u"fields: "_s + QString::fromUtf8(lines[i]);
        for (qsizetype k = 0; k + 1 < fields.size(); ++k) {
            const double value = fields[k].toDouble();
            if (!fields[k].isEmpty() && QString::fromLatin1(fields[k]) != compactNumberText(value))
                return u"number format: "_s + QString::fromUtf8(fields[k]);
            const double asFloat = static_cast<float>(value);
            floatDigits += k > 0 && asFloat != value ? 1 : 0;
        }
    }
    return {};
}

void TestHatpicCtl::sampleCsvFormsReadTheColumnTable()
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

// ---- device commands against the in-process simulated joystick ----

void TestHatpicCtl::simDevice_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("stdoutContains");

    const auto sim = [](std::initializer_list<QString> args) {
        QStringList list(args);
        list.insert(1, u"sim"_s);
        list.insert(1, u"--port"_s);
        return list;
    };
    QTest::newRow("info") << sim({u"info"_s}) << 0 << u"simulated         yes"_s;
    QTest::newRow("info --json") << sim({u"info"_s, u"--json"_s}) << 0 << u"\"protocol\": \"v2\""_s;
    QTest::newRow("info, forced v2")
        << sim({u"info"_s, u"--protocol"_s, u"v2"_s}) << 0 << u"protocol          v2"_s;
    QTest::newRow("get") << sim({u"get"_s}) << 0 << u"K_max   0.4 "_s;
    QTest::newRow("zero") << sim({u"zero"_s}) << 0 << u"theta0"_s;
    QTest::newRow("save") << sim({u"save"_s}) << 0 << QString();
    QTest::newRow("set --profile")
        << sim({u"set"_s, u"--profile"_s, m_exact}) << 0 << u"K_max   0.375 "_s;
    QTest::newRow("set, invalid value")
        << sim({u"set"_s, u"--set"_s, u"K_min=0.9"_s}) << 4 << QString();
    QTest::newRow("set, invalid on top of a profile")
        << sim({u"set"_s, u"--profile"_s, m_exact, u"--set"_s, u"N=0.01"_s}) << 4 << QString();
    QTest::newRow("set, invalid profile")
        << sim({u"set"_s, u"--profile"_s, m_invalid}) << 4 << QString();
    QTest::newRow("set, unknown name")
        << sim({u"set"_s, u"--set"_s, u"K_mid=1"_s}) << 4 << QString();
    QTest::newRow("set, not NAME=VALUE")
        << sim({u"set"_s, u"--set"_s, u"K_max"_s}) << 4 << QString();
    QTest::newRow("set, value not a number")
        << sim({u"set"_s, u"--set"_s, u"K_max=stiff"_s}) << 4 << QString();
    QTest::newRow("set, nothing to set") << sim({u"set"_s}) << 4 << QString();
    QTest::newRow("stream, bad rate") << sim({u"stream"_s, u"--rate"_s, u"0"_s}) << 4 << QString();
    QTest::newRow("stream, bad duration")
        << sim({u"stream"_s, u"--duration"_s, u"-2"_s}) << 4 << QString();
}

void TestHatpicCtl::simDevice()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, code);
    QFETCH(QString, stdoutContains);
    const Run run = runCtl(arguments);
    QVERIFY2(run.code == code, qPrintable(describe(run)));
    if (code == 0) {
        QVERIFY2(QString::fromUtf8(run.out).contains(stdoutContains), qPrintable(describe(run)));
    } else {
        QVERIFY2(run.out.isEmpty(), qPrintable(describe(run)));
        // One sentence; a validation failure may list each violation under it.
        const QList<QByteArray> lines = run.err.trimmed().split('\n');
        QVERIFY2(lines.first().startsWith("hatpicctl: "), qPrintable(describe(run)));
        for (qsizetype i = 1; i < lines.size(); ++i)
            QVERIFY2(lines[i].startsWith("  "), qPrintable(describe(run)));
    }
}

void TestHatpicCtl::simGetJsonRoundTrips()
{
    const Run run = runCtl({u"get"_s, u"--port"_s, u"sim"_s, u"--json"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    const ProfileReadResult read = parseProfile(run.out);
    QVERIFY2(read.ok(), qPrintable(read.errors.join(u'\n')));
    QVERIFY(read.warnings.isEmpty());
    // The simulator powers up with the defaults; the JSON shows the decimals a person wrote.
    QCOMPARE(read.profile->device, DeviceParams{});
    QCOMPARE(read.profile->host.tau_limit, 0.44);
}

void TestHatpicCtl::simSetChangesParameters()
{
    // --set alone starts from the device's parameters: only K_max and theta0 change.
    const Run run = runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--set"_s, u"K_max=0.5"_s, u"--set"_s,
                            u"theta0=-0.25"_s, u"--json"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    const ProfileReadResult read = parseProfile(run.out);
    QVERIFY2(read.ok(), qPrintable(read.errors.join(u'\n')));
    DeviceParams expected;
    expected.K_max = 0.5;
    expected.theta0 = -0.25;
    QCOMPARE(read.profile->device, expected);
    QVERIFY2(run.err.contains("accepted"), qPrintable(describe(run)));
}

void TestHatpicCtl::simStreamRecording()
{
    const QString csv = m_dir.filePath(u"sim-stream.csv"_s);
    const Run run = runCtl({u"stream"_s, u"--port"_s, u"sim"_s, u"--rate"_s, u"500"_s,
                            u"--duration"_s, u"1"_s, u"--csv"_s, csv});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QVERIFY2(run.out.isEmpty(), qPrintable(describe(run)));
    const QString err = QString::fromUtf8(run.err);
    for (const QString &part : {u"frames/s"_s, u"decoder drops"_s, u"rtt"_s, u"recording"_s})
        QVERIFY2(err.contains(part), qPrintable(err));

    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording.has_value(), qPrintable(read.error));
    const Recording &recording = *read.recording;
    QVERIFY(recording.hasMetadata);
    QCOMPARE(recording.metadata.source, u"hatpicctl stream"_s);
    QVERIFY(recording.metadata.device.simulated);
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) // the device's float32 read-back
        QCOMPARE(recording.metadata.params.field(i), double(float(DeviceParams{}.field(i))));
    // 1 s at 500 Hz: allow for start-up, but most of a second must be there, in order.
    QVERIFY2(recording.samples.size() >= 300 && recording.samples.size() <= 600,
             qPrintable(QString::number(recording.samples.size())));
    for (qsizetype i = 1; i < recording.samples.size(); ++i)
        QVERIFY(recording.samples[i].t_s > recording.samples[i - 1].t_s);
}

void TestHatpicCtl::simStreamToStdout()
{
    const Run run = runCtl(
        {u"stream"_s, u"--port"_s, u"sim"_s, u"--rate"_s, u"200"_s, u"--duration"_s, u"0.5"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QString problem;
    const auto table = parseCsv(run.out, kSampleHeader, &problem);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QVERIFY2(table.size() >= 50, qPrintable(QString::number(table.size())));
    int floatDigits = 0; // none need be: a knob at rest reports zeros
    problem = sampleCsvFormProblem(run.out, floatDigits);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    QVERIFY(run.err.contains("frames/s"));
}

void TestHatpicCtl::deviceRejection()
{
    // Q_dz just below N passes host validation in double (Q_dz < N), but both round to the
    // same 32-bit float on the wire, where the device finds Q_dz = N and answers OUT_OF_RANGE.
    const QString qdz = QString::number(std::nextafter(0.1, 0.0), 'g', 17);
    const Run run = runCtl(
        {u"set"_s, u"--port"_s, u"sim"_s, u"--set"_s, u"N=0.1"_s, u"--set"_s, u"Q_dz="_s + qdz});
    QVERIFY2(run.code == 2, qPrintable(describe(run)));
    QVERIFY2(isOneLine(run.err), qPrintable(describe(run)));
    QVERIFY2(run.err.contains("OUT_OF_RANGE") && run.err.contains("Q_dz"),
             qPrintable(describe(run)));
    QVERIFY(run.out.isEmpty());
}

void TestHatpicCtl::noSuchPort_data()
{
    QTest::addColumn<QString>("command");
    QTest::newRow("info") << u"info"_s;
    QTest::newRow("get") << u"get"_s;
    QTest::newRow("stream") << u"stream"_s;
}

void TestHatpicCtl::noSuchPort()
{
    QFETCH(QString, command);
    const Run run =
        runCtl({command, u"--port"_s, m_dir.filePath(u"no-such-tty"_s), u"--timeout"_s, u"3"_s});
    QVERIFY2(run.code == 3, qPrintable(describe(run)));
    QVERIFY2(isOneLine(run.err), qPrintable(describe(run)));
    QVERIFY(run.out.isEmpty());
}

void TestHatpicCtl::silentPort_data()
{
    QTest::addColumn<QString>("protocol");
    QTest::newRow("detecting") << u"auto"_s;
    QTest::newRow("forced v2") << u"v2"_s;
    QTest::newRow("forced legacy") << u"legacy"_s;
}

void TestHatpicCtl::silentPort()
{
    // A real pseudo-terminal nobody answers on: the port opens, detection finds no HATPIC.
    QFETCH(QString, protocol);
    int master = -1;
    int slave = -1;
    char name[256] = {};
    QVERIFY(::openpty(&master, &slave, name, nullptr, nullptr) == 0);
    const Run run = runCtl({u"info"_s, u"--port"_s, QString::fromLocal8Bit(name), u"--protocol"_s,
                            protocol, u"--timeout"_s, u"3"_s});
    ::close(slave);
    ::close(master);
    QVERIFY2(run.code == 3, qPrintable(describe(run)));
    QVERIFY2(isOneLine(run.err), qPrintable(describe(run)));
    QVERIFY(run.out.isEmpty());
}

void TestHatpicCtl::ptySimulator()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not built");
#else
    const QString link = m_dir.filePath(u"hatpic"_s);
    QProcess sim;
    sim.setProgram(QStringLiteral(HATPIC_SIM_PATH));
    sim.setArguments({u"--link"_s, link});
    sim.start();
    QVERIFY2(sim.waitForStarted(5000), qPrintable(sim.errorString()));
    QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
    const QString path = QString::fromLocal8Bit(sim.readLine()).trimmed();
    QVERIFY2(path.startsWith(u"/dev/"_s), qPrintable(path));

    const Run get = runCtl({u"get"_s, u"--port"_s, link});
    QVERIFY2(get.code == 0, qPrintable(describe(get)));
    QVERIFY2(get.out.contains("K_min   0.15 "), qPrintable(describe(get)));

    // The simulator keeps its state between connections: set, then get shows it.
    const Run set = runCtl({u"set"_s, u"--port"_s, path, u"--set"_s, u"K_min=0.2"_s});
    QVERIFY2(set.code == 0, qPrintable(describe(set)));
    const Run again = runCtl({u"get"_s, u"--port"_s, link, u"--protocol"_s, u"v2"_s});
    QVERIFY2(again.code == 0, qPrintable(describe(again)));
    QVERIFY2(again.out.contains("K_min   0.2 "), qPrintable(describe(again)));

    const QString csv = m_dir.filePath(u"pty-stream.csv"_s);
    const Run stream =
        runCtl({u"stream"_s, u"--port"_s, link, u"--duration"_s, u"1"_s, u"--csv"_s, csv});
    QVERIFY2(stream.code == 0, qPrintable(describe(stream)));
    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording.has_value(), qPrintable(read.error));
    QVERIFY2(read.recording->samples.size() >= 500,
             qPrintable(QString::number(read.recording->samples.size())));
    QCOMPARE(read.recording->metadata.params.K_min, double(0.2f));

    sim.terminate();
    QVERIFY(sim.waitForFinished(10000));
    QCOMPARE(sim.exitCode(), 0);

    // The simulator is gone: the port is still named but nobody answers.
    const Run gone = runCtl({u"get"_s, u"--port"_s, link, u"--timeout"_s, u"3"_s});
    QVERIFY2(gone.code == 3, qPrintable(describe(gone)));
    QVERIFY2(isOneLine(gone.err), qPrintable(describe(gone)));
#endif
}

void TestHatpicCtl::ptyLegacySimulator()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not built");
#else
    // The published firmware's protocol: identity and telemetry work, parameters cannot.
    QProcess sim;
    sim.setProgram(QStringLiteral(HATPIC_SIM_PATH));
    sim.setArguments({u"--protocol"_s, u"legacy"_s});
    sim.start();
    QVERIFY2(sim.waitForStarted(5000), qPrintable(sim.errorString()));
    QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
    const QString path = QString::fromLocal8Bit(sim.readLine()).trimmed();

    const Run info = runCtl({u"info"_s, u"--port"_s, path});
    QVERIFY2(info.code == 0, qPrintable(describe(info)));
    QVERIFY2(info.out.contains("legacy"), qPrintable(describe(info)));

    const Run get = runCtl({u"get"_s, u"--port"_s, path, u"--protocol"_s, u"legacy"_s});
    QVERIFY2(get.code == 2, qPrintable(describe(get)));
    QVERIFY2(isOneLine(get.err), qPrintable(describe(get)));

    const QString csv = m_dir.filePath(u"legacy-stream.csv"_s);
    const Run stream = runCtl({u"stream"_s, u"--port"_s, path, u"--protocol"_s, u"legacy"_s,
                               u"--duration"_s, u"1.5"_s, u"--csv"_s, csv});
    QVERIFY2(stream.code == 0, qPrintable(describe(stream)));
    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording.has_value(), qPrintable(read.error));
    // About 5 frames per second; ω and τ are not carried (NaN).
    QVERIFY2(read.recording->samples.size() >= 4,
             qPrintable(QString::number(read.recording->samples.size())));
    QVERIFY(std::isnan(read.recording->samples.first().omega));

    // To stdout, the uncarried ω and τ are empty fields too, so both CSV forms read the same.
    const Run out = runCtl(
        {u"stream"_s, u"--port"_s, path, u"--protocol"_s, u"legacy"_s, u"--duration"_s, u"0.7"_s});
    QVERIFY2(out.code == 0, qPrintable(describe(out)));
    const QList<QByteArray> lines = out.out.trimmed().split('\n');
    QVERIFY2(lines.size() >= 2, qPrintable(describe(out)));
    const QList<QByteArray> fields = lines[1].split(',');
    QCOMPARE(fields.size(), 13);
    QVERIFY2(fields[2].isEmpty() && fields[3].isEmpty(), lines[1].constData());
    QVERIFY2(fields[10].isEmpty(), lines[1].constData()); // no effects: τ_fx unknown
    // …nor a passivity controller: τ_pc and R unknown.
    QVERIFY2(fields[11].isEmpty() && fields[12].isEmpty(), lines[1].constData());
    QVERIFY(!fields[1].isEmpty());

    sim.terminate();
    QVERIFY(sim.waitForFinished(10000));
#endif
}

void TestHatpicCtl::ptyLinkLostDuringStream()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not built");
#else
    QProcess sim;
    sim.setProgram(QStringLiteral(HATPIC_SIM_PATH));
    sim.start();
    QVERIFY2(sim.waitForStarted(5000), qPrintable(sim.errorString()));
    QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
    const QString path = QString::fromLocal8Bit(sim.readLine()).trimmed();

    const QString csv = m_dir.filePath(u"lost-stream.csv"_s);
    QProcess ctl;
    ctl.setProgram(QStringLiteral(HATPICCTL_PATH));
    ctl.setArguments({u"stream"_s, u"--port"_s, path, u"--csv"_s, csv}); // no --duration
    ctl.start();
    QVERIFY2(ctl.waitForStarted(5000), qPrintable(ctl.errorString()));
    // Streaming has begun once rows reach the file (the recorder flushes every 0.5 s).
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(csv).size() > 1000, 15000);

    sim.terminate(); // the device goes away mid-stream
    QVERIFY(sim.waitForFinished(10000));
    QVERIFY(ctl.waitForFinished(15000));
    QCOMPARE(ctl.exitStatus(), QProcess::NormalExit);
    const QByteArray err = ctl.readAllStandardError();
    QVERIFY2(ctl.exitCode() == 3, err.constData());
    // The statistics first, then the one sentence saying why, last.
    const QList<QByteArray> lines = err.trimmed().split('\n');
    QVERIFY2(lines.last().startsWith("hatpicctl: "), err.constData());
    QVERIFY2(err.contains("frames/s"), err.constData());

    // The recording was closed properly and reads back.
    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording.has_value(), qPrintable(read.error));
    QVERIFY(!read.recording->samples.isEmpty());
#endif
}

void TestHatpicCtl::ptySaveStorageError()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not built");
#else
    // A state file in a folder that does not exist: SAVE_PARAMS fails on the device, which
    // answers STORAGE_ERROR, and hatpicctl exits with 2 (docs/cli.md, exit codes).
    QProcess sim;
    sim.setProgram(QStringLiteral(HATPIC_SIM_PATH));
    sim.setArguments({u"--state"_s, m_dir.filePath(u"no-such-folder/state.json"_s)});
    sim.start();
    QVERIFY2(sim.waitForStarted(5000), qPrintable(sim.errorString()));
    QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
    const QString path = QString::fromLocal8Bit(sim.readLine()).trimmed();

    const Run save = runCtl({u"save"_s, u"--port"_s, path});
    sim.terminate();
    QVERIFY(sim.waitForFinished(10000));
    QVERIFY2(save.code == 2, qPrintable(describe(save)));
    // Two lines: the device's reason (its LOG, with the OS error), then the outcome.
    const QList<QByteArray> lines = save.err.trimmed().split('\n');
    QVERIFY2(lines.size() == 2, qPrintable(describe(save)));
    QVERIFY2(lines.at(0).contains("SAVE_PARAMS failed") && lines.at(0).contains("no-such-folder"),
             qPrintable(describe(save)));
    QVERIFY2(lines.at(1).contains("STORAGE_ERROR"), qPrintable(describe(save)));
    QVERIFY(save.out.isEmpty());
#endif
}

void TestHatpicCtl::streamInterruptedEndsCleanly_data()
{
    QTest::addColumn<int>("signal");
    QTest::newRow("SIGINT") << int(SIGINT);
    QTest::newRow("SIGTERM") << int(SIGTERM);
}

void TestHatpicCtl::streamInterruptedEndsCleanly()
{
    // Without --duration, stream runs until SIGINT or SIGTERM; either ends it cleanly: the
    // recording is closed, the statistics are printed, exit 0.
    QFETCH(int, signal);
    const QString csv = m_dir.filePath(u"interrupted-"_s + QString::number(signal) + u".csv"_s);
    QProcess ctl;
    ctl.setProgram(QStringLiteral(HATPICCTL_PATH));
    ctl.setArguments({u"stream"_s, u"--port"_s, u"sim"_s, u"--csv"_s, csv});
    ctl.start();
    QVERIFY2(ctl.waitForStarted(5000), qPrintable(ctl.errorString()));
    // Streaming has begun once rows reach the file (the recorder flushes every 0.5 s).
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(csv).size() > 1000, 15000);

    QCOMPARE(::kill(pid_t(ctl.processId()), signal), 0);
    QVERIFY(ctl.waitForFinished(15000));
    const QByteArray err = ctl.readAllStandardError();
    QCOMPARE(ctl.exitStatus(), QProcess::NormalExit);
    QVERIFY2(ctl.exitCode() == 0, err.constData());
    QVERIFY2(err.contains("frames/s") && err.contains("recording"), err.constData());
    QVERIFY2(!err.contains("hatpicctl: "), err.constData());
    QVERIFY(ctl.readAllStandardOutput().isEmpty());

    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording.has_value(), qPrintable(read.error));
    QVERIFY(!read.recording->samples.isEmpty());
}

QTEST_GUILESS_MAIN(TestHatpicCtl)
#include "tst_hatpicctl.moc"
