// ProfileController: save/open round trip, refused files change nothing, the modified marker,
// A/B slots, presets and recent files. Settings go to a temporary directory.
#include "editor/parametereditor.h"
#include "editor/parameterfield.h"
#include "editor/scientificspinbox.h"
#include "editorrig.h"
#include "profile/profile.h"
#include "profiles/profilecontroller.h"
#include "testfiles.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QMenu>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

using namespace hatpic;
using hatpic::test::EditorRig;
using namespace Qt::StringLiterals;
using hatpic::test::readAll;
using hatpic::test::writeFile;

namespace {

void setValue(ParameterEditor &editor, const QString &key, double value)
{
    editor.field(key)->spinBox()->setValue(value);
}

QList<QAction *> fileActions(QMenu *menu)
{
    QList<QAction *> out;
    for (QAction *a : menu->actions()) {
        if (!a->data().toString().isEmpty())
            out << a;
    }
    return out;
}

} // namespace

class TestProfileController : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void saveOpenRoundTrip();
    void bridgeSettingsSavedAndLoaded();
    void refusedFileChangesNothing_data();
    void refusedFileChangesNothing();
    void invalidSetIsNotSaved();
    void modifiedMarkerInTitle();
    void abSwitch();
    void abSwitchUndo();
    void effectsTravelWithTheProfile();
    void presetsMenuLoadsPreset();
    void recentFiles();
    void maybeSaveAsks_data();
    void maybeSaveAsks();
    void quitPromptNamesABridgeSetting();
    void enterInThePromptOverwritesNothing();

private:
    QTemporaryDir m_settingsDir;
    std::unique_ptr<QTemporaryDir> m_dir;
};

void TestProfileController::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QCoreApplication::setOrganizationName(u"hatpic-tests"_s);
    QCoreApplication::setApplicationName(u"tst_profilecontroller"_s);
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_settingsDir.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
}

void TestProfileController::init()
{
    QSettings().clear();
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
}

void TestProfileController::saveOpenRoundTrip()
{
    const QString path = m_dir->filePath(u"mytuning.json"_s);
    DeviceParams saved;
    {
        EditorRig editorRig;
        ParameterEditor &editor = editorRig.editor;
        ProfileController controller(editor.model(), editor.undoStack(), nullptr);
        setValue(editor, u"K_max"_s, 0.55);
        setValue(editor, u"D_adm"_s, 3.3e-5);
        DeviceParams d = editor.params();
        d.theta0 = 0.123456789012345; // more digits than any spin box shows
        HostParams h = editor.hostParams();
        h.mode = ReferenceMode::Rotation;
        h.v_max = 2.5;
        editor.setParams(d, h, u"set"_s);
        QVERIFY(controller.isModified());
        QString error;
        QVERIFY2(controller.saveTo(path, &error), qPrintable(error));
        QVERIFY(error.isEmpty());
        QVERIFY(!controller.isModified());
        QCOMPARE(controller.profileName(), u"mytuning"_s); // untitled takes the file's name
        QCOMPARE(controller.filePath(), path);
        saved = editor.params();
    }
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    QString error;
    QVERIFY2(controller.openFile(path, &error), qPrintable(error));
    QCOMPARE(editor.params(), saved); // identical doubles
    QCOMPARE(editor.params().theta0, 0.123456789012345);
    QCOMPARE(editor.hostParams().mode, ReferenceMode::Rotation);
    QCOMPARE(editor.hostParams().v_max, 2.5);
    QCOMPARE(controller.profileName(), u"mytuning"_s);
    QVERIFY(!controller.isModified());
    QCOMPARE(editor.undoStack()->count(), 1); // opening is one undo step
}

