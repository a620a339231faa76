// hatpicctl and the passivity controller (docs/teleop.md § The passivity controller), run as a
// real process: get shows the block, set changes it alone or from a profile and refuses bad values
// before sending. (A legacy device is sent none: tst_hatpicctleffects' legacy case.)
#include "ctlprocess.h"
#include "model/passivity.h"
#include "profile/profile.h"

#include <QTemporaryDir>
#include <QTest>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

class TestHatpicCtlPassivity : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void getShowsTheBlock();
    void setOneField();
    void aProfilesBlockGoesWhole();
    void invalidValueIsRefusedBeforeSending();
    void unknownNameListsThePassivityFields();
};

void TestHatpicCtlPassivity::getShowsTheBlock()
{
    const Run get = runCtl({u"get"_s, u"--port"_s, u"sim"_s});
    QVERIFY2(get.code == 0, qPrintable(describe(get)));
    // Seven parameter lines, seven effect lines, then the passivity controller's two.
    const QList<QByteArray> lines = get.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 16);
    QVERIFY2(lines[14].startsWith("pc_damping_max  0.7 "), lines[14].constData());
    QVERIFY2(lines[15].startsWith("pc_reserve_max  0.15 "), lines[15].constData());
    QVERIFY(lines[14].contains("N·m·s/rad"));
    // --json carries every block the device has, defaults included (issue 35: get --json >
    // profile.json lost the effects and passivity blocks, leaving them to another version's
    // defaults).
    const Run json = runCtl({u"get"_s, u"--port"_s, u"sim"_s, u"--json"_s});
    QVERIFY2(json.code == 0, qPrintable(describe(json)));
    QVERIFY2(json.out.contains("\"passivity\": {"), json.out.constData());
    QVERIFY2(json.out.contains("\"effects\": {"), json.out.constData());
    QVERIFY2(json.out.contains("\"pc_reserve_max\": 0.15"), json.out.constData());
    QVERIFY2(json.out.contains("\"detent_strength\""), json.out.constData());
    const ProfileReadResult read = parseProfile(json.out);
    QVERIFY2(read.ok(), qPrintable(read.errors.join(u'\n')));
    QVERIFY(read.warnings.isEmpty());
    QVERIFY(sameOnWire(read.profile->passivity, PassivityParams{}));
}

void TestHatpicCtlPassivity::setOneField()
{
    const Run set = runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--set"_s, u"pc_damping_max=0"_s});
    QVERIFY2(set.code == 0, qPrintable(describe(set)));
    QVERIFY2(set.err.contains("The device accepted the passivity settings."), set.err.constData());
    // Only the passivity block was pushed: no parameters, no effects.
    QVERIFY(!set.err.contains("accepted the parameters"));
    QVERIFY(!set.err.contains("accepted the effects"));
    QVERIFY2(set.out.contains("\npc_damping_max  0 "), set.out.constData());
    QVERIFY2(set.out.contains("\npc_reserve_max  0.15 "), set.out.constData()); // unchanged
    const Run json = runCtl(
        {u"set"_s, u"--port"_s, u"sim"_s, u"--set"_s, u"pc_reserve_max=0.05"_s, u"--json"_s});
    QVERIFY2(json.code == 0, qPrintable(describe(json)));
    const ProfileReadResult read = parseProfile(json.out);
    QVERIFY2(read.ok(), qPrintable(read.errors.join(u'\n')));
    QCOMPARE(read.profile->passivity.pc_reserve_max, 0.05); // the float as its shortest decimal
    QCOMPARE(read.profile->passivity.pc_damping_max, 0.7);  // only the named field changed
}

void TestHatpicCtlPassivity::aProfilesBlockGoesWhole()
{
    QTemporaryDir dir;
    Profile p;
    p.name = u"off"_s;
    p.passivity = PassivityParams{.pc_damping_max = 0.25, .pc_reserve_max = 0.125};
    const QString path = dir.filePath(u"pc.json"_s);
    QCOMPARE(writeProfile(p, path), QString());
    const Run run = runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--profile"_s, path, u"--json"_s});
    QVERIFY2(run.code == 0, qPrintable(describe(run)));
    QVERIFY(run.err.contains("The device accepted the parameters."));
    QVERIFY(run.err.contains("The device accepted the passivity settings."));
    const ProfileReadResult back = parseProfile(run.out);
    QVERIFY(back.ok());
    QVERIFY(back.profile->passivity == p.passivity);
}

void TestHatpicCtlPassivity::invalidValueIsRefusedBeforeSending()
{
    const Run run = runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--set"_s, u"pc_damping_max=2"_s,
                            u"--set"_s, u"K_max=0.5"_s});
    QCOMPARE(run.code, 4);
    QVERIFY2(run.err.contains("The passivity settings are not valid; nothing was sent:"),
             run.err.constData());
    QVERIFY2(run.err.contains("pc_damping_max") && run.err.contains("got 2"), run.err.constData());
    QVERIFY(run.out.isEmpty());
}

void TestHatpicCtlPassivity::unknownNameListsThePassivityFields()
{
    const Run run = runCtl({u"set"_s, u"--port"_s, u"sim"_s, u"--set"_s, u"pc_damping=1"_s});
    QCOMPARE(run.code, 4);
    QVERIFY2(run.err.contains("and the passivity controller's pc_damping_max, pc_reserve_max"),
             run.err.constData());
}

QTEST_GUILESS_MAIN(TestHatpicCtlPassivity)
#include "tst_hatpicctlpassivity.moc"
