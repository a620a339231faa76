// hatpicctl, run as a real process: argument handling and exit codes, the curve command's CSV
// against an independent computation of model.md, and validate. simulate and the sample CSV:
// tst_hatpicctlsimulate; the device commands: tst_hatpicctldevice.
#include "ctlprocess.h"
#include "ctltest.h"
#include "model/params.h"

#include <QStringList>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

class TestHatpicCtl : public CtlTest
{
    Q_OBJECT

private Q_SLOTS:
    void usage_data();
    void usage();
    void commandHelp_data();
    void commandHelp();

    void curveDefaults();
    void curveValues_data();
    void curveValues();
    void curveBadRange_data();
    void curveBadRange();

    void validate_data();
    void validate();
};

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

QTEST_GUILESS_MAIN(TestHatpicCtl)
#include "tst_hatpicctl.moc"
