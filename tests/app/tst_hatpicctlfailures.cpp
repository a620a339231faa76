// hatpicctl as a real process where a first hostile round found wrong words and wrong exit
// codes (issue 27): a push that failed part-way, experiments that cannot measure, foreign text
// on the terminal, two clients on one terminal, relative port paths, and the smaller ones.
// Devices are scripted on the master side of real pseudo-terminals, or hatpic-sim.
#include "ctlprocess.h"
#include "scripteddevice.h"

#include "profile/paramsjson.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <cmath>
#include <sys/resource.h>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

//! A v2 device that streams θ = 0 with τ_ext = 0 every `periodMs` while `on`:
//! it never renders the feedback it is sent.
struct StreamingDevice
{
    ScriptedDevice device;
    QTimer timer;
    quint32 tUs = 0;
    bool on = true;
    explicit StreamingDevice(int periodMs = 2)
    {
        QObject::connect(&timer, &QTimer::timeout, [this, periodMs] {
            tUs += quint32(periodMs) * 1000;
            if (on)
                device.sendTelemetry(0.0f, tUs);
        });
        timer.start(periodMs);
    }
};

} // namespace

class TestHatpicctlFailures : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    // 8: a partly applied push
    void refusedEffectsAfterAcceptedParameters();
    void unansweredEffectsAfterAcceptedParameters();
    void linkLostAfterAcceptedParameters();
    // 9: experiments that cannot measure
    void stepLevelsThatAreOneFloatAreRefusedBeforeSending();
    void deviceThatIgnoresTauExtFailsTheStep();
    void bodeWhoseDeviceStopsStreamingFails();
    // 11: foreign text
    void legacyDeviceTextIsEscapedAndRateLimited();
    void unknownKeysAreBoundedAndEscaped();
    // 12, 13: ports
    void secondClientOnAnAliasIsToldWhoHoldsThePort();
    void relativePortIsAPath();
    void deviceThatBootsAfterTheOpenIsFound_data();
    void deviceThatBootsAfterTheOpenIsFound();
    // 14: the smaller ones
    void slowStreamDoesNotSayTheDeviceDidNotStream();
    void streamIntoAClosedPipeExitsWithFour();
    void vibrateIsCheckedBeforeConnecting();
    void bodeOptionsAreRefusedByStep();
    void longIntegerIsOutOfRange();
    void recordingFailureIsToldOnce();
    void helpKeepsAGapAfterEveryName();
};

// The device takes SET_PARAMS (and reads it back), then refuses SET_EFFECTS.
void TestHatpicctlFailures::refusedEffectsAfterAcceptedParameters()
{
    ScriptedDevice device;
    QVERIFY(device.isValid());
    device.hello.capabilities = v2::kCapabilityEffects;
    device.answer = [&device](const v2::Frame &f) {
        if (const auto *set = std::get_if<v2::SetParams>(&f.message)) {
            device.params = set->params; // accepted: GET_PARAMS reads it back
            return false;
        }
        if (std::holds_alternative<v2::SetEffects>(f.message)) {
            device.send(v2::Ack{f.seq, v2::AckStatus::OutOfRange, 0});
            return true;
        }
        if (std::holds_alternative<v2::GetEffects>(f.message)) {
            device.send(v2::Effects{roundedForWire(EffectParams{}, 0.44)});
            return true;
        }
        return false;
    };
    const Run run = runCtlServing({u"set"_s, u"--port"_s, device.path(), u"--set"_s, u"K_max=0.6"_s,
                                   u"--set"_s, u"detent_strength=0.05"_s});
    QCOMPARE(run.code, 2);
    const QString err = QString::fromUtf8(run.err);
    QVERIFY2(err.contains(u"its effects are unchanged"_s), qPrintable(describe(run)));
    QVERIFY2(err.contains(u"It had accepted the parameters (SET_PARAMS, read back): those are in "
                          u"force."_s),
             qPrintable(describe(run)));
    // What is in force, as `get` shows it: the new K_max, the old effects.
    QVERIFY2(run.out.contains("K_max") && run.out.contains("0.6"), qPrintable(describe(run)));
    QVERIFY2(run.out.contains("detent_strength"), qPrintable(describe(run)));
}

void TestHatpicctlFailures::deviceThatBootsAfterTheOpenIsFound_data()
{
    QTest::addColumn<QString>("protocol");
    QTest::newRow("detecting") << u"auto"_s;
    QTest::newRow("forced v2") << u"v2"_s;
}

