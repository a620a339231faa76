// hatpic-tuner as a real process: numeric options out of range or not numbers are refused
// before the window opens, with one sentence and exit code 2 (issue 10, "Hostile input").
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {

struct Run
{
    int code = -1; //!< -1: did not finish in time, -2: crashed
    QByteArray err;
};

Run runTuner(const QString &configDir, const QStringList &arguments, int timeoutMs)
{
    QProcess process;
    process.setProgram(QStringLiteral(HATPIC_TUNER_PATH));
    process.setArguments(arguments);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(u"QT_QPA_PLATFORM"_s, u"offscreen"_s);
    env.insert(u"XDG_CONFIG_HOME"_s, configDir); // never the user's own settings
    env.insert(u"XDG_RUNTIME_DIR"_s, configDir); // 0700: no warning on stderr
    process.setProcessEnvironment(env);
    process.start();
    Run run;
    if (!process.waitForStarted(10000))
        return run;
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished(5000);
        return run;
    }
    run.err = process.readAllStandardError();
    run.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    return run;
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
    QTest::newRow("repaint-rate nan")
        << QStringList{u"--repaint-rate"_s, u"nan"_s} << u"--repaint-rate"_s;
    QTest::newRow("repaint-rate not a number")
        << QStringList{u"--repaint-rate"_s, u"fast"_s} << u"--repaint-rate"_s;
    QTest::newRow("repaint-rate zero")
        << QStringList{u"--repaint-rate"_s, u"0"_s} << u"--repaint-rate"_s;
    QTest::newRow("baud not a number") << QStringList{u"--baud"_s, u"fast"_s} << u"--baud"_s;
    QTest::newRow("baud negative") << QStringList{u"--baud"_s, u"-9600"_s} << u"--baud"_s;
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
    QVERIFY2(run.code == 2, qPrintable(u"exit "_s + QString::number(run.code) + u", stderr: "_s +
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

QTEST_GUILESS_MAIN(TestTunerOptions)
#include "tst_tuneroptions.moc"