// The Bridge panel's settings go into the profile's host.bridge: Save writes them, the '*'
// counts them, Open and the A/B switch hand the profile's back.
void TestProfileController::bridgeSettingsSavedAndLoaded()
{
    const QString path = m_dir->filePath(u"robot.json"_s);
    bridge::BridgeSettings s;
    s.feedback.gain = 0.3;
    s.topics.wrench = "/arm/wrench";
    {
        EditorRig editorRig;
        ParameterEditor &editor = editorRig.editor;
        ProfileController controller(editor.model(), editor.undoStack(), nullptr);
        QVERIFY(!controller.isModified());
        bridge::BridgeSettings withDomain = s;
        withDomain.domainId = 9; // no part of a profile, like the ROS version
        withDomain.rosVersion = 1;
        controller.setBridgeSettings(withDomain);
        QVERIFY(controller.isModified());
        QVERIFY(controller.windowTitle().contains(u'*'));
        QCOMPARE(controller.bridgeSettings().domainId, 0);
        QCOMPARE(controller.bridgeSettings().rosVersion, 2);
        QString error;
        QVERIFY2(controller.saveTo(path, &error), qPrintable(error));
        QVERIFY(!controller.isModified());
    }
    const auto read = readProfile(path);
    QVERIFY(read.ok());
    QVERIFY(read.profile->bridge == s);

    EditorRig editorRig;

    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    QSignalSpy loaded(&controller, &ProfileController::bridgeSettingsLoaded);
    QVERIFY(controller.openFile(path));
    QCOMPARE(loaded.size(), 1);
    QVERIFY(loaded.last().at(0).value<bridge::BridgeSettings>() == s);
    QVERIFY(controller.bridgeSettings() == s);
    QVERIFY(!controller.isModified());

    // Slot B starts as a copy; its own settings come back when it is active again.
    controller.toggleSlot();
    QCOMPARE(controller.activeSlot(), 1);
    bridge::BridgeSettings b = s;
    b.feedback.limit = 0.05;
    controller.setBridgeSettings(b);
    controller.toggleSlot();
    QVERIFY(loaded.last().at(0).value<bridge::BridgeSettings>() == s);
    controller.toggleSlot();
    QVERIFY(loaded.last().at(0).value<bridge::BridgeSettings>() == b);
    QVERIFY(controller.bridgeSettings() == b);
}

void TestProfileController::refusedFileChangesNothing_data()
{
    QTest::addColumn<QByteArray>("content");
    const QByteArray valid = serializeProfile(Profile{u"x"_s, {}, DeviceParams{}, HostParams{}});
    QByteArray crossField = valid;
    crossField.replace("\"K_min\": 0.15", "\"K_min\": 0.9");
    QByteArray twoErrors = crossField;
    twoErrors.replace("\"Q_dz\": 0.02", "\"Q_dz\": 0.5");
    QByteArray newer = valid;
    newer.replace("\"version\": 1", "\"version\": 7");
    QByteArray stringValue = valid;
    stringValue.replace("\"N\": 0.1", "\"N\": \"0.1\"");

    QTest::newRow("not JSON") << QByteArray("{ this is not json");
    QTest::newRow("K_min above K_max") << crossField;
    QTest::newRow("two violations, both reported") << twoErrors;
    QTest::newRow("newer version") << newer;
    QTest::newRow("number as string") << stringValue;
    QTest::newRow("empty file") << QByteArray();
}

void TestProfileController::refusedFileChangesNothing()
{
    QFETCH(QByteArray, content);
    const QString path = m_dir->filePath(u"bad.json"_s);
    QVERIFY(writeFile(path, content));
    const ProfileReadResult expected = readProfile(path);
    QVERIFY(!expected.ok());
    QVERIFY(!expected.errors.isEmpty());

    EditorRig editorRig;

    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    setValue(editor, u"K_max"_s, 0.7);
    const DeviceParams before = editor.params();
    const int undoCount = editor.undoStack()->count();
    const QString title = controller.windowTitle();
    QSignalSpy status(&controller, &ProfileController::statusMessage);

    QString error;
    QVERIFY(!controller.openFile(path, &error));
    for (const QString &message : expected.errors)
        QVERIFY2(error.contains(message), qPrintable(error)); // as the core says it, all of it
    QCOMPARE(editor.params(), before);
    QCOMPARE(editor.undoStack()->count(), undoCount);
    QCOMPARE(controller.windowTitle(), title);
    QVERIFY(controller.filePath().isEmpty());
    QCOMPARE(readAll(path), content); // the file is untouched
    QVERIFY(controller.recentFiles().isEmpty());
    QCOMPARE(status.count(), 1);

    QVERIFY(!controller.openFile(m_dir->filePath(u"missing.json"_s), &error));
    QVERIFY(!error.isEmpty());
    QCOMPARE(editor.params(), before);
}

