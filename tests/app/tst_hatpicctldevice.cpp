// hatpicctl's device commands, run as a real process, against the in-process simulated
// joystick, a hatpic-sim child on a pseudo-terminal, a port that does not exist and one that
// stays silent: get, set, push, stream (to a file, to stdout, ended by a signal), a device's
// rejection, the link lost during a stream, a failed save.
#include "ctlprocess.h"
#include "ctltest.h"
#include "telemetry/recordingreader.h"

#include <QFileInfo>
#include <QProcess>
#include <QStringList>
#include <QTest>

#include <csignal>
#include <pty.h>
#include <sys/types.h>
#include <unistd.h>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

#ifdef HATPIC_SIM_PATH
//! Starts hatpic-sim with `arguments` and returns its pseudo-terminal's path, the first line it
//! prints; empty when it did not start or say one within 10 s.
QString startSim(QProcess &sim, const QStringList &arguments)
{
    sim.start(QStringLiteral(HATPIC_SIM_PATH), arguments);
    if (!sim.waitForStarted(5000))
        return {};
    for (int waited = 0; !sim.canReadLine() && waited < 10000; waited += 50)
        sim.waitForReadyRead(50);
    return QString::fromLocal8Bit(sim.readLine()).trimmed();
}
#endif

} // namespace

class TestHatpicCtlDevice : public CtlTest
{
    Q_OBJECT

private Q_SLOTS:
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
    void ptyImuBranchSimulator();
    void ptyLinkLostDuringStream();
    void ptySaveStorageError();
    void streamInterruptedEndsCleanly_data();
    void streamInterruptedEndsCleanly();
};

// ---- device commands against the in-process simulated joystick ----

void TestHatpicCtlDevice::simDevice_data()
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

void TestHatpicCtlDevice::simDevice()
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

void TestHatpicCtlDevice::simGetJsonRoundTrips()
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

void TestHatpicCtlDevice::simSetChangesParameters()
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

void TestHatpicCtlDevice::simStreamRecording()
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

void TestHatpicCtlDevice::simStreamToStdout()
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

void TestHatpicCtlDevice::deviceRejection()
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

void TestHatpicCtlDevice::noSuchPort_data()
{
    QTest::addColumn<QString>("command");
    QTest::newRow("info") << u"info"_s;
    QTest::newRow("get") << u"get"_s;
    QTest::newRow("stream") << u"stream"_s;
}

void TestHatpicCtlDevice::noSuchPort()
{
    QFETCH(QString, command);
    const Run run =
        runCtl({command, u"--port"_s, m_dir.filePath(u"no-such-tty"_s), u"--timeout"_s, u"3"_s});
    QVERIFY2(run.code == 3, qPrintable(describe(run)));
    QVERIFY2(isOneLine(run.err), qPrintable(describe(run)));
    QVERIFY(run.out.isEmpty());
}

void TestHatpicCtlDevice::silentPort_data()
{
    QTest::addColumn<QString>("protocol");
    QTest::newRow("detecting") << u"auto"_s;
    QTest::newRow("forced v2") << u"v2"_s;
    QTest::newRow("forced legacy") << u"legacy"_s;
}

void TestHatpicCtlDevice::silentPort()
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

void TestHatpicCtlDevice::ptySimulator()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not built");
#else
    const QString link = m_dir.filePath(u"hatpic"_s);
    QProcess sim;
    const QString path = startSim(sim, {u"--link"_s, link});
    QVERIFY2(!path.isEmpty(), qPrintable(sim.errorString()));
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

void TestHatpicCtlDevice::ptyLegacySimulator()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not built");
#else
    // The published firmware's protocol: identity and telemetry work, parameters cannot.
    QProcess sim;
    const QString path = startSim(sim, {u"--protocol"_s, u"legacy"_s});
    QVERIFY2(!path.isEmpty(), qPrintable(sim.errorString()));

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

void TestHatpicCtlDevice::ptyImuBranchSimulator()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not built");
#else
    // The published IMU branch's board: four knobs and the tilt, to stdout and to a recording.
    QProcess sim;
    const QString path = startSim(sim, {u"--device"_s, u"imu-branch"_s, u"--hand-2"_s,
                                        u"const:0.05"_s, u"--tilt"_s, u"0.3,0"_s});
    QVERIFY2(!path.isEmpty(), qPrintable(sim.errorString()));

    const Run info = runCtl({u"info"_s, u"--port"_s, path});
    QVERIFY2(info.code == 0, qPrintable(describe(info)));
    QVERIFY2(info.out.contains("published IMU branch (legacy)") &&
                 info.out.contains("knobs             4") &&
                 info.out.contains("tilt              roll and pitch"),
             qPrintable(describe(info)));

    const Run out = runCtl({u"stream"_s, u"--port"_s, path, u"--duration"_s, u"1.2"_s});
    QVERIFY2(out.code == 0, qPrintable(describe(out)));
    const QList<QByteArray> lines = out.out.trimmed().split('\n');
    QVERIFY2(lines.size() >= 3, qPrintable(describe(out)));
    const QList<QByteArray> header = lines[0].split(',');
    QCOMPARE(header.size(), 13 + 3 * 8 + 2);
    QCOMPARE(header[13], QByteArray("theta_2"));
    QCOMPARE(header.last(), QByteArray("pitch"));
    const QList<QByteArray> fields = lines.last().split(',');
    QCOMPARE(fields.size(), header.size());
    QVERIFY2(fields[13].toDouble() > 0.02, lines.last().constData()); // knob 2 pushed
    QVERIFY2(fields[14].isEmpty(), lines.last().constData());         // omega_2 not carried
    QVERIFY2(std::abs(fields[header.size() - 2].toDouble() - 0.3) < 1e-3, lines.last().constData());

    const QString csv = m_dir.filePath(u"imu-stream.csv"_s);
    const Run stream =
        runCtl({u"stream"_s, u"--port"_s, path, u"--duration"_s, u"1.2"_s, u"--csv"_s, csv});
    QVERIFY2(stream.code == 0, qPrintable(describe(stream)));
    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording.has_value(), qPrintable(read.error));
    QVERIFY(!read.recording->samples.isEmpty());
    QCOMPARE(read.recording->samples.last().axes(), 4);
    QVERIFY(read.recording->samples.last().axis(2)->theta > 0.02);

    sim.terminate();
    QVERIFY(sim.waitForFinished(10000));
#endif
}

void TestHatpicCtlDevice::ptyLinkLostDuringStream()
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

void TestHatpicCtlDevice::ptySaveStorageError()
{
#ifndef HATPIC_SIM_PATH
    QSKIP("hatpic-sim is not built");
#else
    // A state file in a folder that does not exist: SAVE_PARAMS fails on the device, which
    // answers STORAGE_ERROR, and hatpicctl exits with 2 (docs/cli.md, exit codes).
    QProcess sim;
    const QString path =
        startSim(sim, {u"--state"_s, m_dir.filePath(u"no-such-folder/state.json"_s)});
    QVERIFY2(!path.isEmpty(), qPrintable(sim.errorString()));

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

void TestHatpicCtlDevice::streamInterruptedEndsCleanly_data()
{
    QTest::addColumn<int>("signal");
    QTest::newRow("SIGINT") << int(SIGINT);
    QTest::newRow("SIGTERM") << int(SIGTERM);
}

void TestHatpicCtlDevice::streamInterruptedEndsCleanly()
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

QTEST_GUILESS_MAIN(TestHatpicCtlDevice)
#include "tst_hatpicctldevice.moc"
