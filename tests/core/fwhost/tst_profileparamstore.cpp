// ProfileParamStore on real files: the --state FILE of hatpic-fw-host and hatpic-sim. SAVE_PARAMS
// owns the device block and the effects and nothing else; a file it cannot rewrite whole is
// left alone; a failure says why, with the system's own words.
#include "fwhost/profileparamstore.h"
#include "profile/profile.h"
#include "testfiles.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace hatpic;
using namespace Qt::StringLiterals;
using hatpic::test::readAll;

namespace {

constexpr double kTauLimit = 0.44; //!< the device's [N·m]

//! A profile a user made: every part SAVE_PARAMS does not own differs from the defaults.
Profile userProfile()
{
    Profile p;
    p.name = u"My knob"_s;
    p.notes = u"Tuned for the crane demo."_s;
    p.device.K_min = 0.15;
    p.device.K_max = 0.3;
    p.device.theta0 = 0.1;
    p.host.v_max = 0.5;
    p.host.mode = ReferenceMode::Rotation;
    p.host.tau_limit = 0.4;
    p.bridge.feedback.gain = 0.2;
    p.bridge.topics.wrench = "/crane/wrench";
    p.effects.detent_strength = 0.05;
    p.effects.detent_range = 1.0;
    return p;
}

//! The blocks as the device holds them after loading `p` (f32, ±π moved inside).
fw::StoredSettings asDevice(const Profile &p)
{
    return {roundedToFloat(p.device), roundedForWire(p.effects, kTauLimit),
            roundedForWire(p.passivity)};
}

} // namespace

class TestProfileParamStore : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void newFileNamesItsOwner();
    void unchangedSaveLeavesTheProfileAsItWas();
    void saveChangesOnlyTheDeviceAndEffects();
    void fileItCannotRewriteWholeIsLeftAlone_data();
    void fileItCannotRewriteWholeIsLeftAlone();
    void failureSaysWhy();
    void saveProblemAtStart();
    void savedNumbersAreTheFloatsShortestDecimals();
    void effectsAboveTheFilesTauLimitAreSaved();
    void saveThatWouldNotReadBackIsRefused();
};

void TestProfileParamStore::newFileNamesItsOwner()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"state.json"_s);
    ProfileParamStore store(path, u"hatpic-fw-host"_s, kTauLimit);
    QCOMPARE(store.saveProblem(), QString());
    fw::StoredSettings settings;
    settings.params.K_max = 0.5;
    QVERIFY(store.save(settings));
    QVERIFY(store.failure().empty());
    const ProfileReadResult read = readProfile(path);
    QVERIFY2(read.ok(), qPrintable(read.errors.join(u"; ")));
    QCOMPARE(read.profile->name, u"hatpic-fw-host state"_s);
    QCOMPARE(read.profile->notes, u"Parameters saved by hatpic-fw-host (SAVE_PARAMS)."_s);
    QCOMPARE(read.profile->device, settings.params);
    QCOMPARE(read.profile->host.tau_limit, kTauLimit);
}

void TestProfileParamStore::unchangedSaveLeavesTheProfileAsItWas()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"knob.json"_s);
    QCOMPARE(writeProfile(userProfile(), path), QString());
    const QByteArray before = readAll(path);
    ProfileParamStore store(path, u"hatpic-fw-host"_s, kTauLimit);
    fw::StoredSettings loaded;
    QVERIFY(store.load(loaded));
    // The device holds f32: 0.15 is 0.15000000596… there, and stays 0.15 in the file.
    QVERIFY(store.save(asDevice(userProfile())));
    QCOMPARE(readAll(path), before);
}

