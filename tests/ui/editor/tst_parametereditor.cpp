// ParameterEditor with real widgets: its fields. Defaults shown, validation at the fields,
// what cannot be typed (NaN, letters, beyond a bound) and the clamp's note, the reason for no
// push beside Push, derived figures and their warnings, degrees, host fields, steps for small
// values. Push, sync states, undo/redo, diff markers and live push: tst_parametereditorsync.
#include "editor/derivedfiguresview.h"
#include "editor/parametereditor.h"
#include "editor/parameterfield.h"
#include "editor/scientificspinbox.h"
#include "editorparts.h"
#include "editorrig.h"
#include "model/derived.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

class TestParameterEditor : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void defaultsShown();
    void invalidValueBlocksPush_data();
    void invalidValueBlocksPush();
    void nanCannotBeTyped();
    void outOfRangeTypingClampsVisibly_data();
    void outOfRangeTypingClampsVisibly();
    void lettersAreRefusedOutLoud();
    void exclusiveBoundRefusesTheEntry_data();
    void exclusiveBoundRefusesTheEntry();
    void clampNoteGoesWithRevertAndUndo();
    void reasonForNoPushSitsBesidePush();
    void derivedFiguresWarn_data();
    void derivedFiguresWarn();
    void warningsNeverCutTheFigures_data();
    void warningsNeverCutTheFigures();
    void degreesChangeOnlyTheDisplay();
    void hostFieldsEdit();
    void tauLimitFromDevice();
    void relativeStepsForSmallValues();
};

void TestParameterEditor::defaultsShown()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    const DeviceParams defaults;
    QCOMPARE(editor.params(), defaults);
    QCOMPARE(editor.hostParams(), HostParams{});
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        const QString key = QString::fromLatin1(deviceFieldName(i));
        QCOMPARE(spin(editor, key)->value(), defaults.field(i));
        QVERIFY2(editor.field(key)->problem().isEmpty(), qPrintable(key));
    }
    // 1e-4 must be readable, not "0.00" as with a two-decimal spin box.
    QCOMPARE(spin(editor, u"D_adm"_s)->text(), u"0.0001"_s);
    QCOMPARE(spin(editor, u"v_max"_s)->value(), HostParams{}.v_max);
    QCOMPARE(spin(editor, u"tau_limit"_s)->value(), HostParams{}.tau_limit);
    QVERIFY(editor.isValid());
    QCOMPARE(editor.syncState(), SyncState::NotConnected);
    QCOMPARE(editor.syncText(), u"not connected"_s);
    QVERIFY(!editor.pushAction()->isEnabled()); // nothing to push to
    QCOMPARE(editor.undoStack()->count(), 0);
    // D_adm is the inertia and M_adm the damping: the labels say so.
    QVERIFY(label(editor, u"label_D_adm"_s)->text().contains(u"inertia"_s));
    QVERIFY(label(editor, u"label_M_adm"_s)->text().contains(u"damping"_s));
    QCOMPARE(label(editor, u"unit_D_adm"_s)->text(), u"kg·m²"_s);
    QCOMPARE(label(editor, u"unit_M_adm"_s)->text(), u"N·m·s/rad"_s);
}

void TestParameterEditor::invalidValueBlocksPush_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("rule");

    QTest::newRow("K_min above K_max") << u"K_min"_s << 0.5 << u"K_min: must be ≤ K_max (0.4)"_s;
    QTest::newRow("K_max below K_min") << u"K_max"_s << 0.1 << u"K_min: must be ≤ K_max (0.1)"_s;
    QTest::newRow("Q_dz equal to N") << u"Q_dz"_s << 0.1 << u"Q_dz: must be < N (0.1)"_s;
    QTest::newRow("Q_dz above N") << u"Q_dz"_s << 0.3 << u"Q_dz: must be < N (0.1)"_s;
    QTest::newRow("N below Q_dz") << u"N"_s << 0.01 << u"Q_dz: must be < N (0.01)"_s;
    QTest::newRow("M_adm zero") << u"M_adm"_s << 0.0 << u"M_adm: must be > 0"_s;
    QTest::newRow("N zero") << u"N"_s << 0.0 << u"N: must be > 0"_s;
    QTest::newRow("v_max zero") << u"v_max"_s << 0.0 << u"v_max: must be > 0"_s;
    QTest::newRow("tau_limit zero") << u"tau_limit"_s << 0.0 << u"tau_limit: must be > 0"_s;
}

