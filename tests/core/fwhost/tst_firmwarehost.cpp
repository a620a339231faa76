// hatpic-fw-host end to end: the real binary driving hatpic-servo-sim's emulated STS3032 over
// one real pseudo-terminal, served to a v2 host (and hatpicctl) over another.
#include "fwhosttest.h"
#include "link/pseudoterminal.h"
#include "model/stiffness.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSocketNotifier>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <csignal>
#include <unistd.h>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

constexpr double kHandTorque = 0.02;     //!< --hand const:0.02 [N·m]
constexpr double kLoadQuantum = 0.44e-3; //!< tau_limit / 1000 [N·m]
constexpr int kSettleMs = 1500;          //!< from a change to the window [ms]
constexpr int kWindowMs = 500;           //!< window the rest point is averaged over [ms]
constexpr int kTimeoutMs = 5000;

DeviceParams asDevice(DeviceParams p) // the device keeps 7 × f32
{
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        p.setField(i, double(float(p.field(i))));
    return p;
}

//! The θ where the model holds the measured hand torque plus τ_ext (bisection) [rad].
double restPoint(const DeviceParams &p, double tauExt)
{
    // The servo reads the hand's torque on its load grid: 0.02 N·m reads 45 quanta.
    const double push = std::round(kHandTorque / kLoadQuantum) * kLoadQuantum + tauExt;
    double lo = 0, hi = 1;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (recenteringTorque(p, mid) + push > 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

QList<v2::Telemetry> telemetrySince(const V2Client &client, qsizetype from)
{
    QList<v2::Telemetry> out;
    for (qsizetype i = from; i < client.frames.size(); ++i) {
        if (const auto *t = std::get_if<v2::Telemetry>(&client.frames.at(i).message))
            out.append(*t);
    }
    return out;
}

//! Waits kSettleMs, then averages θ over kWindowMs of telemetry.
double settledTheta(V2Client &client)
{
    QTest::qWait(kSettleMs); // the knob needs the time: nothing to poll for
    const qsizetype from = client.frames.size();
    QTest::qWait(kWindowMs);
    const QList<v2::Telemetry> window = telemetrySince(client, from);
    double sum = 0;
    for (const v2::Telemetry &t : window)
        sum += t.theta;
    return window.isEmpty() ? std::nan("") : sum / double(window.size());
}

//! Every frame's θ on the tick grid, τ on the load grid, τ_rec the model at that θ.
QString inconsistency(const QList<v2::Telemetry> &frames, const DeviceParams &p)
{
    for (const v2::Telemetry &t : frames) {
        const double ticks = t.theta / kTick;
        const double loads = t.tau / kLoadQuantum;
        const double model = recenteringTorque(p, double(t.theta));
        if (std::abs(ticks - std::round(ticks)) > 1e-3)
            return u"θ %1 is %2 ticks"_s.arg(t.theta).arg(ticks);
        if (std::abs(loads - std::round(loads)) > 1e-3)
            return u"τ %1 is %2 load units"_s.arg(t.tau).arg(loads);
        if (std::abs(double(t.tau_rec) - model) > 1e-6)
            return u"τ_rec %1 at θ %2, the model says %3"_s.arg(t.tau_rec).arg(t.theta).arg(model);
    }
    return {};
}

} // namespace

class TestFirmwareHost : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void closedLoopThroughPtys();
    void savedParamsSurviveRestart();
    void hatpicctlInfo();
    void faultsAreInjectedAndCounted();
    void sigtermDisablesTorque();
    void everyEndingSignalDisablesTorque_data();
    void everyEndingSignalDisablesTorque();
    void silentServoFails();
    void servoAnsweringLateAtStartIsWaitedFor();
    void wronglyAnsweringServoFails();
    void experimentFailsWhenTheTorqueGoesOff();
    void badOptions_data();
    void badOptions();
};

