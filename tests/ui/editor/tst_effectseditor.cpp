// The editor's Effects section with real widgets, without a device: the fields with their
// units and ranges, edits on the shared undo stack, validation against tau_limit, the push and
// sync of the effect block next to the parameters, a rejection by the device, the passivity
// and servo-loop warnings, and the vibration test's own checks.
#include "editor/effectssection.h"
#include "editor/parametereditor.h"
#include "editor/parameterfield.h"
#include "editor/scientificspinbox.h"
#include "editorrig.h"
#include "model/paramtable.h"
#include "pushresult.h"

#include <QAction>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <numbers>

using namespace hatpic;
using hatpic::test::EditorRig;
using namespace Qt::StringLiterals;

namespace {

ScientificSpinBox *spin(const ParameterEditor &editor, const QString &key)
{
    return editor.field(key)->spinBox();
}

//! What the device holds after SET_EFFECTS: the block as it travels.
EffectParams onWire(const EffectParams &effects, double tauLimit = HostParams{}.tau_limit)
{
    EffectParams out = roundedForWire(effects, tauLimit);
    for (int i = 0; i < EffectParams::kFieldCount; ++i)
        out.setField(i, static_cast<float>(out.field(i)));
    return out;
}

DeviceParams asFloat(const DeviceParams &p)
{
    DeviceParams out;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        out.setField(i, static_cast<float>(p.field(i)));
    return out;
}

//! An editor connected to a device that renders effects, in sync with its defaults.
void connectWithEffects(ParameterEditor &editor)
{
    editor.setCanPush(true);
    editor.setEffectsAvailable(true, QString(), 1000);
    editor.setDeviceTuning({asFloat(editor.params()), onWire(editor.effects())});
}

//! The device's OUT_OF_RANGE for SET_EFFECTS of `sent`, naming wall_stiffness (field 5), after
//! `applied` (the parts acknowledged before it) and their read-back `received`.
Outcome wallStiffnessRejected(const DeviceTuning &sent = {}, const DeviceTuning &applied = {},
                              const DeviceTuning &received = {})
{
    return Outcome{
        request::Push{sent},
        outcome::Refused{{CommandKind::SetEffects, applied}, v2::AckStatus::OutOfRange, 5},
        received};
}

} // namespace

class TestEffectsEditor : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void fieldsShowUnitsAndDefaults();
    void editIsOneUndoStep();
    void strengthAboveTauLimitBlocksPush();
    void pushCarriesEffectsOnlyToADeviceThatRendersThem();
    void rejectionNamesTheEffectField();
    void refusedEffectsAfterAcceptedParametersSayWhatIsInForce();
    void warnings_data();
    void warnings();
    void anglesFollowTheDegreesSwitch();
    void vibrationTestChecksItsFields();
    void torqueLimitIsTheDevicesFloat();
    void frequencyBeyondHalfTheRateIsRefused();
    void sectionDoesNotWidenTheEditor();

private:
    QTemporaryDir m_settingsDir;
};

void TestEffectsEditor::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QCoreApplication::setOrganizationName(u"hatpic-tests"_s);
    QCoreApplication::setApplicationName(u"tst_effectseditor"_s);
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_settingsDir.path());
    QSettings().clear();
}

void TestEffectsEditor::fieldsShowUnitsAndDefaults()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    QCOMPARE(editor.effects(), EffectParams{});
    QVERIFY(editor.findChild<QGroupBox *>(u"group_effects"_s));
    const EffectParams defaults;
    for (int i = 0; i < EffectParams::kFieldCount; ++i) {
        const EffectFieldSpec &spec = kEffectFields[std::size_t(i)];
        const QString key = QString::fromLatin1(spec.name.data(), qsizetype(spec.name.size()));
        ParameterField *f = editor.field(key);
        QVERIFY2(f, qPrintable(key));
        QCOMPARE(f->value(), defaults.field(i));
        QCOMPARE(f->unitLabel()->text(), QString::fromUtf8(spec.unit.data()));
        QVERIFY2(f->problem().isEmpty(), qPrintable(key));
        // The spin box takes the table's range (tau_limit's maximum stands in for tau_limit).
        QCOMPARE(f->spec().minimum, spec.lower.value);
    }
    QCOMPARE(editor.field(u"wall_max"_s)->spec().maximum, std::numbers::pi);
    QCOMPARE(editor.field(u"detent_strength"_s)->spec().maximum, kHostFields[1].upper.value);
    // Not connected: the section says where the effects go.
    QVERIFY(!editor.effectsSection()->isAvailable());
    QVERIFY(editor.effectsSection()->warningText().isEmpty());
}

