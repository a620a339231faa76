// Presets are read from the installed presets folder when it holds them, else from the copy
// compiled in; an unknown name has no file.
#include "profile/profile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace hatpic;

class TestPresetFiles : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void installedFolderFirst();
    void searchesBesideTheProgram();
};

void TestPresetFiles::installedFolderFirst()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QStringList dirs{dir.path(), QStringLiteral(":/presets")};
    // Nothing installed: the compiled-in copy.
    QCOMPARE(presetFile(QStringLiteral("Soft"), dirs), QStringLiteral(":/presets/soft.json"));
    QVERIFY(QFile::copy(QStringLiteral(":/presets/soft.json"),
                        dir.filePath(QStringLiteral("soft.json"))));
    QCOMPARE(presetFile(QStringLiteral("soft"), dirs), dir.filePath(QStringLiteral("soft.json")));
    QCOMPARE(presetFile(QStringLiteral("Notchy"), dirs), QStringLiteral(":/presets/notchy.json"));
    QVERIFY(presetFile(QStringLiteral("Nonexistent"), dirs).isEmpty());
    QVERIFY(
        presetFile(QStringLiteral("Soft"), {dir.path() + QStringLiteral("/missing")}).isEmpty());
}

void TestPresetFiles::searchesBesideTheProgram()
{
    const QStringList dirs = presetDirectories();
    QCOMPARE(dirs.size(), 2);
    // <prefix>/bin/program → <prefix>/share/hatpic-tuner/presets
    QCOMPARE(dirs[0], QDir::cleanPath(QCoreApplication::applicationDirPath() +
                                      QStringLiteral("/../share/hatpic-tuner/presets")));
    QCOMPARE(dirs[1], QStringLiteral(":/presets"));
    QVERIFY(preset(QStringLiteral("Default")).has_value());
}

QTEST_GUILESS_MAIN(TestPresetFiles)
#include "tst_presetfiles.moc"