void TestFirmwareHost::closedLoopThroughPtys()
{
    PtyProgram servo(hatpicServoSim(), {u"--hand"_s, u"const:0.02"_s});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    PtyProgram host(hatpicFwHost(),
                    QStringList{u"--servo"_s, servo.path(), u"--quiet"_s} + patientBus());
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    V2Client client(host.path());
    QVERIFY2(client.open(), qPrintable(client.errorString()));
    client.send(v2::SetStream{1000});

    // Defaults: at rest where K_rec holds the hand, 0.0495 rad.
    const DeviceParams defaults = asDevice(DeviceParams{});
    const double rest = settledTheta(client);
    qInfo("rest %.5f rad (model %.5f)", rest, restPoint(defaults, 0));
    QVERIFY(std::abs(restPoint(defaults, 0) - 0.0495) < 1e-4);
    QVERIFY2(std::abs(rest - 0.0495) < 2 * kTick, qPrintable(QString::number(rest)));
    const QList<v2::Telemetry> early = telemetrySince(client, 0);
    QVERIFY(early.size() > 1000);
    QCOMPARE(inconsistency(early, defaults), QString());

    // K_max = 0.5 moves the rest point to 0.0396 rad.
    DeviceParams stiff = defaults;
    stiff.K_max = 0.5;
    const quint8 seq = client.send(v2::SetParams{stiff});
    QTRY_VERIFY_WITH_TIMEOUT(client.ack(seq).has_value(), kTimeoutMs);
    QCOMPARE(client.ack(seq)->status, v2::AckStatus::Ok);
    const qsizetype afterSet = client.frames.size();
    const double stiffRest = settledTheta(client);
    qInfo("rest with K_max 0.5: %.5f rad (model %.5f)", stiffRest, restPoint(asDevice(stiff), 0));
    QVERIFY2(std::abs(stiffRest - 0.0396) < 2 * kTick, qPrintable(QString::number(stiffRest)));
    QCOMPARE(inconsistency(telemetrySince(client, afterSet + 100), asDevice(stiff)), QString());

    // Streamed feedback shifts the rest point…
    constexpr float kTauExt = 0.01f;
    QTimer feedback;
    QElapsedTimer sinceLastFeedback;
    connect(&feedback, &QTimer::timeout, this, [&] {
        client.send(v2::SetFeedback{kTauExt});
        sinceLastFeedback.start();
    });
    feedback.start(20);
    const double pushed = settledTheta(client);
    const double pushedModel = restPoint(asDevice(stiff), double(kTauExt));
    qInfo("rest with τ_ext %.3f N·m: %.5f rad (model %.5f)", double(kTauExt), pushed, pushedModel);
    QVERIFY2(std::abs(pushed - pushedModel) < 2 * kTick, qPrintable(QString::number(pushed)));
    QCOMPARE(telemetrySince(client, client.frames.size() - 50).last().tau_ext, kTauExt);

    // …and the watchdog takes it back 200 ms after the feedback stops.
    feedback.stop();
    const qsizetype stopped = client.frames.size();
    const auto stale = [&] {
        for (const v2::Telemetry &t : telemetrySince(client, stopped)) {
            if (t.flags & v2::kFlagFeedbackStale)
                return true;
        }
        return false;
    };
    QTRY_VERIFY_WITH_TIMEOUT(stale(), kTimeoutMs);
    const qint64 staleAfterMs = sinceLastFeedback.elapsed();
    qInfo("stale %lld ms after the last feedback frame", static_cast<long long>(staleAfterMs));
    // Not before 200 ms (less the host timer's slack). The upper bound only says "it came":
    // on a loaded 2-core CI machine the ptys and two event loops can add a second of delay;
    // the watchdog's exact timing is tested on simulated time (tst_simulateddevicelink::watchdog).
    QVERIFY2(staleAfterMs >= 180 && staleAfterMs < 1500, qPrintable(QString::number(staleAfterMs)));
    const double back = settledTheta(client);
    QVERIFY2(std::abs(back - 0.0396) < 2 * kTick, qPrintable(QString::number(back)));
    QCOMPARE(telemetrySince(client, client.frames.size() - 50).last().tau_ext, 0.0f);
}