// An ESP32 resets when the port opens (DTR) and says nothing while it boots: detection keeps
// trying — listen, HELLO, again — for as long as --timeout, not one round of about a second.
void TestHatpicctlFailures::deviceThatBootsAfterTheOpenIsFound()
{
    QFETCH(QString, protocol);
    ScriptedDevice device;
    QVERIFY(device.isValid());
    QElapsedTimer sinceOpen;
    int ignored = 0;
    device.answer = [&](const v2::Frame &) {
        if (!sinceOpen.isValid())
            sinceOpen.start();
        if (sinceOpen.elapsed() >= 2500)
            return false;
        ++ignored; // still booting
        return true;
    };
    const Run run = runCtlServing(
        {u"info"_s, u"--port"_s, device.path(), u"--protocol"_s, protocol, u"--timeout"_s, u"8"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QVERIFY2(run.out.contains("scripted"), qPrintable(describe(run)));
    QVERIFY2(ignored >= 2, qPrintable(QString::number(ignored))); // more than one round's HELLOs
    QCOMPARE(device.hellosAnswered(), 1);
}

// SET_EFFECTS goes unanswered after SET_PARAMS was accepted.
void TestHatpicctlFailures::unansweredEffectsAfterAcceptedParameters()
{
    ScriptedDevice device;
    QVERIFY(device.isValid());
    device.hello.capabilities = v2::kCapabilityEffects;
    device.answer = [&device](const v2::Frame &f) {
        if (const auto *set = std::get_if<v2::SetParams>(&f.message)) {
            device.params = set->params;
            return false;
        }
        if (std::holds_alternative<v2::GetEffects>(f.message)) {
            device.send(v2::Effects{roundedForWire(EffectParams{}, 0.44)});
            return true;
        }
        return std::holds_alternative<v2::SetEffects>(f.message); // silence
    };
    const Run run = runCtlServing({u"set"_s, u"--port"_s, device.path(), u"--set"_s, u"K_max=0.6"_s,
                                   u"--set"_s, u"detent_strength=0.05"_s, u"--json"_s});
    QCOMPARE(run.code, 3);
    const QString err = QString::fromUtf8(run.err);
    QVERIFY2(err.contains(u"did not answer SET_EFFECTS"_s), qPrintable(describe(run)));
    QVERIFY2(err.contains(u"It had accepted the parameters (SET_PARAMS, read back)"_s),
             qPrintable(describe(run)));
    QVERIFY2(err.contains(u"Whether the effects changed is unknown"_s), qPrintable(describe(run)));
    // The parameters in force, and no effects: they are not known.
    QVERIFY2(run.out.contains("\"K_max\": 0.6"), qPrintable(describe(run)));
    QVERIFY2(!run.out.contains("detent_strength"), qPrintable(describe(run)));
}

// The device acknowledges SET_PARAMS and vanishes before its read-back: the host knows the
// parameters were taken, not what the device holds now.
void TestHatpicctlFailures::linkLostAfterAcceptedParameters()
{
    ScriptedDevice device;
    QVERIFY(device.isValid());
    bool acked = false;
    device.answer = [&](const v2::Frame &f) {
        if (std::holds_alternative<v2::SetParams>(f.message)) {
            device.send(v2::Ack{f.seq, v2::AckStatus::Ok, v2::kNoField});
            acked = true;
            return true;
        }
        // The ACK arrived (the host asks for the read-back): now the device is gone.
        if (acked && std::holds_alternative<v2::GetParams>(f.message)) {
            device.hangUp();
            return true;
        }
        return false;
    };
    const Run run =
        runCtlServing({u"set"_s, u"--port"_s, device.path(), u"--set"_s, u"K_max=0.6"_s});
    QVERIFY(acked);
    QVERIFY2(run.code == 3, qPrintable(describe(run)));
    const QString err = QString::fromUtf8(run.err);
    QVERIFY2(err.contains(u"It had accepted the parameters (SET_PARAMS, not read back): those "
                          u"were in force when the link went."_s),
             qPrintable(describe(run)));
    QVERIFY2(run.out.contains("K_max") && run.out.contains("0.6"), qPrintable(describe(run)));
}

// 0 and 1e-46 N·m are one float32: no step; refused before anything is sent (exit 4).
void TestHatpicctlFailures::stepLevelsThatAreOneFloatAreRefusedBeforeSending()
{
    const Run run = runCtl({u"experiment"_s, u"step"_s, u"--port"_s, u"sim"_s, u"--from"_s, u"0"_s,
                            u"--to"_s, u"1e-46"_s});
    QCOMPARE(run.code, 4);
    QVERIFY2(run.err.contains("one and the same 32-bit float"), qPrintable(describe(run)));
    QVERIFY(run.out.isEmpty());
    QVERIFY2(!run.err.contains("Running"), qPrintable(describe(run))); // nothing ran
}

// The device streams but renders no τ_ext: no figure, exit 3, the reason.
void TestHatpicctlFailures::deviceThatIgnoresTauExtFailsTheStep()
{
    StreamingDevice knob;
    QVERIFY(knob.device.isValid());
    const Run run = runCtlServing({u"experiment"_s, u"step"_s, u"--port"_s, knob.device.path(),
                                   u"--settle"_s, u"0.3"_s, u"--duration"_s, u"0.5"_s});
    QCOMPARE(run.code, 3);
    QVERIFY2(run.err.contains("No step appears in the device's"), qPrintable(describe(run)));
    QVERIFY2(run.out.isEmpty(), qPrintable(describe(run))); // no table of zeros
}

// The device stops streaming halfway (it still answers PING): the frequencies after that have
// no samples; the run fails with the reason instead of a table of dashes.
void TestHatpicctlFailures::bodeWhoseDeviceStopsStreamingFails()
{
    StreamingDevice knob;
    QVERIFY(knob.device.isValid());
    QTimer::singleShot(1800, [&knob] { knob.on = false; });
    const Run run =
        runCtlServing({u"experiment"_s, u"bode"_s, u"--port"_s, knob.device.path(), u"--settle"_s,
                       u"0.2"_s, u"--frequencies"_s, u"5,10,20"_s, u"--cycles"_s, u"2"_s,
                       u"--offset"_s, u"0.05"_s, u"--amplitude"_s, u"0.02"_s});
    QVERIFY2(run.code == 3, qPrintable(describe(run)));
    QVERIFY2(run.err.contains("Too few samples to measure"), qPrintable(describe(run)));
    QVERIFY2(run.out.isEmpty(), qPrintable(describe(run)));
}

// A legacy device that floods ESC sequences and BEL between its frames: escaped, and at most
// 20 lines a second reach the terminal, plus a summary of the rest.
void TestHatpicctlFailures::legacyDeviceTextIsEscapedAndRateLimited()
{
    ScriptedDevice port; // only its pseudo-terminal: this test writes legacy bytes itself
    QVERIFY(port.isValid());
    port.answer = [](const v2::Frame &) { return true; };
    QTimer flood;
    int sent = 0;
    QObject::connect(&flood, &QTimer::timeout, [&] {
        QByteArray bytes = "ia100b0c0d0o\r\n";
        for (int i = 0; i < 50; ++i, ++sent)
            bytes += "\x1b[2J\x1b]0;owned\x07 boot line\r\n";
        port.sendRaw(bytes);
    });
    flood.start(5);
    const Run run = runCtlServing(
        {u"stream"_s, u"--port"_s, port.path(), u"--protocol"_s, u"legacy"_s, u"--duration"_s,
         u"2"_s, u"--csv"_s, QDir::temp().filePath(u"hatpic-t27-legacy.csv"_s), u"--force"_s});
    flood.stop();
    QFile::remove(QDir::temp().filePath(u"hatpic-t27-legacy.csv"_s));
    QFile::remove(QDir::temp().filePath(u"hatpic-t27-legacy.json"_s));
    QVERIFY2(sent > 1000, qPrintable(QString::number(sent)));
    QVERIFY2(!run.err.contains('\x1b') && !run.err.contains('\x07'), qPrintable(describe(run)));
    QVERIFY2(run.err.contains("\\x1b[2J"), qPrintable(describe(run)));
    const qsizetype deviceLines = run.err.count("hatpicctl: device: ");
    QVERIFY2(deviceLines <= 4 * 21, qPrintable(QString::number(deviceLines)));
    QVERIFY2(run.err.contains("more lines from the device not shown"), qPrintable(describe(run)));
}

// 50 000 unknown keys: a bounded number of warnings and a count; keys with ESC escaped.
void TestHatpicctlFailures::unknownKeysAreBoundedAndEscaped()
{
    QTemporaryDir dir;
    QByteArray json = R"({"format": "hatpic-profile", "version": 1, "device": {)";
    json += "\"\x1b[2Jk\": 1";
    for (int i = 0; i < 50000; ++i)
        json += ", \"k" + QByteArray::number(i) + "\": 1";
    json += "}}";
    const QString path = dir.filePath(u"keys.json"_s);
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly) && file.write(json) == json.size());
    file.close();
    const Run run = runCtl({u"validate"_s, path});
    const qsizetype warnings = run.err.count("warning: ") + run.out.count("warning: ");
    QVERIFY2(warnings == kMaxUnknownKeysNamed + 1, qPrintable(describe(run)));
    QVERIFY2(run.err.contains("… and 49991 more unknown keys in \"device\" ignored") ||
                 run.out.contains("… and 49991 more unknown keys in \"device\" ignored"),
             qPrintable(describe(run)));
    QVERIFY2(!run.err.contains('\x1b') && !run.out.contains('\x1b'), qPrintable(describe(run)));
}