void TestProfileController::invalidSetIsNotSaved()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    setValue(editor, u"K_min"_s, 0.9); // above K_max
    const QString path = m_dir->filePath(u"invalid.json"_s);
    QString error;
    QVERIFY(!controller.saveTo(path, &error));
    QVERIFY2(error.contains(u"K_min: must be ≤ K_max"_s), qPrintable(error));
    QVERIFY(!QFile::exists(path));
    QVERIFY(controller.isModified());
}

void TestProfileController::modifiedMarkerInTitle()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    QSignalSpy titles(&controller, &ProfileController::titleChanged);
    QCOMPARE(controller.windowTitle(), u"Untitled [A] — HATPIC Tuner"_s);

    setValue(editor, u"N"_s, 0.2);
    QCOMPARE(controller.windowTitle(), u"Untitled* [A] — HATPIC Tuner"_s);
    QCOMPARE(titles.count(), 1);
    QCOMPARE(titles.last().at(0).toString(), controller.windowTitle());

    // Undoing back to the saved values clears the marker.
    editor.undoStack()->undo();
    QCOMPARE(controller.windowTitle(), u"Untitled [A] — HATPIC Tuner"_s);
    QCOMPARE(titles.count(), 2);

    setValue(editor, u"N"_s, 0.25);
    QVERIFY(controller.saveTo(m_dir->filePath(u"Wide.json"_s)));
    QCOMPARE(controller.windowTitle(), u"Wide [A] — HATPIC Tuner"_s);
    setValue(editor, u"N"_s, 0.3);
    QCOMPARE(controller.windowTitle(), u"Wide* [A] — HATPIC Tuner"_s);

    // Issue 27: slot B, a copy of A, said "B" twice ("Wide (B) [B]"). The slot is said once.
    controller.toggleSlot();
    QCOMPARE(controller.windowTitle(), u"Wide (copy) [B] — HATPIC Tuner"_s);
}

void TestProfileController::abSwitch()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    QVERIFY(controller.loadPreset(u"Soft"_s));
    const DeviceParams soft = preset(u"Soft"_s)->device;
    QCOMPARE(controller.abToggleAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_B));
    QSignalSpy slotSpy(&controller, &ProfileController::activeSlotChanged);

    controller.abToggleAction()->trigger();
    QCOMPARE(controller.activeSlot(), 1);
    QCOMPARE(slotSpy.count(), 1);
    QCOMPARE(editor.params(), soft); // B starts as a copy of A
    QVERIFY(controller.windowTitle().contains(u"[B]"_s));
    QVERIFY(!controller.isModified());

    setValue(editor, u"K_max"_s, 0.9);
    QVERIFY(controller.isModified());
    QVERIFY(controller.windowTitle().contains(u"*"_s));

    controller.abToggleAction()->trigger();
    QCOMPARE(controller.activeSlot(), 0);
    QCOMPARE(editor.params(), soft);
    QVERIFY(controller.windowTitle().startsWith(u"Soft [A]"_s));
    QVERIFY(!controller.isModified());
    QVERIFY(controller.isModified(1)); // B keeps its unsaved edit

    controller.toggleSlot();
    QCOMPARE(editor.params().K_max, 0.9);

    // Opening a file goes into the active slot only.
    const QString path = m_dir->filePath(u"other.json"_s);
    Profile other{u"Other"_s, {}, DeviceParams{}, HostParams{}};
    other.device.K_max = 2.0;
    QVERIFY(writeProfile(other, path).isEmpty());
    QVERIFY(controller.openFile(path));
    QCOMPARE(controller.profileName(), u"Other"_s);
    controller.toggleSlot();
    QCOMPARE(controller.profileName(), u"Soft"_s);
    QCOMPARE(editor.params(), soft);
    controller.toggleSlot();
    QCOMPARE(editor.params().K_max, 2.0);
}