void TestFirmwareHost::savedParamsSurviveRestart()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString state = dir.filePath(u"state.json"_s);
    PtyProgram servo(hatpicServoSim(), {});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    DeviceParams stiff = asDevice(DeviceParams{});
    stiff.K_max = 0.5;
    {
        PtyProgram host(hatpicFwHost(),
                        QStringList{u"--servo"_s, servo.path(), u"--state"_s, state, u"--quiet"_s} +
                            patientBus());
        QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
        V2Client client(host.path());
        QVERIFY(client.open());
        const quint8 set = client.send(v2::SetParams{stiff});
        const quint8 save = client.send(v2::SaveParams{});
        QTRY_VERIFY_WITH_TIMEOUT(client.ack(save).has_value(), kTimeoutMs);
        QCOMPARE(client.ack(set)->status, v2::AckStatus::Ok);
        QCOMPARE(client.ack(save)->status, v2::AckStatus::Ok);
        QVERIFY(QFileInfo::exists(state));
        QVERIFY(host.terminate());
        QCOMPARE(host.process().exitCode(), 0);
    }
    PtyProgram host(hatpicFwHost(),
                    QStringList{u"--servo"_s, servo.path(), u"--state"_s, state, u"--quiet"_s} +
                        patientBus());
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    V2Client client(host.path());
    QVERIFY(client.open());
    client.send(v2::GetParams{});
    QTRY_COMPARE_WITH_TIMEOUT(client.all<v2::Params>().size(), 1, kTimeoutMs);
    QCOMPARE(client.all<v2::Params>().first().params, stiff);

    // An unreadable state file: a warning, and the defaults.
    QVERIFY(host.terminate());
    QFile file(state);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write("{ not json");
    file.close();
    PtyProgram broken(hatpicFwHost(),
                      QStringList{u"--servo"_s, servo.path(), u"--state"_s, state, u"--quiet"_s} +
                          patientBus());
    QVERIFY2(!broken.path().isEmpty(), qPrintable(broken.errors()));
    QTRY_VERIFY_WITH_TIMEOUT(broken.errors().contains(u"ignored"_s), kTimeoutMs);
    V2Client again(broken.path());
    QVERIFY(again.open());
    again.send(v2::GetParams{});
    QTRY_COMPARE_WITH_TIMEOUT(again.all<v2::Params>().size(), 1, kTimeoutMs);
    QCOMPARE(again.all<v2::Params>().first().params, asDevice(DeviceParams{}));
}

void TestFirmwareHost::hatpicctlInfo()
{
    PtyProgram servo(hatpicServoSim(), {});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    PtyProgram host(hatpicFwHost(),
                    QStringList{u"--servo"_s, servo.path(), u"--quiet"_s} + patientBus());
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    QProcess ctl;
    ctl.start(QStringLiteral(HATPICCTL_PATH), {u"info"_s, u"--port"_s, host.path()});
    QVERIFY(ctl.waitForFinished(10000));
    const QString out = QString::fromUtf8(ctl.readAllStandardOutput());
    QVERIFY2(ctl.exitCode() == 0, qPrintable(QString::fromUtf8(ctl.readAllStandardError())));
    QVERIFY2(out.contains(u"hatpic-fw-host"_s) && out.contains(u"0x46574831"_s), qPrintable(out));
    QVERIFY2(out.contains(u"1000 Hz"_s), qPrintable(out));
}

void TestFirmwareHost::faultsAreInjectedAndCounted()
{
    PtyProgram servo(hatpicServoSim(), {});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    PtyProgram host(hatpicFwHost(),
                    QStringList{u"--servo"_s, servo.path(), u"--quiet"_s, u"--faults"_s,
                                u"drop=0.05,corrupt=0.02,dup=0.02,hdrop=0.2"_s, u"--seed"_s,
                                u"3"_s} +
                        patientBus());
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    // A lost SET_PARAMS (or its lost ACK) is retried: the push succeeds all the same. The
    // push is six wire steps (parameters, effects, passivity, each read back), each of four
    // tries; on a loaded machine all four tries of one step can miss, which is the right
    // answer and not the one under test, so the (idempotent) push may be run again.
    QProcess set;
    QString setErrors;
    for (int attempt = 0; attempt < 3; ++attempt) {
        set.start(QStringLiteral(HATPICCTL_PATH),
                  {u"set"_s, u"--port"_s, host.path(), u"--set"_s, u"K_max=0.5"_s});
        QVERIFY(set.waitForFinished(15000));
        setErrors = QString::fromUtf8(set.readAllStandardError());
        if (set.exitCode() == 0 || !setErrors.contains(u"did not answer"_s))
            break;
    }
    QVERIFY2(set.exitCode() == 0, qPrintable(setErrors));
    // With a fifth of the host's frames dropped and 7 % of the device's lost or corrupt, all
    // four tries of the stream's GET_PARAMS can fail (about 1 run in 200, more on a loaded
    // machine): that is the right answer, not the one under test, so it may try again.
    QProcess stream;
    QString stats;
    for (int attempt = 0; attempt < 3; ++attempt) {
        stream.start(QStringLiteral(HATPICCTL_PATH),
                     {u"stream"_s, u"--port"_s, host.path(), u"--duration"_s, u"2"_s});
        QVERIFY(stream.waitForFinished(10000));
        stats = QString::fromUtf8(stream.readAllStandardError());
        if (stream.exitCode() != 3 || !stats.contains(u"did not answer"_s))
            break;
    }
    QVERIFY2(stream.exitCode() == 0, qPrintable(stats));
    const QRegularExpression frames(u"(\\d+) missing by seq, (\\d+) received twice"_s);
    const QRegularExpressionMatch m = frames.match(stats);
    QVERIFY2(m.hasMatch() && m.captured(1).toInt() > 20 && m.captured(2).toInt() > 5,
             qPrintable(stats));
    QVERIFY2(!stats.contains(u"decoder drops 0 "_s), qPrintable(stats));

    QVERIFY(host.terminate());
    QCOMPARE(host.process().exitCode(), 0);
    const QString summary = host.errors();
    QVERIFY2(summary.contains(u"hatpic-fw-host: faults drop=0.05,corrupt=0.02,dup=0.02,"
                              u"hdrop=0.2, seed 3:"_s),
             qPrintable(summary));
    const QRegularExpression hostDrops(u"injected host→device: frames=\\d+ dropped=(\\d+)"_s);
    const QRegularExpressionMatch d = hostDrops.match(summary);
    QVERIFY2(d.hasMatch() && d.captured(1).toInt() > 0, qPrintable(summary));
}