void TestParameterEditor::invalidValueBlocksPush()
{
    QFETCH(QString, key);
    QFETCH(double, value);
    QFETCH(QString, rule);
    // The field that owns the broken rule (cross-field rules belong to K_min and Q_dz).
    const QString owner = rule.section(u':', 0, 0);

    EditorRig editorRig;

    ParameterEditor &editor = editorRig.editor;
    editor.setCanPush(true);
    QVERIFY(editor.pushAction()->isEnabled());
    QSignalSpy validity(&editor, &ParameterEditor::validityChanged);

    spin(editor, key)->setValue(value);

    QVERIFY(!editor.isValid());
    QCOMPARE(validity.count(), 1);
    QCOMPARE(validity.at(0).at(0).toBool(), false);
    QVERIFY(!editor.pushAction()->isEnabled());
    QVERIFY2(editor.field(owner)->problem().contains(rule),
             qPrintable(editor.field(owner)->problem()));
    QLabel *message = label(editor, u"error_"_s + owner);
    QVERIFY(!message->isHidden());
    QVERIFY(message->text().contains(rule));
    QVERIFY(spin(editor, owner)->property("invalid").toBool());
    QVERIFY(spin(editor, owner)->toolTip().contains(rule));
    QVERIFY(editor.problems().join(u'\n').contains(rule));
    QVERIFY(!editor.derivedFiguresView()->isShowingSaturation());

    // Triggering the disabled action does not push.
    QSignalSpy pushes(editor.model(), &TuningModel::pushRequested);
    editor.pushAction()->trigger();
    QCOMPARE(pushes.count(), 0);

    editor.undoStack()->undo();
    QVERIFY(editor.isValid());
    QCOMPARE(validity.count(), 2);
    QVERIFY(editor.pushAction()->isEnabled());
    QVERIFY(message->isHidden());
    QVERIFY(!spin(editor, owner)->property("invalid").toBool());
}

void TestParameterEditor::nanCannotBeTyped()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ScientificSpinBox *box = spin(editor, u"K_max"_s);
    for (QString text : {u"nan"_s, u"inf"_s, u"1e999"_s, u"abc"_s}) {
        int pos = 0;
        QVERIFY2(box->validate(text, pos) != QValidator::Acceptable, qPrintable(text));
    }
    box->selectAll();
    QTest::keyClicks(box, u"nan"_s);
    QTest::keyClick(box, Qt::Key_Enter);
    QCOMPARE(editor.params().K_max, DeviceParams{}.K_max);
    QVERIFY(std::isfinite(editor.params().K_max));

    // Scientific input is accepted.
    box->selectAll();
    QTest::keyClicks(box, u"1.5e-1"_s);
    QTest::keyClick(box, Qt::Key_Enter);
    QCOMPARE(editor.params().K_max, 0.15);
}

void TestParameterEditor::outOfRangeTypingClampsVisibly_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("words");

    // N's maximum π/2 shows as 1.5708, just above it: once set N to 0 instead.
    QTest::newRow("N above π/2") << u"N"_s << u"1.6"_s << u"above the maximum 1.5708"_s;
    QTest::newRow("K_max above 50") << u"K_max"_s << u"60"_s << u"above the maximum 50"_s;
    QTest::newRow("K_min below 0") << u"K_min"_s << u"-1"_s << u"below the minimum 0"_s;
    QTest::newRow("Q_dz above π/2") << u"Q_dz"_s << u"2"_s << u"above the maximum"_s;
}

void TestParameterEditor::outOfRangeTypingClampsVisibly()
{
    QFETCH(QString, key);
    QFETCH(QString, typed);
    QFETCH(QString, words);

    EditorRig editorRig;

    ParameterEditor &editor = editorRig.editor;
    ScientificSpinBox *box = spin(editor, key);
    box->selectAll();
    QTest::keyClicks(box, typed);
    QTest::keyClick(box, Qt::Key_Enter);

    // The value is the nearest bound, never an unrelated one, and the field says so.
    const double bound = words.contains(u"above"_s) ? box->maximum() : box->minimum();
    QCOMPARE(editor.field(key)->value(), bound);
    const QString note = editor.field(key)->clampNote();
    QVERIFY2(note.contains(typed) && note.contains(words), qPrintable(note));
    QLabel *message = label(editor, u"error_"_s + key);
    QVERIFY(!message->isHidden());
    // A rule the bound breaks (Q_dz = π/2 is not < N) comes first (it blocks the push), the
    // note after it: the rule names the value held, the note what became of the text typed.
    const QString problem = editor.field(key)->problem();
    QCOMPARE(message->text(), problem.isEmpty() ? note : problem + u'\n' + note);

    // The next ordinary edit clears the note.
    box->selectAll();
    QTest::keyClicks(box, u"0.01"_s);
    QTest::keyClick(box, Qt::Key_Enter);
    QVERIFY(editor.field(key)->clampNote().isEmpty());
}

