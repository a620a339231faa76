// hatpicctl as a real process against hostile conditions (issue 10, "Hostile input"): files it
// did not create, paths that are not files, signals, a file-size limit, line noise before
// HELLO, a silent legacy port.
#include "processrun.h"
#include "scripteddevice.h"
#include "telemetry/recordingreader.h"
#include "testfiles.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>
#include <limits>
#include <pty.h>
#include <sys/resource.h>
#include <unistd.h>

using namespace hatpic;
using namespace Qt::StringLiterals;
using hatpic::test::readAll;
using hatpic::test::Run;
using hatpic::test::runToEnd;
using hatpic::test::writeFile;

namespace {

Run runCtl(const QStringList &arguments, qint64 fileSizeLimit = 0)
{
    QProcess process;
    process.setProgram(QStringLiteral(HATPICCTL_PATH));
    process.setArguments(arguments);
    if (fileSizeLimit > 0) {
        process.setChildProcessModifier([fileSizeLimit] {
            const rlimit limit{rlim_t(fileSizeLimit), rlim_t(fileSizeLimit)};
            ::setrlimit(RLIMIT_FSIZE, &limit);
        });
    }
    return runToEnd(process, 60000);
}

QString describe(const Run &run)
{
    return u"exit "_s + QString::number(run.code) + u"\nstderr: "_s + QString::fromUtf8(run.err);
}

//! The rows of a recording's CSV on disk, and whether it ends in a whole row.
qsizetype rowsOf(const QString &csv, bool *whole)
{
    const QByteArray text = readAll(csv);
    *whole = text.endsWith('\n');
    return text.count('\n') - 1;
}

//! The number on stderr's "samples" line.
qint64 samplesLine(const QByteArray &err)
{
    for (const QByteArray &line : err.split('\n')) {
        if (line.startsWith("samples "))
            return line.mid(8).trimmed().split(' ').value(0).toLongLong();
    }
    return -1;
}

//! Runs hatpicctl while this thread's event loop keeps a ScriptedDevice answering.
Run runCtlWithDevice(const QStringList &arguments)
{
    QProcess process;
    process.setProgram(QStringLiteral(HATPICCTL_PATH));
    process.setArguments(arguments);
    process.start();
    Run run;
    if (!process.waitForStarted(10000))
        return run;
    QElapsedTimer clock;
    clock.start();
    while (process.state() != QProcess::NotRunning && clock.elapsed() < 30000)
        QTest::qWait(20);
    if (process.state() != QProcess::NotRunning) {
        process.kill();
        process.waitForFinished(5000);
        return run;
    }
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    run.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    return run;
}

const QByteArray kProfile = R"({"format": "hatpic-profile", "version": 1})";

} // namespace

class TestHatpicCtlHostile : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void streamNeverOverwritesWithoutForce_data();
    void streamNeverOverwritesWithoutForce();
    void streamForceReplacesAProfile();
    void failedStartTouchesNothing();
    void deviceAsRecordingIsRefused();
    void emptyCsvNameIsRefused();
    void hangupClosesTheRecording();
    void fileSizeLimitKeepsWholeRows();
    void samplesFigureIsTheRowCount();
    void strayByteBeforeDetection();
    void silentLegacyPortSaysNoFrameArrived();
    void infoRefusesANonsenseDevice();
    void infoEscapesTheFirmwareName();
    void getRefusesInvalidDeviceParameters();
    void setBlamesTheDeviceForItsParameters();
    void simulateRefusesAnAbsurdHand_data();
    void simulateRefusesAnAbsurdHand();

private:
    QTemporaryDir m_dir;
};

void TestHatpicCtlHostile::streamNeverOverwritesWithoutForce_data()
{
    QTest::addColumn<QString>("existing");
    QTest::newRow("the CSV") << u"mine.csv"_s;
    QTest::newRow("a profile as the .json") << u"mine.json"_s;
}

void TestHatpicCtlHostile::streamNeverOverwritesWithoutForce()
{
    QFETCH(QString, existing);
    QTemporaryDir dir;
    QVERIFY(writeFile(dir.filePath(existing), kProfile));
    const QString csv = dir.filePath(u"mine.csv"_s);
    const Run run =
        runCtl({u"stream"_s, u"--port"_s, u"sim"_s, u"--duration"_s, u"0.5"_s, u"--csv"_s, csv});
    QVERIFY2(run.code == 4, qPrintable(describe(run)));
    QVERIFY2(run.err.trimmed().count('\n') == 0 && run.err.contains("--force"),
             qPrintable(describe(run)));
    QCOMPARE(readAll(dir.filePath(existing)), kProfile);
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{existing});
}

void TestHatpicCtlHostile::streamForceReplacesAProfile()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"mine.csv"_s);
    QVERIFY(writeFile(dir.filePath(u"mine.json"_s), kProfile));
    QVERIFY(writeFile(csv, "old\n"));
    const Run run = runCtl({u"stream"_s, u"--port"_s, u"sim"_s, u"--duration"_s, u"0.5"_s,
                            u"--csv"_s, csv, u"--force"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording, qPrintable(read.error));
    QVERIFY(read.recording->hasMetadata);
}