// One client streams through a symlink; a second asks through /dev/pts/N: "in use by another
// program" naming it, and the first one streams on to its end.
void TestHatpicctlFailures::secondClientOnAnAliasIsToldWhoHoldsThePort()
{
    ScriptedDevice device;
    QVERIFY(device.isValid());
    QTemporaryDir dir;
    const QString alias = dir.filePath(u"knob"_s);
    QVERIFY(QFile::link(device.path(), alias));
    QTimer telemetry;
    quint32 t = 0;
    QObject::connect(&telemetry, &QTimer::timeout, [&] { device.sendTelemetry(0, t += 5000); });
    telemetry.start(5);

    QProcess first;
    first.setProgram(QStringLiteral(HATPICCTL_PATH));
    first.setArguments({u"stream"_s, u"--port"_s, alias, u"--duration"_s, u"3"_s});
    first.start();
    QVERIFY(first.waitForStarted(10000));
    const qint64 firstPid = first.processId();
    QElapsedTimer clock;
    clock.start();
    while (first.bytesAvailable() < 200 && clock.elapsed() < 10000)
        QTest::qWait(10); // streaming: the port is open and locked
    const Run second = runCtlServing({u"info"_s, u"--port"_s, device.path()});
    while (first.state() != QProcess::NotRunning && clock.elapsed() < 30000)
        QTest::qWait(10);
    const QByteArray firstErr = first.readAllStandardError();
    QCOMPARE(second.code, 3);
    QVERIFY2(second.err.contains(QByteArray("is in use by another program (hatpicctl, PID " +
                                            QByteArray::number(firstPid))),
             qPrintable(describe(second)));
    QVERIFY2(!second.err.contains("Permission error"), qPrintable(describe(second)));
    QCOMPARE(first.exitStatus(), QProcess::NormalExit);
    QVERIFY2(first.exitCode() == 0, firstErr.constData());
}