void TestProfileController::abSwitchUndo()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    setValue(editor, u"K_max"_s, 0.6);
    controller.toggleSlot();
    setValue(editor, u"K_max"_s, 0.8);
    QCOMPARE(controller.activeSlot(), 1);
    editor.undoStack()->undo(); // the B edit
    QCOMPARE(editor.params().K_max, 0.6);
    QCOMPARE(controller.activeSlot(), 1);
    editor.undoStack()->undo(); // the switch: back to A, never A's values in B
    QCOMPARE(controller.activeSlot(), 0);
    QCOMPARE(editor.params().K_max, 0.6);
    editor.undoStack()->redo();
    QCOMPARE(controller.activeSlot(), 1);
    editor.undoStack()->redo();
    QCOMPARE(editor.params().K_max, 0.8);
}

void TestProfileController::presetsMenuLoadsPreset()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    QStringList names;
    for (QAction *a : controller.presetsMenu()->actions())
        names << a->data().toString();
    QCOMPARE(names, presetNames());
    QVERIFY(names.contains(u"Notchy"_s));
    // Each says what it is in the menu itself (issue 27), its notes whole in the tooltip.
    for (QAction *a : controller.presetsMenu()->actions()) {
        QVERIFY2(a->text().startsWith(a->data().toString() + u" — "_s), qPrintable(a->text()));
        QVERIFY(!a->toolTip().isEmpty());
        if (a->data().toString() == u"Detents")
            QCOMPARE(a->text(), u"Detents — A knob that clicks"_s);
    }
    QCOMPARE(ProfileController::presetSummary(QString(100, u'x')).size(), 64);
    // The user guide names every preset the menu offers (it once lacked Detents and Walled).
    QFile guide(qEnvironmentVariable("HATPIC_SOURCE_DIR") + u"/docs/user-guide.md"_s);
    QVERIFY(guide.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(guide.readAll());
    const qsizetype at = text.indexOf(u"**Presets** ("_s);
    QVERIFY(at >= 0);
    const QString listed = text.mid(at, text.indexOf(u')', at) - at);
    for (const QString &name : names)
        QVERIFY2(listed.contains(name), qPrintable(name));

    for (QAction *a : controller.presetsMenu()->actions()) {
        if (a->data().toString() == u"Notchy")
            a->trigger();
    }
    const Profile notchy = *preset(u"Notchy"_s);
    QCOMPARE(editor.params(), notchy.device);
    QCOMPARE(editor.hostParams(), notchy.host);
    QCOMPARE(controller.profileName(), u"Notchy"_s);
    QVERIFY(controller.filePath().isEmpty());
    QVERIFY(!controller.isModified());
    QCOMPARE(controller.windowTitle(), u"Notchy [A] — HATPIC Tuner"_s);
    editor.undoStack()->undo();
    QCOMPARE(editor.params(), DeviceParams{});
    QVERIFY(controller.isModified()); // the values no longer match the preset
    QVERIFY(!controller.loadPreset(u"No such preset"_s));
}

