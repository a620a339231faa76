// hatpic-tuner as a real process: numeric options out of range or not numbers are refused
// before the window opens, with one sentence and exit code 4 (issue 10, "Hostile input").
#include "processrun.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

using namespace Qt::StringLiterals;
using hatpic::test::Run;
using hatpic::test::runToEnd;

namespace {

//! `platform` "offscreen", or "xcb" with no display to connect to (an ssh session).
Run runTuner(const QString &configDir, const QStringList &arguments, int timeoutMs,
             const QString &platform = u"offscreen"_s)
{
    QProcess process;
    process.setProgram(QStringLiteral(HATPIC_TUNER_PATH));
    process.setArguments(arguments);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(u"QT_QPA_PLATFORM"_s, platform);
    env.remove(u"DISPLAY"_s);
    env.remove(u"WAYLAND_DISPLAY"_s);
    env.insert(u"XDG_CONFIG_HOME"_s, configDir); // never the user's own settings
    env.insert(u"XDG_RUNTIME_DIR"_s, configDir); // 0700: no warning on stderr
    process.setProcessEnvironment(env);
    return runToEnd(process, timeoutMs);
}

} // namespace

class TestTunerOptions : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QVERIFY(m_config.isValid()); }
    void refusesBadNumbers_data();
    void refusesBadNumbers();
    void quitAfterCloses();
    void signalClosesTheRecording_data();
    void signalClosesTheRecording();
    void helpAndErrorsNeedNoDisplay_data();
    void helpAndErrorsNeedNoDisplay();
    void qtOptionsStillWork();

private:
    QTemporaryDir m_config;
};

void TestTunerOptions::refusesBadNumbers_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("option"); // what the sentence names
    QTest::newRow("quit-after not a number")
        << QStringList{u"--quit-after"_s, u"abc"_s} << u"--quit-after"_s;
    QTest::newRow("quit-after negative")
        << QStringList{u"--quit-after"_s, u"-5"_s} << u"--quit-after"_s;
    QTest::newRow("quit-after nan")
        << QStringList{u"--quit-after"_s, u"nan"_s} << u"--quit-after"_s;
    QTest::newRow("quit-after inf") << QStringList{u"--quit-after=inf"_s} << u"--quit-after"_s;
    QTest::newRow("quit-after beyond int ms")
        << QStringList{u"--quit-after"_s, u"1e300"_s} << u"--quit-after"_s;
    QTest::newRow("quit-after empty") << QStringList{u"--quit-after="_s} << u"--quit-after"_s;
    QTest::newRow("bridge not a ROS") << QStringList{u"--bridge"_s, u"3"_s} << u"--bridge"_s;
    QTest::newRow("repaint-rate nan")
        << QStringList{u"--repaint-rate"_s, u"nan"_s} << u"--repaint-rate"_s;
    QTest::newRow("repaint-rate not a number")
        << QStringList{u"--repaint-rate"_s, u"fast"_s} << u"--repaint-rate"_s;
    QTest::newRow("repaint-rate zero")
        << QStringList{u"--repaint-rate"_s, u"0"_s} << u"--repaint-rate"_s;
    QTest::newRow("baud not a number") << QStringList{u"--baud"_s, u"fast"_s} << u"--baud"_s;
    QTest::newRow("baud negative") << QStringList{u"--baud"_s, u"-9600"_s} << u"--baud"_s;
    QTest::newRow("baud below 300") << QStringList{u"--baud"_s, u"299"_s} << u"--baud"_s;
    QTest::newRow("protocol unknown") << QStringList{u"--protocol"_s, u"v3"_s} << u"--protocol"_s;
    QTest::newRow("faults spec") << QStringList{u"--port"_s, u"sim"_s, u"--faults"_s, u"drop=2"_s}
                                 << u"--faults"_s;
    QTest::newRow("faults without the sim port")
        << QStringList{u"--port"_s, u"/dev/null"_s, u"--faults"_s, u"drop=0.1"_s} << u"--faults"_s;
    QTest::newRow("seed not a number")
        << QStringList{u"--port"_s, u"sim"_s, u"--seed"_s, u"-1"_s} << u"--seed"_s;
}

void TestTunerOptions::refusesBadNumbers()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, option);
    // A refusal is immediate; a tuner that opened its window instead is killed after 15 s, so
    // that a silent acceptance fails here rather than hanging.
    const Run run = runTuner(m_config.path(), arguments, 15000);
    QVERIFY2(run.code == 4, qPrintable(u"exit "_s + QString::number(run.code) + u", stderr: "_s +
                                       QString::fromUtf8(run.err)));
    const QString err = QString::fromUtf8(run.err).trimmed();
    QVERIFY2(err.startsWith(u"hatpic-tuner: "_s + option), qPrintable(err));
    QCOMPARE(err.count(u'\n'), 0); // one sentence
}

void TestTunerOptions::quitAfterCloses()
{
    const Run run = runTuner(m_config.path(), {u"--quit-after"_s, u"0.5"_s}, 30000);
    QVERIFY2(run.code == 0, qPrintable(u"exit "_s + QString::number(run.code) + u", stderr: "_s +
                                       QString::fromUtf8(run.err)));
}

void TestTunerOptions::signalClosesTheRecording_data()
{
    QTest::addColumn<int>("signal");
    QTest::addColumn<int>("code");
    QTest::newRow("SIGTERM") << int(SIGTERM) << 0;
    QTest::newRow("SIGHUP") << int(SIGHUP) << 128 + SIGHUP;
    QTest::newRow("SIGINT") << int(SIGINT) << 0;
}