void TestHatpicCtlHostile::failedStartTouchesNothing()
{
    // k.json is a folder: the start is refused (even with --force) before k.csv is touched.
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"k.csv"_s);
    QVERIFY(writeFile(csv, "precious\n"));
    QVERIFY(QDir(dir.path()).mkdir(u"k.json"_s));
    for (const bool force : {false, true}) {
        QStringList args{u"stream"_s, u"--port"_s, u"sim"_s, u"--duration"_s,
                         u"0.5"_s,    u"--csv"_s,  csv};
        if (force)
            args << u"--force"_s;
        const Run run = runCtl(args);
        QVERIFY2(run.code == 4, qPrintable(describe(run)));
        QVERIFY2(run.err.contains("k.json"), qPrintable(describe(run)));
        QCOMPARE(readAll(csv), QByteArray("precious\n"));
    }
}

void TestHatpicCtlHostile::deviceAsRecordingIsRefused()
{
    // A link to /dev/null in a temporary folder: no null.json may appear beside it.
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"null.csv"_s);
    QVERIFY(QFile::link(u"/dev/null"_s, csv));
    const Run run = runCtl({u"stream"_s, u"--port"_s, u"sim"_s, u"--duration"_s, u"0.5"_s,
                            u"--csv"_s, csv, u"--force"_s});
    QVERIFY2(run.code == 4, qPrintable(describe(run)));
    QVERIFY2(run.err.contains("not a regular file"), qPrintable(describe(run)));
    QVERIFY(!QFileInfo::exists(dir.filePath(u"null.json"_s)));
}

void TestHatpicCtlHostile::emptyCsvNameIsRefused()
{
    const Run run = runCtl(
        {u"stream"_s, u"--port"_s, u"sim"_s, u"--duration"_s, u"0.5"_s, u"--csv"_s, QString()});
    QVERIFY2(run.code == 4, qPrintable(describe(run)));
    QVERIFY(run.out.isEmpty());
}

void TestHatpicCtlHostile::hangupClosesTheRecording()
{
    const QString csv = m_dir.filePath(u"hup.csv"_s);
    QProcess ctl;
    ctl.setProgram(QStringLiteral(HATPICCTL_PATH));
    ctl.setArguments({u"stream"_s, u"--port"_s, u"sim"_s, u"--csv"_s, csv});
    ctl.start();
    QVERIFY(ctl.waitForStarted(5000));
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(csv).size() > 1000, 15000);
    QCOMPARE(::kill(pid_t(ctl.processId()), SIGHUP), 0);
    QVERIFY(ctl.waitForFinished(15000));
    const QByteArray err = ctl.readAllStandardError();
    QCOMPARE(ctl.exitStatus(), QProcess::NormalExit);
    QVERIFY2(ctl.exitCode() == 0, err.constData());
    const QJsonObject meta = QJsonDocument::fromJson(readAll(recordingMetadataPath(csv))).object();
    QCOMPARE(meta.value(u"closed").toBool(), true);
    bool whole = false;
    const qsizetype rows = rowsOf(csv, &whole);
    QVERIFY(whole && rows > 0);
    QCOMPARE(qsizetype(meta.value(u"samples").toDouble()), rows);
}

void TestHatpicCtlHostile::fileSizeLimitKeepsWholeRows()
{
    // ulimit -f: SIGXFSZ must not kill hatpicctl mid-row; the write fails, whole rows stay.
    const QString csv = m_dir.filePath(u"limited.csv"_s);
    const Run run =
        runCtl({u"stream"_s, u"--port"_s, u"sim"_s, u"--duration"_s, u"20"_s, u"--csv"_s, csv},
               100 * 1000 + 37);
    QVERIFY2(run.code == 4, qPrintable(describe(run)));
    QVERIFY2(run.err.contains("File too large"), qPrintable(describe(run)));
    bool whole = false;
    const qsizetype rows = rowsOf(csv, &whole);
    QVERIFY2(whole, "the recording ends in half a row");
    const QJsonObject meta = QJsonDocument::fromJson(readAll(recordingMetadataPath(csv))).object();
    QCOMPARE(meta.value(u"closed").toBool(), true);
    QVERIFY(meta.contains(u"error"));
    QCOMPARE(qsizetype(meta.value(u"samples").toDouble()), rows);
    QCOMPARE(samplesLine(run.err), qint64(rows));
    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording && read.warnings.isEmpty(), qPrintable(read.error));
}

void TestHatpicCtlHostile::samplesFigureIsTheRowCount()
{
    const QString csv = m_dir.filePath(u"count.csv"_s);
    const Run run =
        runCtl({u"stream"_s, u"--port"_s, u"sim"_s, u"--duration"_s, u"1"_s, u"--csv"_s, csv});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    bool whole = false;
    QCOMPARE(samplesLine(run.err), qint64(rowsOf(csv, &whole)));
}