void TestProfileParamStore::saveChangesOnlyTheDeviceAndEffects()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"knob.json"_s);
    QCOMPARE(writeProfile(userProfile(), path), QString());
    ProfileParamStore store(path, u"hatpic-sim"_s, kTauLimit);
    fw::StoredSettings settings = asDevice(userProfile());
    settings.params.K_max = double(0.35f);
    settings.effects.wall_stiffness = double(2.0f);
    QVERIFY(store.save(settings));

    const ProfileReadResult read = readProfile(path);
    QVERIFY2(read.ok(), qPrintable(read.errors.join(u"; ")));
    Profile expected = userProfile();
    expected.device.K_max = 0.35; // the float's shortest decimal, as `get --json` writes it
    expected.effects.wall_stiffness = 2.0;
    QCOMPARE(read.profile->name, expected.name);
    QCOMPARE(read.profile->notes, expected.notes);
    QCOMPARE(read.profile->host, expected.host);
    QCOMPARE(read.profile->bridge, expected.bridge);
    QCOMPARE(read.profile->device, expected.device);
    QCOMPARE(read.profile->effects, expected.effects);
}

void TestProfileParamStore::fileItCannotRewriteWholeIsLeftAlone_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("says");
    QTest::newRow("not JSON") << QByteArray("{ not json") << u"not a profile this program reads"_s;
    QTest::newRow("not a profile")
        << QByteArray(R"({"format": "something else", "version": 1})") << u"format"_s;
    QTest::newRow("a newer version")
        << QByteArray(R"({"format": "hatpic-profile", "version": 7, "device": {}})")
        << u"newer version"_s;
    QTest::newRow("a key this build does not know")
        << QByteArray(R"({"format": "hatpic-profile", "version": 1, "colour": "red",
            "device": {"D_adm": 0.01, "M_adm": 0.001, "K_min": 0.1, "K_max": 0.4,
                       "N": 0.1, "Q_dz": 0.02, "theta0": 0}})")
        << u"would drop what this program does not read (unknown key \"colour\""_s;
}

void TestProfileParamStore::fileItCannotRewriteWholeIsLeftAlone()
{
    QFETCH(QByteArray, text);
    QFETCH(QString, says);
    QTemporaryDir dir;
    const QString path = dir.filePath(u"other.json"_s);
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text);
    file.close();

    ProfileParamStore store(path, u"hatpic-fw-host"_s, kTauLimit);
    QVERIFY2(store.saveProblem().contains(u"will not overwrite state file " + path) &&
                 store.saveProblem().contains(says),
             qPrintable(store.saveProblem()));
    QVERIFY(!store.save(fw::StoredSettings{}));
    const QString failure = QString::fromUtf8(store.failure());
    QVERIFY2(failure.startsWith(u"not overwriting " + path) && failure.contains(says),
             qPrintable(failure));
    QCOMPARE(readAll(path), text);
}

void TestProfileParamStore::failureSaysWhy()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"missing/state.json"_s);
    ProfileParamStore store(path, u"hatpic-fw-host"_s, kTauLimit);
    QVERIFY(!store.save(fw::StoredSettings{}));
    const QString failure = QString::fromUtf8(store.failure());
    QVERIFY2(failure.contains(path) && failure.contains(u"No such file or directory"_s),
             qPrintable(failure));
    // A good save clears it.
    QVERIFY(QDir(dir.path()).mkdir(u"missing"_s));
    QVERIFY(store.save(fw::StoredSettings{}));
    QVERIFY(store.failure().empty());
}

void TestProfileParamStore::saveProblemAtStart()
{
    QTemporaryDir dir;
    const QString missing = dir.filePath(u"nowhere/state.json"_s);
    QCOMPARE(ProfileParamStore(missing, u"hatpic-sim"_s, kTauLimit).saveProblem(),
             u"SAVE_PARAMS cannot write state file " + missing + u": its folder " +
                 dir.filePath(u"nowhere"_s) + u" does not exist.");
    QCOMPARE(
        ProfileParamStore(dir.filePath(u"state.json"_s), u"hatpic-sim"_s, kTauLimit).saveProblem(),
        QString());
}