void TestFirmwareHost::sigtermDisablesTorque()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(u"hatpic"_s);
    PtyProgram servo(hatpicServoSim(), {});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    PtyProgram host(hatpicFwHost(),
                    QStringList{u"--servo"_s, servo.path(), u"--link"_s, link, u"--quiet"_s} +
                        patientBus());
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    QCOMPARE(QFileInfo(link).symLinkTarget(), host.path());
    QVERIFY(!servo.errors().contains(u"torque off"_s));

    QVERIFY(host.terminate());
    QCOMPARE(host.process().exitStatus(), QProcess::NormalExit);
    QCOMPARE(host.process().exitCode(), 0);
    QVERIFY(!QFileInfo(link).isSymLink());
    QTRY_VERIFY_WITH_TIMEOUT(servo.errors().contains(u"torque off"_s), kTimeoutMs);

    // Ask the servo itself: READ 1 byte at the torque enable register (40).
    QSerialPort bus(servo.path());
    QVERIFY(bus.open(QIODevice::ReadWrite));
    const QByteArray read = QByteArray::fromHex("ffff0104022801cf");
    bus.write(read);
    QByteArray reply;
    QTRY_VERIFY_WITH_TIMEOUT((reply += bus.readAll()).size() >= 7, kTimeoutMs);
    QCOMPARE(reply.left(7).toHex(), QByteArray("ffff01030000fb")); // error 0, value 0
}

void TestFirmwareHost::everyEndingSignalDisablesTorque_data()
{
    QTest::addColumn<int>("signal");
    QTest::addColumn<bool>("crash"); //!< ends as the signal would (after the emergency stop)
    // Faults the event loop cannot wait for: an emergency stop, then the signal's own end.
    QTest::newRow("SIGSEGV") << int(SIGSEGV) << true;
    QTest::newRow("SIGABRT") << int(SIGABRT) << true;
    QTest::newRow("SIGBUS") << int(SIGBUS) << true;
    // Signals that can wait: the orderly stop, then exit 128 + the signal.
    QTest::newRow("SIGHUP") << int(SIGHUP) << false;
    QTest::newRow("SIGQUIT") << int(SIGQUIT) << false;
    QTest::newRow("SIGXCPU") << int(SIGXCPU) << false;
    QTest::newRow("SIGUSR2") << int(SIGUSR2) << false;
}

void TestFirmwareHost::everyEndingSignalDisablesTorque()
{
    QFETCH(int, signal);
    QFETCH(bool, crash);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(u"hatpic"_s);
    PtyProgram servo(hatpicServoSim(), {});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    // No core file from the faults sent on purpose.
    PtyProgram host(u"/bin/sh"_s,
                    QStringList{u"-c"_s, u"ulimit -c 0; exec \"$0\" \"$@\""_s, hatpicFwHost(),
                                u"--servo"_s, servo.path(), u"--link"_s, link, u"--quiet"_s} +
                        patientBus());
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    QCOMPARE(QFileInfo(link).symLinkTarget(), host.path());
    QVERIFY(!servo.errors().contains(u"torque off"_s));

    QCOMPARE(::kill(pid_t(host.process().processId()), signal), 0);
    QVERIFY(host.process().waitForFinished(kTimeoutMs));
    if (crash) {
        QCOMPARE(host.process().exitStatus(), QProcess::CrashExit);
    } else {
        QCOMPARE(host.process().exitStatus(), QProcess::NormalExit);
        QCOMPARE(host.process().exitCode(), 128 + signal);
    }
    QVERIFY(!QFileInfo(link).isSymLink());
    QTRY_VERIFY_WITH_TIMEOUT(servo.errors().contains(u"torque off"_s), kTimeoutMs);
}