void TestEffectsEditor::editIsOneUndoStep()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    QSignalSpy edited(editor.model(), &TuningModel::editedChanged);
    spin(editor, u"detent_strength"_s)->setValue(0.05);
    spin(editor, u"detent_range"_s)->setValue(0.8);
    QCOMPARE(editor.undoStack()->count(), 2);
    QCOMPARE(edited.count(), 2);
    QCOMPARE(editor.effects().detent_strength, 0.05);
    QCOMPARE(editor.params(), DeviceParams{}); // the parameters are not touched

    editor.undoAction()->trigger();
    QCOMPARE(editor.effects().detent_range, EffectParams{}.detent_range);
    QCOMPARE(spin(editor, u"detent_range"_s)->value(), EffectParams{}.detent_range);
    editor.undoAction()->trigger();
    QCOMPARE(editor.effects(), EffectParams{});
    editor.redoAction()->trigger();
    QCOMPARE(editor.effects().detent_strength, 0.05);
    QCOMPARE(spin(editor, u"detent_strength"_s)->value(), 0.05);

    // A whole tuning is one step, and setParams keeps the effects as they are.
    Tuning t = editor.tuning();
    t.device.K_max = 0.8;
    t.effects.wall_stiffness = 1.5;
    editor.setTuning(t, u"load"_s);
    QCOMPARE(editor.tuning(), t);
    editor.setParams(DeviceParams{}, editor.hostParams(), u"params"_s);
    QCOMPARE(editor.effects(), t.effects);
    editor.undoAction()->trigger();
    editor.undoAction()->trigger();
    QCOMPARE(editor.effects().wall_stiffness, 0.0);
    QCOMPARE(editor.effects().detent_strength, 0.05);
}

void TestEffectsEditor::strengthAboveTauLimitBlocksPush()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    connectWithEffects(editor);
    spin(editor, u"detent_strength"_s)->setValue(0.5); // tau_limit is 0.44
    QVERIFY(!editor.isValid());
    QVERIFY(!editor.pushAction()->isEnabled());
    const QString rule = u"detent_strength: must be ≤ tau_limit (0.44), got 0.5"_s;
    QCOMPARE(editor.field(u"detent_strength"_s)->problem(), rule);
    QVERIFY(editor.problems().contains(rule));
    // The detents' bound moves with tau_limit, a field of another group.
    spin(editor, u"tau_limit"_s)->setValue(0.6);
    QVERIFY(editor.isValid());
    QVERIFY(editor.field(u"detent_strength"_s)->problem().isEmpty());
    spin(editor, u"tau_limit"_s)->setValue(0.44);
    QVERIFY(!editor.isValid());
}

