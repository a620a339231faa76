// hatpic-fw-host's --state FILE end to end, over real ptys with hatpic-servo-sim and hatpicctl:
// a profile given as the state file keeps what SAVE_PARAMS does not own; a save that cannot be
// written fails with its reason (a LOG frame) instead of killing the program, also past the
// file-size limit; start-up warns about a folder SAVE_PARAMS cannot write.
#include "fwhosttest.h"
#include "profile/profile.h"
#include "testfiles.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

constexpr int kTimeoutMs = 5000;

//! hatpicctl ARGUMENTS; its exit code, stderr on failure in `error`.
int hatpicctl(const QStringList &arguments, QString &error)
{
    QProcess ctl;
    ctl.start(QStringLiteral(HATPICCTL_PATH), arguments);
    if (!ctl.waitForFinished(10000))
        return -1;
    error = QString::fromUtf8(ctl.readAllStandardError());
    return ctl.exitStatus() == QProcess::NormalExit ? ctl.exitCode() : -2;
}

//! The text of every LOG frame the client received, one a line.
QString logs(const V2Client &client)
{
    QStringList lines;
    for (const v2::Log &log : client.all<v2::Log>())
        lines.append(v2::toQString(log.text));
    return lines.join(u'\n');
}

} // namespace

class TestFirmwareHostState : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void profileKeepsWhatSaveDoesNotOwn();
    void fileSizeLimitFailsTheSaveNotTheProgram();
    void saveFailureSaysWhy();
};

void TestFirmwareHostState::profileKeepsWhatSaveDoesNotOwn()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString file = dir.filePath(u"knob.json"_s);
    Profile knob;
    knob.name = u"My knob"_s;
    knob.notes = u"Tuned for the crane demo."_s;
    knob.device.K_max = 0.3;
    knob.host.v_max = 0.5;
    knob.bridge.topics.wrench = "/crane/wrench";
    QCOMPARE(writeProfile(knob, file), QString());
    const QByteArray before = readAll(file);

    PtyProgram servo(hatpicServoSim(), {});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    PtyProgram host(hatpicFwHost(),
                    QStringList{u"--servo"_s, servo.path(), u"--state"_s, file, u"--quiet"_s} +
                        patientBus());
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    QString error;
    // A save that changes nothing leaves the profile as it was, to the byte.
    QVERIFY2(hatpicctl({u"save"_s, u"--port"_s, host.path()}, error) == 0, qPrintable(error));
    QCOMPARE(readAll(file), before);

    // A changed parameter changes that parameter only.
    QVERIFY2(hatpicctl({u"set"_s, u"--port"_s, host.path(), u"--set"_s, u"K_max=0.35"_s}, error) ==
                 0,
             qPrintable(error));
    QVERIFY2(hatpicctl({u"save"_s, u"--port"_s, host.path()}, error) == 0, qPrintable(error));
    const ProfileReadResult read = readProfile(file);
    QVERIFY2(read.ok(), qPrintable(read.errors.join(u"; ")));
    Profile expected = knob;
    expected.device.K_max = 0.35; // the float's shortest decimal, as `get --json` writes it
    QCOMPARE(*read.profile, expected);
    // A good profile: no warning at start.
    QVERIFY2(!host.errors().contains(u"State file"_s) && !host.errors().contains(u"SAVE_PARAMS"_s),
             qPrintable(host.errors()));
}

void TestFirmwareHostState::fileSizeLimitFailsTheSaveNotTheProgram()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString state = dir.filePath(u"state.json"_s);
    const QString link = dir.filePath(u"hatpic"_s);
    PtyProgram servo(hatpicServoSim(), {});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    // ulimit -f 0: any write to a file passes the limit (SIGXFSZ kills by default).
    PtyProgram host(u"/bin/sh"_s,
                    QStringList{u"-c"_s, u"ulimit -f 0; exec \"$0\" \"$@\""_s, hatpicFwHost(),
                                u"--servo"_s, servo.path(), u"--state"_s, state, u"--link"_s, link,
                                u"--quiet"_s} +
                        patientBus());
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    V2Client client(link);
    QVERIFY2(client.open(), qPrintable(client.errorString()));
    const quint8 save = client.send(v2::SaveParams{});
    QTRY_VERIFY_WITH_TIMEOUT(client.ack(save).has_value(), kTimeoutMs);
    QCOMPARE(client.ack(save)->status, v2::AckStatus::StorageError);
    QTRY_VERIFY_WITH_TIMEOUT(logs(client).contains(u"File too large"_s), kTimeoutMs);
    QVERIFY2(logs(client).startsWith(u"SAVE_PARAMS failed: cannot write profile \"" + state),
             qPrintable(logs(client)));
    QVERIFY(!QFileInfo::exists(state));

    // Still running, and it stops as always: torque off, link removed, exit 0.
    QCOMPARE(host.process().state(), QProcess::Running);
    QVERIFY(!servo.errors().contains(u"torque off"_s));
    QVERIFY(host.terminate());
    QCOMPARE(host.process().exitStatus(), QProcess::NormalExit);
    QCOMPARE(host.process().exitCode(), 0);
    QVERIFY(!QFileInfo(link).isSymLink());
    QTRY_VERIFY_WITH_TIMEOUT(servo.errors().contains(u"torque off"_s), kTimeoutMs);
}

void TestFirmwareHostState::saveFailureSaysWhy()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString state = dir.filePath(u"gone/state.json"_s);
    PtyProgram servo(hatpicServoSim(), {});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    PtyProgram host(hatpicFwHost(),
                    QStringList{u"--servo"_s, servo.path(), u"--state"_s, state, u"--quiet"_s} +
                        patientBus());
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    // Said at start, before anyone asks for a save.
    const QString warning = u"hatpic-fw-host: SAVE_PARAMS cannot write state file " + state +
                            u": its folder " + dir.filePath(u"gone"_s) + u" does not exist."_s;
    QTRY_VERIFY_WITH_TIMEOUT(host.errors().contains(warning), kTimeoutMs);

    V2Client client(host.path());
    QVERIFY2(client.open(), qPrintable(client.errorString()));
    const quint8 save = client.send(v2::SaveParams{});
    QTRY_VERIFY_WITH_TIMEOUT(client.ack(save).has_value(), kTimeoutMs);
    QCOMPARE(client.ack(save)->status, v2::AckStatus::StorageError);
    // The LOG comes before the ACK.
    QVERIFY2(logs(client).contains(u"No such file or directory"_s), qPrintable(logs(client)));
}

QTEST_GUILESS_MAIN(TestFirmwareHostState)
#include "tst_firmwarehoststate.moc"