// --port rel/k: the file rel/k under the working directory (a symlink to the terminal).
void TestHatpicctlFailures::relativePortIsAPath()
{
    ScriptedDevice device;
    QVERIFY(device.isValid());
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkdir(u"rel"_s));
    QVERIFY(QFile::link(device.path(), dir.filePath(u"rel/k"_s)));
    const QString before = QDir::currentPath();
    QVERIFY(QDir::setCurrent(dir.path()));
    const Run run = runCtlServing({u"info"_s, u"--port"_s, u"rel/k"_s});
    QDir::setCurrent(before);
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QVERIFY2(run.out.contains("rel/k"), qPrintable(describe(run)));
}

// --rate 1 --duration 0.5: a frame came at connecting; the words must not deny the stream.
void TestHatpicctlFailures::slowStreamDoesNotSayTheDeviceDidNotStream()
{
    QTemporaryDir dir;
    const Run run = runCtl({u"stream"_s, u"--port"_s, u"sim"_s, u"--rate"_s, u"1"_s,
                            u"--duration"_s, u"0.5"_s, u"--csv"_s, dir.filePath(u"r.csv"_s)});
    QVERIFY2(!run.err.contains("did not stream"), qPrintable(describe(run)));
    if (run.code != 0) {
        QCOMPARE(run.code, 3);
        QVERIFY2(run.err.contains("though the device streams"), qPrintable(describe(run)));
    }
}

// `hatpicctl stream | head -3`: exit 4 with a sentence, not death by SIGPIPE (141).
void TestHatpicctlFailures::streamIntoAClosedPipeExitsWithFour()
{
    QProcess ctl;
    QProcess head;
    ctl.setStandardOutputProcess(&head);
    head.setStandardOutputFile(QProcess::nullDevice());
    ctl.start(QStringLiteral(HATPICCTL_PATH),
              {u"stream"_s, u"--port"_s, u"sim"_s, u"--duration"_s, u"20"_s});
    head.start(u"head"_s, {u"-3"_s});
    QVERIFY(ctl.waitForStarted(10000) && head.waitForStarted(10000));
    QVERIFY(head.waitForFinished(20000));
    QVERIFY(ctl.waitForFinished(20000)); // well before its 20 s
    QCOMPARE(ctl.exitStatus(), QProcess::NormalExit);
    QCOMPARE(ctl.exitCode(), 4);
    QVERIFY2(ctl.readAllStandardError().contains("closed by its reader"), "no sentence");
}