void TestEffectsEditor::pushCarriesEffectsOnlyToADeviceThatRendersThem()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.setCanPush(true);
    editor.setDeviceTuning({asFloat(editor.params()), std::nullopt});
    QCOMPARE(editor.syncState(), SyncState::InSync); // no effects to keep in sync
    QSignalSpy pushes(editor.model(), &TuningModel::pushRequested);
    spin(editor, u"wall_stiffness"_s)->setValue(2.0);
    QCOMPARE(editor.syncState(), SyncState::InSync); // a v2 device without effects
    editor.pushAction()->trigger();
    QCOMPARE(pushes.size(), 1);
    const auto withoutEffects = pushes.takeFirst().at(0).value<DeviceTuning>();
    QCOMPARE(withoutEffects.params, std::optional(editor.params()));
    QVERIFY(!withoutEffects.effects);
    editor.model()->pushFinished(
        pushed({asFloat(editor.params()), std::nullopt}, {asFloat(editor.params()), std::nullopt}));
    QCOMPARE(editor.syncState(), SyncState::InSync);

    // Now a device that renders them, still at its defaults: the edited walls differ.
    editor.setEffectsAvailable(true, QString(), 1000);
    QCOMPARE(editor.syncState(), SyncState::NotRead);
    editor.setDeviceTuning({asFloat(editor.params()), onWire(EffectParams{})});
    QCOMPARE(editor.syncState(), SyncState::Edited);
    QVERIFY(editor.field(u"wall_stiffness"_s)->differsFromDevice());
    QVERIFY(!editor.field(u"wall_max"_s)->differsFromDevice()); // π travels as float(π)⁻
    editor.pushAction()->trigger();
    QCOMPARE(editor.syncState(), SyncState::Pushing);
    const auto sent = pushes.takeFirst().at(0).value<DeviceTuning>();
    QVERIFY(sent.effects);
    QCOMPARE(*sent.effects, editor.effects());
    QCOMPARE(sent.params, std::optional(editor.params()));
    // One result for both parts; its read-back of the effects is not what was sent.
    const DeviceTuning onTheWire{asFloat(editor.params()), onWire(editor.effects())};
    EffectParams readBack = onWire(editor.effects());
    readBack.wall_stiffness = 1.5; // a device that kept another value
    editor.model()->pushFinished(pushed(onTheWire, {asFloat(editor.params()), readBack}));
    QCOMPARE(editor.syncState(), SyncState::ReadbackDiffers);
    QVERIFY(editor.field(u"wall_stiffness"_s)->differsFromDevice());
    QCOMPARE(editor.deviceTuning().effects, std::optional(readBack));
    // Read again, the device holds what was sent.
    editor.setDeviceTuning(onTheWire);
    QCOMPARE(editor.syncState(), SyncState::InSync);
    QVERIFY(!editor.field(u"wall_stiffness"_s)->differsFromDevice());
    QVERIFY(!editor.revertAction()->isEnabled());

    // Pushed again and read back as sent: in sync straight from the push's result.
    spin(editor, u"wall_stiffness"_s)->setValue(3.0);
    QCOMPARE(editor.syncState(), SyncState::Edited);
    editor.pushAction()->trigger();
    QCOMPARE(pushes.size(), 1);
    const DeviceTuning again{asFloat(editor.params()), onWire(editor.effects())};
    editor.model()->pushFinished(pushed(again, again));
    QCOMPARE(editor.syncState(), SyncState::InSync);
    QVERIFY(!editor.field(u"wall_stiffness"_s)->differsFromDevice());
}

// Issue 27: SET_PARAMS accepted and read back, then SET_EFFECTS refused. The sync line says the
// parameters were applied, and the editor takes them as the device's: K_max no longer differs
// from the device, the refused effect still does.
void TestEffectsEditor::refusedEffectsAfterAcceptedParametersSayWhatIsInForce()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    connectWithEffects(editor);
    spin(editor, u"K_max"_s)->setValue(0.6);
    spin(editor, u"wall_stiffness"_s)->setValue(4.0);
    QVERIFY(editor.field(u"K_max"_s)->differsFromDevice());
    editor.pushAction()->trigger();
    // SET_PARAMS was acknowledged and read back before SET_EFFECTS was refused.
    const DeviceTuning readBack{asFloat(editor.params()), std::nullopt};
    editor.model()->pushFinished(wallStiffnessRejected(
        {asFloat(editor.params()), onWire(editor.effects())}, readBack, readBack));
    QCOMPARE(editor.syncState(), SyncState::Rejected);
    QCOMPARE(editor.syncText(),
             u"device rejected the effects: OUT_OF_RANGE (wall_stiffness); parameters applied"_s);
    QVERIFY(!editor.field(u"K_max"_s)->differsFromDevice());
    QVERIFY(editor.field(u"wall_stiffness"_s)->differsFromDevice());
}

void TestEffectsEditor::rejectionNamesTheEffectField()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    connectWithEffects(editor);
    spin(editor, u"wall_stiffness"_s)->setValue(4.0);
    editor.pushAction()->trigger();
    editor.model()->pushFinished(wallStiffnessRejected());
    QCOMPARE(editor.syncState(), SyncState::Rejected);
    QCOMPARE(editor.syncText(), u"device rejected the effects: OUT_OF_RANGE (wall_stiffness)"_s);
    QVERIFY(editor.field(u"wall_stiffness"_s)->problem().contains(u"refused"_s));
    QVERIFY(editor.field(u"K_max"_s)->problem().isEmpty());
    QCOMPARE(editor.effects().wall_stiffness, 4.0); // left for the user to fix
}