void TestProfileParamStore::savedNumbersAreTheFloatsShortestDecimals()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"knob.json"_s);
    QCOMPARE(writeProfile(userProfile(), path), QString());
    ProfileParamStore store(path, u"hatpic-sim"_s, kTauLimit);
    fw::StoredSettings settings = asDevice(userProfile());
    settings.params.K_max = double(0.45f); // 0.44999998807907104
    settings.effects.detent_range = double(1.1f);
    QVERIFY(store.save(settings));
    const QByteArray text = readAll(path);
    QVERIFY2(text.contains("\"K_max\": 0.45,") && text.contains("\"detent_range\": 1.1"),
             text.constData());
    QVERIFY2(!text.contains("0.449999") && !text.contains("1.100000"), text.constData());
    // And a new file likewise.
    const QString fresh = dir.filePath(u"new.json"_s);
    QVERIFY(ProfileParamStore(fresh, u"hatpic-sim"_s, kTauLimit).save(settings));
    QVERIFY2(readAll(fresh).contains("\"K_max\": 0.45,"), readAll(fresh).constData());
}

void TestProfileParamStore::effectsAboveTheFilesTauLimitAreSaved()
{
    // The file's own host.tau_limit (0.4) is below the device's (0.44), and the device holds a
    // detent stronger than the file's limit: the save keeps the device's effects and raises
    // the file's limit to the device's, so that the file reads back.
    QTemporaryDir dir;
    const QString path = dir.filePath(u"knob.json"_s);
    QCOMPARE(writeProfile(userProfile(), path), QString());
    ProfileParamStore store(path, u"hatpic-sim"_s, kTauLimit);
    fw::StoredSettings settings = asDevice(userProfile());
    settings.effects.detent_strength = double(0.42f);
    QVERIFY2(store.save(settings), store.failure().data());
    const ProfileReadResult read = readProfile(path);
    QVERIFY2(read.ok(), qPrintable(read.errors.join(u"; ")));
    QCOMPARE(read.profile->effects.detent_strength, 0.42);
    QCOMPARE(read.profile->host.tau_limit, kTauLimit);
    fw::StoredSettings loaded;
    QVERIFY(store.load(loaded));
    // Effects within the file's limit leave it as the user wrote it.
    settings.effects.detent_strength = double(0.25f);
    QCOMPARE(writeProfile(userProfile(), path), QString());
    QVERIFY(store.save(settings));
    QCOMPARE(readProfile(path).profile->host.tau_limit, 0.4);
}

void TestProfileParamStore::saveThatWouldNotReadBackIsRefused()
{
    // A profile just under the 1 MiB a profile may be (long notes); SAVE_PARAMS changes K_max
    // from 0.3 to 0.375, two characters more: the file would be just over the limit, which
    // load() (and every reader) refuses. The save is refused and the old file stays.
    QTemporaryDir dir;
    const QString path = dir.filePath(u"knob.json"_s);
    Profile profile = userProfile();
    profile.notes = QString();
    const qsizetype base = serializeProfile(profile).size();
    profile.notes = QString(kMaxProfileBytes - 1 - base, u'n');
    QCOMPARE(serializeProfile(profile).size(), kMaxProfileBytes - 1);
    QCOMPARE(writeProfile(profile, path), QString());
    const QByteArray before = readAll(path);

    ProfileParamStore store(path, u"hatpic-sim"_s, kTauLimit);
    fw::StoredSettings settings = asDevice(profile);
    settings.params.K_max = 0.375;
    QVERIFY(!store.save(settings));
    const QString failure = QString::fromUtf8(store.failure());
    QVERIFY2(failure.contains(path) && failure.contains(u"1048577 bytes"_s) &&
                 failure.contains(u"1 MiB"_s),
             qPrintable(failure));
    QCOMPARE(readAll(path), before);
    fw::StoredSettings loaded;
    QVERIFY2(store.load(loaded), qPrintable(store.warning()));
    QCOMPARE(loaded.params.K_max, 0.3);
}

QTEST_GUILESS_MAIN(TestProfileParamStore)
#include "tst_profileparamstore.moc"