void TestFirmwareHost::silentServoFails()
{
    PseudoTerminal nobody; // a "serial port" with no servo behind it
    QCOMPARE(nobody.open(), QString());
    QProcess host;
    host.start(hatpicFwHost(), {u"--servo"_s, nobody.slavePath()});
    QVERIFY(host.waitForFinished(kTimeoutMs));
    QCOMPARE(host.exitCode(), 1);
    QVERIFY(host.readAllStandardOutput().isEmpty());
    const QString error = QString::fromUtf8(host.readAllStandardError());
    QVERIFY2(error.contains(u"does not answer"_s), qPrintable(error));
}

namespace {

//! Write system calls `pid` has made so far (/proc/PID/io's syscw); -1 when unknown.
qint64 writeCalls(qint64 pid)
{
    QFile io(u"/proc/%1/io"_s.arg(pid));
    if (!io.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : io.readAll().split('\n')) {
        if (line.startsWith("syscw:"))
            return line.mid(6).trimmed().toLongLong();
    }
    return -1;
}

} // namespace

// hatpic-servo-sim stopped while hatpic-fw-host (default 5 ms reply timeout) sends its first
// start-up ping, continued once that ping has timed out: the start-up is tried again and the
// program comes up (issue 27: one unanswered ping ended it).
void TestFirmwareHost::servoAnsweringLateAtStartIsWaitedFor()
{
    PtyProgram servo(hatpicServoSim(), {});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    const auto servoPid = pid_t(servo.process().processId());
    QCOMPARE(::kill(servoPid, SIGSTOP), 0);
    PtyProgram host(hatpicFwHost(), {u"--servo"_s, servo.path(), u"--quiet"_s});
    QVERIFY(host.process().waitForStarted(kTimeoutMs));
    const qint64 hostPid = host.process().processId();
    // Its first write is the ping (nothing is printed before the servo is up).
    const qint64 before = writeCalls(hostPid);
    QElapsedTimer waited;
    waited.start();
    while (writeCalls(hostPid) <= std::max<qint64>(before, 0) &&
           host.process().state() == QProcess::Running && waited.elapsed() < kTimeoutMs)
        QTest::qWait(1);
    QTest::qWait(10); // twice the reply timeout: the first ping went unanswered
    QCOMPARE(::kill(servoPid, SIGCONT), 0);
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    QVERIFY2(!host.errors().contains(u"does not answer"_s), qPrintable(host.errors()));
}

// Something answers on the bus, but not as a servo: told apart from silence (issue 21).
void TestFirmwareHost::wronglyAnsweringServoFails()
{
    PseudoTerminal bus;
    QCOMPARE(bus.open(), QString());
    // Every request gets a status packet for id 1 with a bad checksum (0x00, not 0xfc).
    QSocketNotifier requests(bus.master(), QSocketNotifier::Read);
    connect(&requests, &QSocketNotifier::activated, this, [&bus] {
        char buffer[64];
        if (::read(bus.master(), buffer, sizeof buffer) > 0) {
            static const char reply[] = {'\xff', '\xff', '\x01', '\x02', '\x00', '\x00'};
            if (::write(bus.master(), reply, sizeof reply) != sizeof reply)
                qWarning("the reply was not written");
        }
    });
    QProcess host;
    host.start(hatpicFwHost(), {u"--servo"_s, bus.slavePath(), u"--servo-timeout"_s, u"100"_s});
    QTRY_VERIFY_WITH_TIMEOUT(host.state() == QProcess::NotRunning, kTimeoutMs);
    QCOMPARE(host.exitCode(), 1);
    const QString error = QString::fromUtf8(host.readAllStandardError()).trimmed();
    QVERIFY2(error.contains(u"answers at 1000000 baud, but not with valid status packets"_s) &&
                 !error.contains(u"does not answer"_s) && !error.contains(u'\n'),
             qPrintable(error));
}