void TestEffectsEditor::warnings_data()
{
    QTest::addColumn<double>("wallStiffness");
    QTest::addColumn<double>("detentStrength");
    QTest::addColumn<QStringList>("expected"); // words of each warning, in order

    // Walls at ±0.5 rad; D_adm = 1e-4 kg·m², so the servo follows up to 1e-4·(2π·25)² = 2.47.
    QTest::newRow("quiet wall") << 2.0 << 0.0 << QStringList{};
    QTest::newRow("wall above the servo loop") << 5.0 << 0.0 << QStringList{u"bounce"_s};
    // 12·0.001/2 = 0.006 > b = 0.0049: not passive either.
    QTest::newRow("wall not passive")
        << 12.0 << 0.0 << QStringList{u"wall may chatter"_s, u"bounce"_s};
    // A = 0.05 every 0.2 rad: 1.57 N·m/rad, above K_max = 0.4 but below 2.47.
    QTest::newRow("detents stiffer than the notch")
        << 0.0 << 0.05 << QStringList{u"stiffer than the notch"_s};
    // A = 0.1: 3.14 N·m/rad > 2.47.
    QTest::newRow("detents above the servo loop")
        << 0.0 << 0.1 << QStringList{u"buzz"_s, u"stiffer than the notch"_s};
}

void TestEffectsEditor::warnings()
{
    QFETCH(double, wallStiffness);
    QFETCH(double, detentStrength);
    QFETCH(QStringList, expected);
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    Tuning t = editor.tuning();
    t.effects.wall_min = -0.5;
    t.effects.wall_max = 0.5;
    t.effects.wall_stiffness = wallStiffness;
    t.effects.detent_strength = detentStrength;
    t.effects.detent_spacing = 0.2;
    t.effects.detent_range = detentStrength > 0 ? 0.8 : 0.0;
    editor.setTuning(t, u"fx"_s);
    const QStringList shown =
        editor.effectsSection()->warningText().split(u'\n', Qt::SkipEmptyParts);
    QCOMPARE(shown.size(), expected.size());
    for (qsizetype i = 0; i < expected.size(); ++i)
        QVERIFY2(shown[i].contains(expected[i]), qPrintable(shown[i]));
    const auto *label = editor.effectsSection()->findChild<QLabel *>(u"label_effect_warnings"_s);
    QCOMPARE(label->isVisibleTo(&editor), !expected.isEmpty());
    // A heavier knob follows a stiffer wall: 4e-4·(2π·25)² = 9.87 N·m/rad.
    if (wallStiffness == 5.0) {
        t.device.D_adm = 4e-4;
        editor.setTuning(t, u"heavier"_s);
        QVERIFY(editor.effectsSection()->warningText().isEmpty());
    }
}

void TestEffectsEditor::anglesFollowTheDegreesSwitch()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    spin(editor, u"wall_max"_s)->setValue(0.5);
    editor.setAngleInDegrees(true);
    QCOMPARE(editor.effects().wall_max, 0.5); // SI inside
    QVERIFY(std::abs(spin(editor, u"wall_max"_s)->value() - 0.5 * 180 / std::numbers::pi) < 1e-3);
    QCOMPARE(editor.field(u"wall_stiffness"_s)->spinBox()->value(), 0.0); // not an angle
}

void TestEffectsEditor::vibrationTestChecksItsFields()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    EffectsSection *fx = editor.effectsSection();
    QCOMPARE(fx->vibration(), EffectsSection::kDefaultVibration);
    QVERIFY(!fx->vibrateButton()->isEnabled()); // no device
    QSignalSpy vibrate(&editor, &ParameterEditor::vibrateRequested);
    editor.setEffectsAvailable(true, QString(), 200); // a device at 200 Hz
    QVERIFY(fx->vibrateButton()->isEnabled());
    fx->setVibration({0.1, 150, 1}); // above 100 Hz, half its rate
    QVERIFY(!fx->vibrateButton()->isEnabled());
    QCOMPARE(fx->vibrationProblems(),
             QStringList{u"frequency: must be < half the control rate (100), got 150"_s});
    QVERIFY(fx->vibrationFields()[1]->problem().contains(u"half the control rate"_s));
    fx->setVibration({0.5, 50, 1}); // above tau_limit
    QVERIFY(!fx->vibrateButton()->isEnabled());
    fx->setVibration({0.1, 50, 1});
    fx->vibrateButton()->click();
    QCOMPARE(vibrate.size(), 1);
    QCOMPARE(vibrate.constFirst().at(0).value<Vibration>(), (Vibration{0.1, 50, 1}));
    fx->stopButton()->click();
    QCOMPARE(vibrate.at(1).at(0).value<Vibration>().amplitude, 0.0);
    // Typed values are remembered for the next start.
    fx->vibrationFields()[0]->spinBox()->setValue(0.07);
    EditorRig nextRig;
    ParameterEditor &next = nextRig.editor;
    QCOMPARE(next.effectsSection()->vibration().amplitude, 0.07);
}