//! Types `text` into the field `key` and commits it with Enter, as a user does.
void typeInto(ParameterEditor &editor, const QString &key, const QString &text)
{
    ScientificSpinBox *box = spin(editor, key);
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
}

void TestParameterEditor::lettersAreRefusedOutLoud()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.show();
    ScientificSpinBox *box = spin(editor, u"K_max"_s);
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, u"4a.b5c"_s);
    // Every key typed is in the field: none is dropped unseen…
    QCOMPARE(box->findChild<QLineEdit *>()->text(), u"4a.b5c"_s);
    QTest::keyClick(box, Qt::Key_Return);
    // …and the entry, not a number, changes nothing and is said to be refused.
    QCOMPARE(editor.params().K_max, DeviceParams{}.K_max);
    QCOMPARE(box->text(), u"0.4"_s);
    QCOMPARE(editor.field(u"K_max"_s)->clampNote(),
             u"K_max: “4a.b5c” is not a number; it stays 0.4 N·m/rad"_s);
    QVERIFY(!label(editor, u"error_K_max"_s)->isHidden());
    QCOMPARE(editor.undoStack()->count(), 0);
    // A number typed afterwards is taken, and the note goes.
    typeInto(editor, u"K_max"_s, u"0.45"_s);
    QCOMPARE(editor.params().K_max, 0.45);
    QVERIFY(editor.field(u"K_max"_s)->clampNote().isEmpty());
}

void TestParameterEditor::exclusiveBoundRefusesTheEntry_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("note");
    // Bounds that are not valid values: the nearest bound would break the same rule.
    QTest::newRow("N below 0") << u"N"_s << u"-0.1"_s
                               << u"N: -0.1 is refused: N must be > 0 rad; it stays 0.1 rad"_s;
    QTest::newRow("M_adm below 0")
        << u"M_adm"_s << u"-1"_s
        << u"M_adm: -1 is refused: M_adm must be > 0 N·m·s/rad; it stays 0.01 N·m·s/rad"_s;
    QTest::newRow("tau_limit below 0")
        << u"tau_limit"_s << u"-0.5"_s
        << u"tau_limit: -0.5 is refused: tau_limit must be > 0 N·m; it stays 0.44 N·m"_s;
}

void TestParameterEditor::exclusiveBoundRefusesTheEntry()
{
    QFETCH(QString, key);
    QFETCH(QString, typed);
    QFETCH(QString, note);
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.show();
    const Tuning before = editor.tuning();
    typeInto(editor, key, typed);
    QVERIFY(editor.tuning() == before);
    QVERIFY(editor.isValid()); // no "got 0": a value nobody typed never enters the editor
    QCOMPARE(editor.field(key)->clampNote(), note);
    QCOMPARE(label(editor, u"error_"_s + key)->text(), note);
    QCOMPARE(editor.undoStack()->count(), 0);
}

void TestParameterEditor::clampNoteGoesWithRevertAndUndo()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.show();
    editor.setCanPush(true);
    DeviceParams device;
    device.K_max = 0.8f;
    editor.setDeviceTuning({device, std::nullopt});
    QLabel *message = label(editor, u"error_K_max"_s);

    typeInto(editor, u"K_max"_s, u"100"_s);
    QCOMPARE(editor.params().K_max, 50.0);
    QVERIFY(editor.field(u"K_max"_s)->clampNote().contains(u"set to 50"_s));
    editor.revertAction()->trigger();
    QCOMPARE(editor.params().K_max, 0.8);
    QVERIFY(editor.field(u"K_max"_s)->clampNote().isEmpty());
    QVERIFY(message->isHidden());

    typeInto(editor, u"K_max"_s, u"100"_s);
    QVERIFY(!message->isHidden());
    editor.undoStack()->undo();
    QCOMPARE(editor.params().K_max, 0.8);
    QVERIFY(message->isHidden());
}