void TestProfileController::recentFiles()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    QStringList paths;
    for (int i = 0; i < 10; ++i) {
        paths << m_dir->filePath(u"p%1.json"_s.arg(i));
        QVERIFY(controller.saveTo(paths.last()));
    }
    QStringList expected;
    for (int i = 9; i >= 10 - ProfileController::kMaxRecentFiles; --i)
        expected << paths[i];
    QCOMPARE(controller.recentFiles(), expected);
    const auto actions = fileActions(controller.recentMenu());
    QCOMPARE(actions.size(), ProfileController::kMaxRecentFiles);
    QCOMPARE(actions.first()->data().toString(), paths[9]);
    QVERIFY(actions.first()->text().contains(u"p9.json"_s));

    // Opening one moves it to the front; the list persists in QSettings.
    QVERIFY(controller.openFile(paths[4]));
    QCOMPARE(controller.recentFiles().first(), paths[4]);
    QCOMPARE(controller.recentFiles().size(), ProfileController::kMaxRecentFiles);
    ProfileController another(editor.model(), editor.undoStack(), nullptr);
    QCOMPARE(another.recentFiles(), controller.recentFiles());

    // The menu entry opens the file.
    setValue(editor, u"K_max"_s, 1.0);
    QVERIFY(controller.saveTo(paths[9]));
    QVERIFY(controller.openFile(paths[5]));
    QVERIFY(editor.params().K_max != 1.0);
    for (QAction *a : fileActions(controller.recentMenu())) {
        if (a->data().toString() == paths[9]) {
            a->trigger(); // rebuilds the menu: stop iterating its old actions
            break;
        }
    }
    QCOMPARE(editor.params().K_max, 1.0);

    // A file that vanished leaves the list when opening it fails.
    QVERIFY(QFile::remove(paths[8]));
    QString error;
    QVERIFY(!controller.openFile(paths[8], &error));
    QVERIFY(!controller.recentFiles().contains(paths[8]));
}

void TestProfileController::maybeSaveAsks_data()
{
    QTest::addColumn<bool>("modify");
    QTest::addColumn<int>("answer");
    QTest::addColumn<bool>("result");
    QTest::addColumn<int>("questions");
    QTest::addColumn<bool>("savedToFile");

    QTest::newRow("unmodified: no question")
        << false << int(QMessageBox::Cancel) << true << 0 << false;
    QTest::newRow("modified, cancel") << true << int(QMessageBox::Cancel) << false << 1 << false;
    QTest::newRow("modified, discard") << true << int(QMessageBox::Discard) << true << 1 << false;
    QTest::newRow("modified, save") << true << int(QMessageBox::Save) << true << 1 << true;
}

void TestProfileController::maybeSaveAsks()
{
    QFETCH(bool, modify);
    QFETCH(int, answer);
    QFETCH(bool, result);
    QFETCH(int, questions);
    QFETCH(bool, savedToFile);

    EditorRig editorRig;

    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    const QString path = m_dir->filePath(u"kept.json"_s);
    QVERIFY(controller.saveTo(path));
    QStringList asked;
    controller.setQuestion([&](const QString &text) {
        asked << text;
        return QMessageBox::StandardButton(answer);
    });
    if (modify)
        setValue(editor, u"Q_dz"_s, 0.05);
    QCOMPARE(controller.maybeSave(), result);
    QCOMPARE(asked.size(), questions);
    if (questions > 0) {
        QVERIFY(asked.first().contains(u"kept"_s));
        // It says what is unsaved (issue 27).
        QVERIFY2(asked.first().contains(u"unsaved changes: Q_dz."_s), qPrintable(asked.first()));
    }
    const ProfileReadResult onDisk = readProfile(path);
    QVERIFY(onDisk.ok());
    QCOMPARE(onDisk.profile->device.Q_dz == 0.05, savedToFile);
}

// Issue 27: a bridge setting changed, and the quit prompt asked to save the profile without
// saying why; it names it.
void TestProfileController::quitPromptNamesABridgeSetting()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    QVERIFY(controller.saveTo(m_dir->filePath(u"bridged.json"_s)));
    bridge::BridgeSettings settings = controller.bridgeSettings();
    settings.feedback.gain *= 2;
    controller.setBridgeSettings(settings);
    QCOMPARE(controller.unsavedParts(controller.activeSlot()), QStringList{u"a bridge setting"_s});
    setValue(editor, u"K_max"_s, 0.5);
    QStringList asked;
    controller.setQuestion([&](const QString &text) {
        asked << text;
        return QMessageBox::Cancel;
    });
    QVERIFY(!controller.maybeSave());
    QCOMPARE(asked.size(), 1);
    QVERIFY2(asked.first().contains(u"unsaved changes: K_max; a bridge setting. Save them?"_s),
             qPrintable(asked.first()));
}