void TestHatpicCtlHostile::strayByteBeforeDetection()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not built");
#else
    QProcess sim;
    sim.setProgram(QStringLiteral(HATPIC_SIM_PATH));
    sim.start();
    QVERIFY(sim.waitForStarted(5000));
    QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
    const QString path = QString::fromLocal8Bit(sim.readLine()).trimmed();
    {
        QFile tty(path); // printf '\x05' > PTY
        QVERIFY(tty.open(QIODevice::WriteOnly | QIODevice::Unbuffered));
        QCOMPARE(tty.write("\x05", 1), qint64(1));
    }
    const Run info = runCtl({u"info"_s, u"--port"_s, path});
    sim.terminate();
    sim.waitForFinished(10000);
    QVERIFY2(info.code == 0, qPrintable(describe(info)));
#endif
}

void TestHatpicCtlHostile::silentLegacyPortSaysNoFrameArrived()
{
    int master = -1;
    int slave = -1;
    char name[256] = {};
    QVERIFY(::openpty(&master, &slave, name, nullptr, nullptr) == 0);
    const Run run = runCtl({u"info"_s, u"--port"_s, QString::fromLocal8Bit(name), u"--protocol"_s,
                            u"legacy"_s, u"--timeout"_s, u"5"_s});
    ::close(slave);
    ::close(master);
    QVERIFY2(run.code == 3, qPrintable(describe(run)));
    QVERIFY2(run.err.contains("No legacy HATPIC frame arrived"), qPrintable(describe(run)));
}

void TestHatpicCtlHostile::infoRefusesANonsenseDevice()
{
    test::ScriptedDevice device;
    QVERIFY(device.isValid());
    device.hello.tauLimit = -1.0f;
    const Run run = runCtlWithDevice({u"info"_s, u"--port"_s, device.path(), u"--json"_s});
    QVERIFY2(run.code == 3, qPrintable(describe(run)));
    QVERIFY2(run.err.contains("tau_limit"), qPrintable(describe(run)));
    QVERIFY(run.out.isEmpty());
}

void TestHatpicCtlHostile::infoEscapesTheFirmwareName()
{
    test::ScriptedDevice device;
    QVERIFY(device.isValid());
    device.hello.firmware.assign("ev\x1b[2J\r\nil");
    const Run run = runCtlWithDevice({u"info"_s, u"--port"_s, device.path()});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QVERIFY(!run.out.contains('\x1b') && !run.out.contains('\r'));
    QVERIFY2(run.out.contains("ev\\x1b[2J\\x0d\\x0ail"), run.out.constData());
}

void TestHatpicCtlHostile::getRefusesInvalidDeviceParameters()
{
    test::ScriptedDevice device;
    QVERIFY(device.isValid());
    device.params.K_min = std::numeric_limits<double>::quiet_NaN();
    const Run run = runCtlWithDevice({u"get"_s, u"--port"_s, device.path(), u"--json"_s});
    QVERIFY2(run.code == 3, qPrintable(describe(run)));
    QVERIFY2(run.err.contains("K_min") && run.err.contains("device"), qPrintable(describe(run)));
    QVERIFY(run.out.isEmpty());
}

void TestHatpicCtlHostile::setBlamesTheDeviceForItsParameters()
{
    // K_min above K_max came from the device, not from --set N=0.12.
    test::ScriptedDevice device;
    QVERIFY(device.isValid());
    device.params.K_min = 0.9;
    device.params.K_max = 0.4;
    const Run run =
        runCtlWithDevice({u"set"_s, u"--port"_s, device.path(), u"--set"_s, u"N=0.12"_s});
    QVERIFY2(run.code == 3, qPrintable(describe(run)));
    QVERIFY2(run.err.contains("The device's current parameters are not valid"),
             qPrintable(describe(run)));
}

void TestHatpicCtlHostile::simulateRefusesAnAbsurdHand_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<QByteArray>("bound"); // what the sentence names
    QTest::newRow("torque") << u"const:1e305"_s << QByteArray("±10 N·m");
    QTest::newRow("angle") << u"hand:1e307"_s << QByteArray("more than one turn");
    QTest::newRow("frequency") << u"sine:1:1e308"_s << QByteArray("1000 Hz");
}

void TestHatpicCtlHostile::simulateRefusesAnAbsurdHand()
{
    // These once printed rows of empty values with exit 0: the knob's speed overflowed.
    QFETCH(QString, spec);
    QFETCH(QByteArray, bound);
    const QString profile = m_dir.filePath(u"simulate.json"_s);
    QVERIFY(writeFile(profile, kProfile));
    for (const bool ideal : {false, true}) {
        QStringList args{u"simulate"_s, u"--profile"_s, profile, u"--input"_s, spec};
        if (ideal)
            args << u"--ideal"_s;
        const Run run = runCtl(args);
        QVERIFY2(run.code == 4, qPrintable(describe(run)));
        QVERIFY2(run.out.isEmpty(), qPrintable(describe(run)));
        QVERIFY2(run.err.trimmed().count('\n') == 0 && run.err.contains(bound),
                 qPrintable(describe(run)));
    }
}

QTEST_GUILESS_MAIN(TestHatpicCtlHostile)
#include "tst_hatpicctlhostile.moc"