void TestParameterEditor::reasonForNoPushSitsBesidePush()
{
    // A short panel: the broken rule's own field is far below the fold.
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.setCanPush(true);
    editor.resize(520, 420);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    QLabel *reason = label(editor, u"push_problem"_s);
    QVERIFY(reason);
    QVERIFY(reason->isHidden());
    HostParams host = editor.hostParams();
    host.tau_limit = 0.3; // below detent_strength…
    Tuning t = editor.tuning();
    t.host = host;
    t.effects.detent_strength = 0.35; // …which must stay within it
    editor.setTuning(t, u"tuning"_s);
    QVERIFY(!editor.pushAction()->isEnabled());
    QWidget *field = spin(editor, u"detent_strength"_s);
    auto *scroll = editor.findChild<QScrollArea *>(u"parameterScroll"_s);
    auto inSight = [&](QWidget *w) {
        const QRect r(w->mapTo(scroll->viewport(), QPoint(0, 0)), w->size());
        return scroll->viewport()->rect().contains(r);
    };
    QVERIFY(!inSight(field));
    // The reason is beside Push, above the scrolling fields, in words and in full on hover.
    QVERIFY(reason->isVisible());
    QVERIFY2(reason->text().contains(u"Cannot push: detent_strength: must be ≤ tau_limit"_s),
             qPrintable(reason->text()));
    QCOMPARE(reason->toolTip(), editor.problems().join(u'\n'));
    QVERIFY(reason->mapTo(&editor, QPoint(0, 0)).y() < scroll->mapTo(&editor, QPoint(0, 0)).y());
    // "Show" brings the field into sight with the cursor in it.
    Q_EMIT reason->linkActivated(u"show"_s);
    QVERIFY(inSight(field));
    QTRY_VERIFY(field->hasFocus());
    // Fixed: the line goes.
    editor.undoStack()->undo();
    QVERIFY(reason->isHidden());
}

void TestParameterEditor::derivedFiguresWarn_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("value");
    QTest::addColumn<bool>("saturates");
    QTest::addColumn<bool>("rings");

    QTest::newRow("defaults: neither") << u"K_max"_s << 0.4 << false << false;
    QTest::newRow("stiff notch saturates") << u"K_max"_s << 5.0 << true << true;
    QTest::newRow("little damping rings") << u"M_adm"_s << 1e-3 << false << true;
    QTest::newRow("heavy damping neither") << u"M_adm"_s << 0.1 << false << false;
}

void TestParameterEditor::derivedFiguresWarn()
{
    QFETCH(QString, key);
    QFETCH(double, value);
    QFETCH(bool, saturates);
    QFETCH(bool, rings);

    EditorRig editorRig;

    ParameterEditor &editor = editorRig.editor;
    spin(editor, key)->setValue(value);
    const DerivedFigures expected = deriveFigures(editor.params(), editor.hostParams());
    const DerivedFigures &shown = editor.derivedFiguresView()->figures();
    QCOMPARE(shown.omega_n, expected.omega_n);
    QCOMPARE(shown.zeta, expected.zeta);
    QCOMPARE(shown.timeConstant, expected.timeConstant);
    QCOMPARE(shown.peakTauRec, expected.peakTauRec);
    QCOMPARE(expected.saturates(), saturates);
    QCOMPARE(expected.rings(), rings);
    QCOMPARE(editor.derivedFiguresView()->isShowingSaturation(), saturates);
    QCOMPARE(editor.derivedFiguresView()->isShowingRinging(), rings);
    if (rings)
        QVERIFY(editor.derivedFiguresView()->warningText().contains(u"ζ"_s));
}

void TestParameterEditor::warningsNeverCutTheFigures_data()
{
    QTest::addColumn<QSize>("size");
    // The editor dock's narrowest width at 1280×720 with a bottom panel open, and roomier.
    QTest::newRow("420×460") << QSize(420, 460);
    QTest::newRow("420×320") << QSize(420, 320);
    QTest::newRow("600×700") << QSize(600, 700);
}