// The editor compares with tau_limit by the one rule (issue 21): as the device's float32, so
// 0.44 is within a limit of 0.44f = 0.4399999976158142, and the next float above is not.
void TestEffectsEditor::torqueLimitIsTheDevicesFloat()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    connectWithEffects(editor);
    editor.setTauLimit(double(0.44f));
    spin(editor, u"detent_strength"_s)->setValue(0.44);
    QVERIFY2(editor.isValid(), qPrintable(editor.problems().join(u'\n')));
    EffectsSection *fx = editor.effectsSection();
    fx->setVibration({0.44, 50, 1});
    QVERIFY2(fx->vibrationProblems().isEmpty(), qPrintable(fx->vibrationProblems().join(u'\n')));
    QVERIFY(fx->vibrateButton()->isEnabled());
    fx->setVibration({double(std::nextafter(0.44f, 1.0f)), 50, 1});
    QVERIFY(!fx->vibrateButton()->isEnabled());
}

void TestEffectsEditor::frequencyBeyondHalfTheRateIsRefused()
{
    // Issue 21: 600 Hz typed on a 1 kHz device used to become 500 without a word (and 500
    // breaks f < 500 as well).
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.show();
    editor.setEffectsAvailable(true, QString(), 1000);
    EffectsSection *fx = editor.effectsSection();
    fx->setVibration(EffectsSection::kDefaultVibration);
    ParameterField *frequency = fx->vibrationFields()[1];
    ScientificSpinBox *box = frequency->spinBox();
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, u"600"_s);
    QTest::keyClick(box, Qt::Key_Return);
    QCOMPARE(fx->vibration().frequency, EffectsSection::kDefaultVibration.frequency);
    QCOMPARE(frequency->clampNote(), u"f: 600 is refused: f must be < 500 Hz; it stays 40 Hz"_s);
    QVERIFY(!editor.findChild<QLabel *>(u"error_vibrate_frequency"_s)->isHidden());
    QVERIFY(fx->vibrateButton()->isEnabled()); // the cue is still the valid one it was
    // A slower device: the rule follows its rate.
    editor.setEffectsAvailable(true, QString(), 200);
    box->selectAll();
    QTest::keyClicks(box, u"150"_s);
    QTest::keyClick(box, Qt::Key_Return);
    QCOMPARE(fx->vibration().frequency, EffectsSection::kDefaultVibration.frequency);
    QVERIFY2(frequency->clampNote().contains(u"f must be < 100 Hz"_s),
             qPrintable(frequency->clampNote()));
}

void TestEffectsEditor::sectionDoesNotWidenTheEditor()
{
    // The editor dock is narrow (about 420 px at 1400×900): the Effects group, its warnings
    // and its vibration test must fit in the width the parameter groups need anyway.
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    Tuning t = editor.tuning();
    t.effects.wall_min = -0.5;
    t.effects.wall_max = 0.5;
    t.effects.wall_stiffness = 12; // every wall warning
    editor.setTuning(t, u"fx"_s);
    editor.show();
    int widest = 0;
    const QGroupBox *effects = nullptr;
    for (const QGroupBox *g : editor.findChildren<QGroupBox *>()) {
        if (g->objectName() == u"group_effects")
            effects = g;
        else if (g->objectName() != u"derivedFiguresBox")
            widest = std::max(widest, g->minimumSizeHint().width());
    }
    QVERIFY(effects && widest > 0);
    for (const QLabel *w : editor.findChildren<QLabel *>())
        qDebug() << w->objectName() << w->text().left(40) << w->minimumSizeHint() << w->sizeHint()
                 << w->minimumWidth();
    QString wide;
    for (const QWidget *w : effects->findChildren<QWidget *>()) {
        if (w->minimumSizeHint().width() > widest)
            wide += u" %1(%2)"_s.arg(w->objectName()).arg(w->minimumSizeHint().width());
    }
    QVERIFY2(
        effects->minimumSizeHint().width() <= widest,
        qPrintable(u"%1 > %2:%3"_s.arg(effects->minimumSizeHint().width()).arg(widest).arg(wide)));
}

QTEST_MAIN(TestEffectsEditor)
#include "tst_effectseditor.moc"