// The real tuner, offscreen, recording the simulated joystick, ended by a signal: the
// recording is closed — every buffered row on disk, its .json saying so (issue 27: a kill lost
// the rows and left "closed": false).
void TestTunerOptions::signalClosesTheRecording()
{
    QFETCH(int, signal);
    QFETCH(int, code);
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"run.csv"_s);
    QProcess process;
    process.setProgram(QStringLiteral(HATPIC_TUNER_PATH));
    process.setArguments({u"--port"_s, u"sim"_s, u"--record"_s, csv});
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(u"QT_QPA_PLATFORM"_s, u"offscreen"_s);
    env.insert(u"XDG_CONFIG_HOME"_s, m_config.path());
    env.insert(u"XDG_RUNTIME_DIR"_s, m_config.path());
    process.setProcessEnvironment(env);
    process.start();
    QVERIFY(process.waitForStarted(10000));
    // Recording: the .json is written at the start; then a second of samples.
    const QString json = dir.filePath(u"run.json"_s);
    QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(json), 30000);
    QTest::qWait(1500);
    QCOMPARE(::kill(pid_t(process.processId()), signal), 0);
    QVERIFY(process.waitForFinished(15000));
    QCOMPARE(process.exitStatus(), QProcess::NormalExit);
    QVERIFY2(process.exitCode() == code,
             qPrintable(u"exit %1: %2"_s.arg(process.exitCode())
                            .arg(QString::fromUtf8(process.readAllStandardError()))));

    QFile metaFile(json);
    QVERIFY(metaFile.open(QIODevice::ReadOnly));
    const QJsonObject meta = QJsonDocument::fromJson(metaFile.readAll()).object();
    QCOMPARE(meta.value(u"closed"_s).toBool(false), true);
    QFile csvFile(csv);
    QVERIFY(csvFile.open(QIODevice::ReadOnly));
    const QByteArray rows = csvFile.readAll();
    QVERIFY(rows.endsWith('\n'));
    const qint64 samples = rows.count('\n') - 1; // the header
    QVERIFY2(samples > 100, qPrintable(QString::number(samples)));
    QCOMPARE(qint64(meta.value(u"samples"_s).toDouble()), samples);
}

// Without a display QApplication aborts (SIGABRT): help and option errors come before it
// (issue 21).
void TestTunerOptions::helpAndErrorsNeedNoDisplay_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("stdoutStart");
    QTest::addColumn<QString>("stderrStart");
    QTest::newRow("--help") << QStringList{u"--help"_s} << 0
                            << u"Usage: "_s + QStringLiteral(HATPIC_TUNER_PATH) +
                                   u" [options] [RECORDING.csv]\n"_s
                            << QString();
    QTest::newRow("-h with a Qt option")
        << QStringList{u"-style"_s, u"Fusion"_s, u"-h"_s} << 0 << u"Usage: "_s << QString();
    QTest::newRow("--help-all lists Qt's options")
        << QStringList{u"--help-all"_s} << 0 << u"Usage: "_s << QString();
    // Bad usage exits 4 in every program (app/common/exitcodes.h), Qt's parse errors too.
    QTest::newRow("unknown option") << QStringList{u"--bogus"_s} << 4 << QString()
                                    << u"hatpic-tuner: Unknown option 'bogus'.\n"_s;
    QTest::newRow("missing value") << QStringList{u"--port"_s} << 4 << QString()
                                   << u"hatpic-tuner: Missing value after '--port'.\n"_s;
    QTest::newRow("bad number") << QStringList{u"--quit-after"_s, u"abc"_s} << 4 << QString()
                                << u"hatpic-tuner: --quit-after"_s;
    QTest::newRow("bad number after a Qt option")
        << QStringList{u"-reverse"_s, u"--repaint-rate"_s, u"0"_s} << 4 << QString()
        << u"hatpic-tuner: --repaint-rate"_s;
}

void TestTunerOptions::helpAndErrorsNeedNoDisplay()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, code);
    QFETCH(QString, stdoutStart);
    QFETCH(QString, stderrStart);
    const Run run = runTuner(m_config.path(), arguments, 15000, u"xcb"_s);
    QVERIFY2(run.code == code, qPrintable(u"exit "_s + QString::number(run.code) + u", stderr: "_s +
                                          QString::fromUtf8(run.err)));
    QVERIFY2(QString::fromUtf8(run.out).startsWith(stdoutStart), run.out.constData());
    QVERIFY2(QString::fromUtf8(run.err).startsWith(stderrStart), run.err.constData());
    if (QTest::currentDataTag() == QByteArray("--help-all lists Qt's options"))
        QVERIFY2(run.out.contains("-platform"), run.out.constData());
}

// Qt's own options are still Qt's: -platform here chooses the platform, not --port
// ("-p latform") and a recording named "offscreen".
void TestTunerOptions::qtOptionsStillWork()
{
    const Run run =
        runTuner(m_config.path(), {u"-platform"_s, u"offscreen"_s, u"--quit-after"_s, u"0.3"_s},
                 30000, u"xcb"_s);
    QVERIFY2(run.code == 0, qPrintable(u"exit "_s + QString::number(run.code) + u", stderr: "_s +
                                       QString::fromUtf8(run.err)));
    QVERIFY2(!run.err.contains("hatpic-tuner:"), run.err.constData());
}

QTEST_GUILESS_MAIN(TestTunerOptions)
#include "tst_tuneroptions.moc"