// NaN, ranges and an amplitude that travels as 0 are refused before any port is opened: the
// port here does not exist, which would give exit 3.
void TestHatpicctlFailures::vibrateIsCheckedBeforeConnecting()
{
    const QString missing = QDir::temp().filePath(u"no-such-knob-27"_s);
    const QList<QStringList> cues = {{u"nan"_s, u"50"_s, u"1"_s},
                                     {u"0.1"_s, u"5000"_s, u"1"_s},
                                     {u"0.1"_s, u"50"_s, u"-1"_s},
                                     {u"1e-46"_s, u"50"_s, u"1"_s}};
    for (const QStringList &cue : cues) {
        const Run run = runCtl({u"vibrate"_s, u"--port"_s, missing, u"--amplitude"_s, cue[0],
                                u"--frequency"_s, cue[1], u"--duration"_s, cue[2]});
        QVERIFY2(run.code == 4, qPrintable(cue.join(u' ') + u"\n"_s + describe(run)));
        QVERIFY2(!run.err.contains("Cannot open"), qPrintable(describe(run)));
    }
    const Run tiny = runCtl({u"vibrate"_s, u"--port"_s, missing, u"--amplitude"_s, u"1e-46"_s,
                             u"--frequency"_s, u"50"_s, u"--duration"_s, u"1"_s});
    QVERIFY2(tiny.err.contains("stops the cue"), qPrintable(describe(tiny)));
}

void TestHatpicctlFailures::bodeOptionsAreRefusedByStep()
{
    for (const QStringList &extra : QList<QStringList>{{u"--frequencies"_s, u"1,2"_s},
                                                       {u"--cycles"_s, u"3"_s},
                                                       {u"--amplitude"_s, u"0.1"_s}}) {
        const Run run =
            runCtl(QStringList{u"experiment"_s, u"step"_s, u"--port"_s, u"sim"_s} + extra);
        QCOMPARE(run.code, 4);
        QVERIFY2(run.err.contains("is an option of 'bode', not of 'step'"),
                 qPrintable(describe(run)));
    }
    const Run run =
        runCtl({u"experiment"_s, u"bode"_s, u"--port"_s, u"sim"_s, u"--to"_s, u"0.1"_s});
    QCOMPARE(run.code, 4);
    QVERIFY2(run.err.contains("is an option of 'step'"), qPrintable(describe(run)));
}

void TestHatpicctlFailures::longIntegerIsOutOfRange()
{
    const Run run = runCtl(
        {u"experiment"_s, u"bode"_s, u"--port"_s, u"sim"_s, u"--cycles"_s, u"99999999999"_s});
    QCOMPARE(run.code, 4);
    QVERIFY2(run.err.contains("out of range"), qPrintable(describe(run)));
    QVERIFY2(!run.err.contains("--cycles must be"), qPrintable(describe(run)));
    const Run word =
        runCtl({u"experiment"_s, u"bode"_s, u"--port"_s, u"sim"_s, u"--cycles"_s, u"many"_s});
    QVERIFY2(word.err.contains("must be a whole number, got 'many'"), qPrintable(describe(word)));
}

// A recording that fails (a file-size limit) says "The recording stopped" once.
void TestHatpicctlFailures::recordingFailureIsToldOnce()
{
    QTemporaryDir dir;
    QProcess process;
    process.setProgram(QStringLiteral(HATPICCTL_PATH));
    process.setArguments({u"stream"_s, u"--port"_s, u"sim"_s, u"--duration"_s, u"5"_s, u"--csv"_s,
                          dir.filePath(u"r.csv"_s)});
    process.setChildProcessModifier([] {
        const rlimit limit{20000, 20000};
        ::setrlimit(RLIMIT_FSIZE, &limit);
    });
    process.start();
    QVERIFY(process.waitForFinished(30000));
    const QByteArray err = process.readAllStandardError();
    QCOMPARE(process.exitCode(), 4);
    QVERIFY2(err.count("recording stopped") + err.count("Recording stopped") == 1, err.constData());
}

void TestHatpicctlFailures::helpKeepsAGapAfterEveryName()
{
    const Run run = runCtl({u"--help"_s});
    QCOMPARE(run.code, 0);
    QVERIFY2(run.out.contains("  experiment  Measure"), run.out.constData());
    QVERIFY(!run.out.contains("experimentMeasure"));
}

QTEST_GUILESS_MAIN(TestHatpicctlFailures)
#include "tst_hatpicctlfailures.moc"