void TestParameterEditor::warningsNeverCutTheFigures()
{
    // Issue 27: with all three warnings up, the figures above them were squeezed and cut.
    QFETCH(QSize, size);
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.resize(size);
    spin(editor, u"K_max"_s)->setValue(5.0); // saturates and rings
    editor.derivedFiguresView()->setChatter(12.0, 0.5);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    QCoreApplication::processEvents();
    QVERIFY(editor.derivedFiguresView()->isShowingSaturation());
    QVERIFY(editor.derivedFiguresView()->isShowingRinging());
    QVERIFY(editor.derivedFiguresView()->isShowingChatter());
    for (const QString &name : {u"figure_omega_n"_s, u"figure_zeta"_s, u"figure_time_constant"_s,
                                u"figure_peak_tau"_s, u"figure_peak_percent"_s}) {
        const QLabel *figure = label(editor, name);
        QVERIFY2(figure, qPrintable(name));
        QVERIFY2(figure->isVisible(), qPrintable(name));
        QVERIFY2(figure->height() >= figure->sizeHint().height(),
                 qPrintable(u"%1: %2 px of %3"_s.arg(name)
                                .arg(figure->height())
                                .arg(figure->sizeHint().height())));
        // Inside the editor, not pushed out below it.
        const QRect inEditor(figure->mapTo(&editor, QPoint(0, 0)), figure->size());
        QVERIFY2(editor.rect().contains(inEditor), qPrintable(name));
    }
    // The warnings in sight (two lines at least), the rest reachable by scrolling.
    const auto *warnings = editor.findChild<QScrollArea *>(u"derivedWarnings"_s);
    QVERIFY(warnings && warnings->isVisible());
    QVERIFY2(warnings->viewport()->height() >= 2 * warnings->fontMetrics().height(),
             qPrintable(QString::number(warnings->viewport()->height())));
    // Each warning laid out whole inside that area: never a cut line.
    for (const QString &name :
         {u"warning_saturation"_s, u"warning_ringing"_s, u"warning_chatter"_s}) {
        const QLabel *warning = label(editor, name);
        QVERIFY2(warning->height() >= warning->heightForWidth(warning->width()),
                 qPrintable(u"%1: %2 px of %3"_s.arg(name)
                                .arg(warning->height())
                                .arg(warning->heightForWidth(warning->width()))));
    }
}

void TestParameterEditor::degreesChangeOnlyTheDisplay()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    DeviceParams d;
    d.theta0 = 0.5;
    editor.setParams(d, HostParams{}, u"set"_s);
    editor.setAngleInDegrees(true);
    QCOMPARE(editor.params().theta0, 0.5); // data stays SI, untouched
    QVERIFY(std::abs(spin(editor, u"theta0"_s)->value() - 0.5 * 180 / std::numbers::pi) < 1e-9);
    QCOMPARE(label(editor, u"unit_theta0"_s)->text(), u"°"_s);
    QCOMPARE(label(editor, u"unit_K_max"_s)->text(), u"N·m/rad"_s); // not an angle

    spin(editor, u"theta0"_s)->setValue(90.0);
    QVERIFY(std::abs(editor.params().theta0 - std::numbers::pi / 2) < 1e-12);
    editor.setAngleInDegrees(false);
    QVERIFY(std::abs(spin(editor, u"theta0"_s)->value() - std::numbers::pi / 2) < 1e-12);
    QCOMPARE(label(editor, u"unit_theta0"_s)->text(), u"rad"_s);
}

void TestParameterEditor::hostFieldsEdit()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    QSignalSpy host(editor.model(), &TuningModel::editedChanged);
    auto *mode = editor.findChild<QComboBox *>(u"combo_mode"_s);
    mode->setCurrentIndex(mode->findData(int(ReferenceMode::Rotation)));
    QCOMPARE(host.count(), 1);
    QVERIFY(host.at(0).at(0).value<TuningChange>().host);
    QVERIFY(!host.at(0).at(0).value<TuningChange>().device);
    QCOMPARE(editor.hostParams().mode, ReferenceMode::Rotation);
    QCOMPARE(label(editor, u"unit_v_max"_s)->text(), u"rad/s"_s);
    spin(editor, u"v_max"_s)->setValue(2.5);
    QCOMPARE(editor.hostParams().v_max, 2.5);
    QCOMPARE(editor.undoStack()->count(), 2);
    editor.undoStack()->undo();
    editor.undoStack()->undo();
    QCOMPARE(editor.hostParams(), HostParams{});
    QCOMPARE(label(editor, u"unit_v_max"_s)->text(), u"m/s"_s);
}

void TestParameterEditor::tauLimitFromDevice()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.setTauLimit(HostParams{}.tau_limit);
    QCOMPARE(editor.undoStack()->count(), 0); // same value: no edit
    editor.setTauLimit(0.3);
    QCOMPARE(editor.hostParams().tau_limit, 0.3);
    QCOMPARE(editor.derivedFiguresView()->figures().tauLimit, 0.3);
    QCOMPARE(editor.undoStack()->count(), 1);
}

void TestParameterEditor::relativeStepsForSmallValues()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    ScientificSpinBox *box = spin(editor, u"D_adm"_s);
    box->stepBy(1);
    QCOMPARE(editor.params().D_adm, 1.1e-4);
    box->stepBy(-2);
    QCOMPARE(editor.params().D_adm, 9.9e-5);
    QCOMPARE(box->text(), u"9.9e-05"_s);
}

QTEST_MAIN(TestParameterEditor)
#include "tst_parametereditor.moc"
