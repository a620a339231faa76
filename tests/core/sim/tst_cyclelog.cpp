// hatpic-sim's --cycle-log (sim/cyclelog.h): the columns are the cycle quantities' one list
// with t_s before and tau_total after; each value is the cycle's; and the real program writes
// that file.
#include "model/cyclequantities.h"
#include "sim/cyclelog.h"
#include "sim/handinput.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

// The columns as this test knows them (protocol.md § 3's TELEMETRY order), written out
// independently of the list the code walks.
const QList<QByteArray> kExpectedColumns = {"t_s",    "t_us",    "theta",      "omega",
                                            "tau",    "tau_rec", "tau_ext",    "flags",
                                            "tau_fx", "tau_pc",  "pc_reserve", "tau_total"};

// A cycle's value of the named column, read member by member.
double valueOf(const SimulatedDevice::Cycle &c, const QByteArray &column)
{
    const std::pair<const char *, double> values[] = {{"t_s", c.t},
                                                      {"t_us", double(c.t_us)},
                                                      {"theta", c.theta},
                                                      {"omega", c.omega},
                                                      {"tau", c.tau},
                                                      {"tau_rec", c.tau_rec},
                                                      {"tau_ext", c.tau_ext},
                                                      {"flags", double(c.flags)},
                                                      {"tau_fx", c.tau_fx},
                                                      {"tau_pc", c.tau_pc},
                                                      {"pc_reserve", c.pc_reserve},
                                                      {"tau_total", c.tau_total}};
    for (const auto &[name, value] : values) {
        if (column == name)
            return value;
    }
    return NAN;
}

} // namespace

class TestCycleLog : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void headerIsTheQuantitiesOneList();
    void lineHoldsTheCyclesValues();
    void hatpicSimWritesIt();
};

void TestCycleLog::headerIsTheQuantitiesOneList()
{
    const QList<QByteArray> columns = cycleLogHeader().split(',');
    QCOMPARE(columns, kExpectedColumns);
    QCOMPARE(std::size_t(columns.size()), kCycleQuantityCount + 2);
}

void TestCycleLog::lineHoldsTheCyclesValues()
{
    SimulatedDevice::Config config;
    config.hand = *HandInput::parse(u"const:0.05"_s);
    SimulatedDevice device(config);
    SimulatedDevice::Cycle cycle;
    for (int i = 0; i < 400; ++i)
        cycle = device.step();
    QVERIFY(cycle.theta != 0 && cycle.tau_total != 0); // the knob moved: values worth reading

    const QList<QByteArray> columns = cycleLogHeader().split(',');
    const QList<QByteArray> fields = cycleLogLine(cycle).split(',');
    QCOMPARE(fields.size(), columns.size());
    for (qsizetype i = 0; i < columns.size(); ++i) {
        bool ok = false;
        const double value = fields[i].toDouble(&ok);
        const double expected = valueOf(cycle, columns[i]);
        QVERIFY2(ok, fields[i].constData());
        QVERIFY2(std::abs(value - expected) <= 1e-8 * std::max(1.0, std::abs(expected)),
                 qPrintable(QString::fromLatin1(columns[i]) + u": "_s +
                            QString::fromLatin1(fields[i]) + u" against "_s +
                            QString::number(expected, 'g', 17)));
    }
    QCOMPARE(fields[1], QByteArray::number(cycle.t_us)); // whole numbers stay whole
}

void TestCycleLog::hatpicSimWritesIt()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(u"cycles.csv"_s);
    QProcess sim;
    sim.start(QStringLiteral(HATPIC_SIM_PATH),
              {u"--cycle-log"_s, path, u"--hand"_s, u"const:0.05"_s});
    QVERIFY2(sim.waitForStarted(5000), qPrintable(sim.errorString()));
    QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000); // the pty's path: running
    QTest::qWait(300);
    sim.terminate();
    QVERIFY(sim.waitForFinished(10000));
    QCOMPARE(sim.exitStatus(), QProcess::NormalExit);
    QCOMPARE(sim.exitCode(), 0);

    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
    QVERIFY2(lines.size() > 100, qPrintable(QString::number(lines.size())));
    QCOMPARE(lines.first().split(','), kExpectedColumns);
    // Every cycle, one after the other: t_us a control period apart, t_s agreeing with it.
    const qsizetype tUs = kExpectedColumns.indexOf("t_us");
    for (qsizetype i = 2; i < lines.size(); ++i) {
        const QList<QByteArray> now = lines[i].split(','), before = lines[i - 1].split(',');
        QCOMPARE(now.size(), kExpectedColumns.size());
        QCOMPARE(now[tUs].toLongLong() - before[tUs].toLongLong(), 1000);
        QVERIFY(std::abs(now[0].toDouble() * 1e6 - now[tUs].toDouble()) < 1);
    }
}

QTEST_GUILESS_MAIN(TestCycleLog)
#include "tst_cyclelog.moc"