// A servo that stops answering mid-experiment: after 100 bus errors the device turns its
// torque off (a LOG, and the flag on every frame); hatpicctl shows the LOG line and fails the
// experiment with the reason instead of printing figures (issue 21).
void TestFirmwareHost::experimentFailsWhenTheTorqueGoesOff()
{
    PtyProgram servo(hatpicServoSim(), {});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    PtyProgram host(hatpicFwHost(), {u"--servo"_s, servo.path(), u"--quiet"_s});
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    QProcess ctl;
    ctl.start(QStringLiteral(HATPICCTL_PATH),
              {u"experiment"_s, u"spectrum"_s, u"--port"_s, host.path(), u"--duration"_s, u"10"_s});
    QVERIFY(ctl.waitForStarted());
    QByteArray err;
    QTRY_VERIFY_WITH_TIMEOUT((err += ctl.readAllStandardError()).contains("keep hands off"),
                             kTimeoutMs);
    const auto servoPid = pid_t(servo.process().processId());
    QCOMPARE(::kill(servoPid, SIGSTOP), 0); // the bus goes silent
    const bool ended = ctl.waitForFinished(kTimeoutMs);
    ::kill(servoPid, SIGCONT);
    QVERIFY(ended);
    err += ctl.readAllStandardError();
    QCOMPARE(ctl.exitCode(), 3);
    QVERIFY(ctl.readAllStandardOutput().isEmpty()); // no figures
    QVERIFY2(
        err.contains("hatpicctl: device: servo bus: 100 consecutive errors, torque disabled\n"),
        err.constData());
    QVERIFY2(err.contains("hatpicctl: The device has turned its torque off"), err.constData());
}

void TestFirmwareHost::badOptions_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("says");
    QTest::newRow("fw-host without --servo") << hatpicFwHost() << QStringList{} << u"--servo"_s;
    QTest::newRow("fw-host rate 0")
        << hatpicFwHost() << QStringList{u"--servo"_s, u"x"_s, u"--rate"_s, u"0"_s}
        << u"control rate"_s;
    // Below 10 Hz a cycle's τ_ext would stay in force past the 200 ms feedback watchdog.
    QTest::newRow("fw-host rate 2")
        << hatpicFwHost() << QStringList{u"--servo"_s, u"x"_s, u"--rate"_s, u"2"_s}
        << u"from 10 to 20000 (a period of at most half the 200 ms feedback watchdog)"_s;
    QTest::newRow("fw-host id 254")
        << hatpicFwHost() << QStringList{u"--servo"_s, u"x"_s, u"--servo-id"_s, u"254"_s}
        << u"servo id"_s;
    QTest::newRow("fw-host timeout")
        << hatpicFwHost() << QStringList{u"--servo"_s, u"x"_s, u"--servo-timeout"_s, u"0"_s}
        << u"timeout"_s;
    QTest::newRow("fw-host unknown") << hatpicFwHost() << QStringList{u"--bogus"_s} << u"bogus"_s;
    QTest::newRow("fw-host faults")
        << hatpicFwHost() << QStringList{u"--servo"_s, u"x"_s, u"--faults"_s, u"drop=2"_s}
        << u"drop is a probability from 0 to 1, got \"2\""_s;
    QTest::newRow("servo-sim hand")
        << hatpicServoSim() << QStringList{u"--hand"_s, u"push"_s} << u"push"_s;
    QTest::newRow("servo-sim center")
        << hatpicServoSim() << QStringList{u"--center-tick"_s, u"4096"_s} << u"center tick"_s;
    // A folder as the state file is refused before anything opens it, as hatpic-sim does
    // (a pipe would block open()).
    static QTemporaryDir dir;
    QTest::newRow("fw-host state is a folder")
        << hatpicFwHost() << QStringList{u"--servo"_s, u"x"_s, u"--state"_s, dir.path()}
        << u"not a regular file"_s;
}

void TestFirmwareHost::badOptions()
{
    QFETCH(QString, program);
    QFETCH(QStringList, arguments);
    QFETCH(QString, says);
    QProcess process;
    process.start(program, arguments);
    QVERIFY(process.waitForFinished(kTimeoutMs));
    QCOMPARE(process.exitCode(), 4);
    QVERIFY(process.readAllStandardOutput().isEmpty());
    const QString error = QString::fromUtf8(process.readAllStandardError()).trimmed();
    QVERIFY2(error.contains(says) && !error.contains(u'\n'), qPrintable(error));
}

QTEST_GUILESS_MAIN(TestFirmwareHost)
#include "tst_firmwarehost.moc"