void TestProfileController::enterInThePromptOverwritesNothing()
{
    // The real question, answered with Enter by someone who did not read it: the safe answer.
    QWidget window;
    window.show();
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), &window);
    const QString path = m_dir->filePath(u"kept.json"_s);
    QVERIFY(controller.saveTo(path));
    const QByteArray before = readAll(path);
    setValue(editor, u"Q_dz"_s, 0.05);
    QString shown;
    bool cancelIsDefault = false;
    QTimer::singleShot(0, this, [&] {
        QTRY_VERIFY(QApplication::activeModalWidget());
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        QVERIFY(box);
        shown = box->text();
        cancelIsDefault = static_cast<QAbstractButton *>(box->defaultButton()) ==
                          box->button(QMessageBox::Cancel);
        QTest::keyClick(box, Qt::Key_Return);
    });
    QVERIFY(!controller.maybeSave()); // cancelled: the window stays open
    QVERIFY(cancelIsDefault);
    QVERIFY2(shown.contains(u"unsaved changes"_s), qPrintable(shown));
    QCOMPARE(readAll(path), before);      // the file is as it was
    QCOMPARE(editor.params().Q_dz, 0.05); // and the edit is still there
    QVERIFY(controller.isModified());
}

void TestProfileController::effectsTravelWithTheProfile()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ProfileController controller(editor.model(), editor.undoStack(), nullptr);
    QVERIFY(controller.loadPreset(u"Detents"_s));
    const Profile detents = *preset(u"Detents"_s);
    QVERIFY(detents.effects.detent_strength > 0);
    QCOMPARE(editor.effects(), detents.effects);
    QVERIFY(!controller.isModified());

    // An effect edit marks the profile modified, and Save writes it.
    setValue(editor, u"detent_strength"_s, 0.03);
    QVERIFY(controller.isModified());
    const QString path = m_dir->filePath(u"clicks.json"_s);
    QVERIFY(controller.saveTo(path));
    QVERIFY(!controller.isModified());
    const ProfileReadResult read = readProfile(path);
    QVERIFY(read.ok());
    QCOMPARE(read.profile->effects.detent_strength, 0.03);
    QCOMPARE(read.profile->effects.detent_range, detents.effects.detent_range);

    // Each slot keeps its own effects; switching shows the other slot's.
    controller.toggleSlot();
    QCOMPARE(editor.effects().detent_strength, 0.03); // B starts as a copy of A
    setValue(editor, u"detent_strength"_s, 0.0);
    setValue(editor, u"wall_stiffness"_s, 2.0);
    controller.toggleSlot();
    QCOMPARE(editor.effects().detent_strength, 0.03);
    QCOMPARE(editor.effects().wall_stiffness, detents.effects.wall_stiffness);
    QCOMPARE(controller.slotProfile(1).effects.wall_stiffness, 2.0);
    // Undo past the switch goes back to B, with B's effects.
    editor.undoStack()->undo();
    QCOMPARE(controller.activeSlot(), 1);
    QCOMPARE(editor.effects().wall_stiffness, 2.0);

    // An invalid effect block is not saved, and the file stays as it was.
    const QByteArray before = readAll(path);
    controller.toggleSlot();
    setValue(editor, u"detent_strength"_s, 0.3);
    setValue(editor, u"tau_limit"_s, 0.2);
    QString error;
    QVERIFY(!controller.saveTo(path, &error));
    QVERIFY2(error.contains(u"detent_strength: must be ≤ tau_limit (0.2), got 0.3"_s),
             qPrintable(error));
    QCOMPARE(readAll(path), before);
}

QTEST_MAIN(TestProfileController)
#include "tst_profilecontroller.moc"
