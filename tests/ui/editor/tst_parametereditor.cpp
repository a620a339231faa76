// ParameterEditor with real widgets: validation at the fields, push/sync states, undo/redo,
// diff markers, live push limits, derived figures.
#include "editor/derivedfiguresview.h"
#include "editor/parametereditor.h"
#include "editor/parameterfield.h"
#include "editor/scientificspinbox.h"
#include "model/derived.h"
#include "pushresult.h"

#include <QAction>
#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

ScientificSpinBox *spin(const ParameterEditor &editor, const QString &key)
{
    return editor.field(key)->spinBox();
}

QLabel *label(const ParameterEditor &editor, const QString &name)
{
    return editor.findChild<QLabel *>(name);
}

//! What a device echoes: every field rounded to float32 on the wire.
DeviceParams asFloat(const DeviceParams &p)
{
    DeviceParams out;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        out.setField(i, static_cast<float>(p.field(i)));
    return out;
}

//! An outcome that carries nothing to check: for a push no longer in flight.
Outcome ok()
{
    return {};
}

//! A push of `params` the device took and holds (float32) as sent.
Outcome echoed(const DeviceParams &params)
{
    return pushed({asFloat(params), std::nullopt}, {asFloat(params), std::nullopt});
}

} // namespace

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
    void pushEmitsExactValues();
    void ctrlReturnPushes();
    void inSyncAfterAckAndReadback_data();
    void inSyncAfterAckAndReadback();
    void mismatchingReadbackIsNotInSync();
    void rejectionShowsReasonAndKeepsValues();
    void timeoutShown();
    void undoRedoRestoresValues();
    void editsOfOneGestureMerge();
    void sliderDragIsOneUndoStep();
    void setParamsIsOneUndoStep();
    void diffMarkersFollowDevice();
    void revertLoadsDeviceValues();
    void livePushOneInFlightLastValueSent();
    void livePushRateLimited();
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
    ParameterEditor editor;
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

    ParameterEditor editor;
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
    QSignalSpy pushes(&editor, &ParameterEditor::pushRequested);
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
    ParameterEditor editor;
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

    ParameterEditor editor;
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
    ParameterEditor editor;
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
    ParameterEditor editor;
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
    ParameterEditor editor;
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
    ParameterEditor editor;
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

void TestParameterEditor::pushEmitsExactValues()
{
    ParameterEditor editor;
    editor.setCanPush(true);
    QSignalSpy pushes(&editor, &ParameterEditor::pushRequested);
    spin(editor, u"K_max"_s)->setValue(0.55);
    spin(editor, u"D_adm"_s)->setValue(2.5e-5);
    spin(editor, u"theta0"_s)->setValue(-0.125);
    QCOMPARE(editor.syncState(), SyncState::NotRead);

    editor.pushAction()->trigger();
    QCOMPARE(pushes.count(), 1);
    const auto sent = pushes.at(0).at(0).value<DeviceTuning>();
    DeviceParams expected;
    expected.K_max = 0.55;
    expected.D_adm = 2.5e-5;
    expected.theta0 = -0.125;
    QCOMPARE(sent.params, std::optional(expected));
    QVERIFY(!sent.effects); // a device that renders no effects gets none
    QCOMPARE(editor.syncState(), SyncState::Pushing);
    QCOMPARE(editor.syncText(), u"pushing…"_s);
    QVERIFY(!editor.pushAction()->isEnabled()); // one push at a time
}

void TestParameterEditor::ctrlReturnPushes()
{
    ParameterEditor editor;
    editor.setCanPush(true);
    editor.show();
    editor.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&editor));
    QSignalSpy pushes(&editor, &ParameterEditor::pushRequested);
    spin(editor, u"K_max"_s)->setFocus();
    QTest::keyClick(spin(editor, u"K_max"_s), Qt::Key_Return, Qt::ControlModifier);
    QCOMPARE(pushes.count(), 1);
    QCOMPARE(editor.pushAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_Return));
}

void TestParameterEditor::inSyncAfterAckAndReadback_data()
{
    QTest::addColumn<bool>("readBackUnanswered");
    QTest::newRow("read-back in the push's result") << false;
    QTest::newRow("read-back unanswered, read again") << true;
}

void TestParameterEditor::inSyncAfterAckAndReadback()
{
    QFETCH(bool, readBackUnanswered);
    ParameterEditor editor;
    editor.setCanPush(true);
    editor.setDeviceTuning({DeviceParams{}, std::nullopt});
    QCOMPARE(editor.syncState(), SyncState::InSync);

    spin(editor, u"K_max"_s)->setValue(0.4123457);
    spin(editor, u"N"_s)->setValue(0.3);
    QCOMPARE(editor.syncState(), SyncState::Edited);
    QCOMPARE(editor.syncText(), u"edited — not pushed"_s);
    QSignalSpy pushes(&editor, &ParameterEditor::pushRequested);
    editor.pushAction()->trigger();
    QCOMPARE(pushes.count(), 1);
    const DeviceParams echo = asFloat(editor.params());
    QVERIFY(echo != editor.params()); // the comparison has to allow float32 rounding

    QCOMPARE(pushes.at(0).at(0).value<DeviceTuning>().params, std::optional(editor.params()));
    if (readBackUnanswered) {
        editor.model()->pushFinished(Outcome{
            request::Push{{echo, std::nullopt}}, outcome::Done{outcome::ReadBack::Unanswered}, {}});
        QCOMPARE(editor.syncState(), SyncState::AwaitingReadback); // ACK alone is not enough
        QVERIFY(editor.syncText().contains(u"read-back"_s));
        editor.setDeviceTuning({echo, std::nullopt}); // read again
    } else {
        editor.model()->pushFinished(pushed({echo, std::nullopt}, {echo, std::nullopt}));
    }
    QCOMPARE(editor.syncState(), SyncState::InSync);
    QCOMPARE(editor.syncText(), u"in sync"_s);
    QVERIFY(editor.pushAction()->isEnabled());
    QVERIFY(!editor.revertAction()->isEnabled()); // nothing differs
}

void TestParameterEditor::mismatchingReadbackIsNotInSync()
{
    ParameterEditor editor;
    editor.setCanPush(true);
    editor.setDeviceTuning({DeviceParams{}, std::nullopt});
    spin(editor, u"K_max"_s)->setValue(0.8);
    editor.pushAction()->trigger();
    DeviceParams other = asFloat(editor.params());
    other.K_max = 0.75f; // the device stored something else
    editor.model()->pushFinished(
        pushed({asFloat(editor.params()), std::nullopt}, {other, std::nullopt}));
    QCOMPARE(editor.syncState(), SyncState::ReadbackDiffers);
    QVERIFY(editor.syncText().startsWith(u"not in sync"_s));
    QVERIFY(editor.field(u"K_max"_s)->differsFromDevice());
    QVERIFY(!editor.field(u"N"_s)->differsFromDevice());
    // The markers show the read-back the result carried.
    QCOMPARE(editor.deviceTuning().params, std::optional(other));
    QCOMPARE(label(editor, u"diff_K_max"_s)->toolTip(), u"device: 0.75 N·m/rad"_s);
}

void TestParameterEditor::rejectionShowsReasonAndKeepsValues()
{
    ParameterEditor editor;
    editor.setCanPush(true);
    editor.setDeviceTuning({DeviceParams{}, std::nullopt});
    spin(editor, u"K_max"_s)->setValue(3.0);
    const DeviceParams edited = editor.params();
    editor.pushAction()->trigger();

    editor.model()->pushFinished(
        Outcome{request::Push{{edited, std::nullopt}},
                outcome::Refused{{CommandKind::SetParams, {}}, v2::AckStatus::OutOfRange, 3},
                {}});

    QCOMPARE(editor.syncState(), SyncState::Rejected);
    QCOMPARE(editor.syncText(), u"device rejected: OUT_OF_RANGE (K_max)"_s);
    QCOMPARE(editor.params(), edited); // left for the user to fix
    QVERIFY(editor.field(u"K_max"_s)->problem().contains(u"refused"_s));
    QVERIFY(editor.pushAction()->isEnabled()); // the user may try again

    // Editing starts over: the rejection was about the old value.
    spin(editor, u"K_max"_s)->setValue(2.0);
    QCOMPARE(editor.syncState(), SyncState::Edited);
    QVERIFY(editor.field(u"K_max"_s)->problem().isEmpty());
}

void TestParameterEditor::timeoutShown()
{
    ParameterEditor editor;
    editor.setCanPush(true);
    editor.setDeviceTuning({DeviceParams{}, std::nullopt});
    spin(editor, u"K_max"_s)->setValue(0.6);
    editor.pushAction()->trigger();
    editor.model()->pushFinished(Outcome{request::Push{{editor.params(), std::nullopt}},
                                         outcome::TimedOut{{CommandKind::SetParams, {}}, 4, 250},
                                         {}});
    QCOMPARE(editor.syncState(), SyncState::Timeout);
    QVERIFY(editor.syncText().startsWith(u"timeout"_s));
    QCOMPARE(editor.params().K_max, 0.6);

    // A late answer after a disconnect changes nothing.
    editor.setDeviceTuning({});
    editor.setCanPush(false);
    editor.model()->pushFinished(ok());
    QCOMPARE(editor.syncState(), SyncState::NotConnected);
}

void TestParameterEditor::undoRedoRestoresValues()
{
    ParameterEditor editor;
    QSignalSpy edited(editor.model(), &TuningModel::editedChanged);
    spin(editor, u"K_max"_s)->setValue(0.5);
    spin(editor, u"K_min"_s)->setValue(0.2);
    QCOMPARE(editor.undoStack()->count(), 2);
    QCOMPARE(edited.count(), 2);

    editor.undoStack()->undo();
    QCOMPARE(editor.params().K_min, DeviceParams{}.K_min);
    QCOMPARE(spin(editor, u"K_min"_s)->value(), DeviceParams{}.K_min);
    QCOMPARE(editor.params().K_max, 0.5);
    editor.undoStack()->undo();
    QCOMPARE(editor.params(), DeviceParams{});
    QCOMPARE(spin(editor, u"K_max"_s)->value(), DeviceParams{}.K_max);
    QCOMPARE(edited.count(), 4);

    editor.undoStack()->redo();
    QCOMPARE(editor.params().K_max, 0.5);
    QCOMPARE(spin(editor, u"K_max"_s)->value(), 0.5);
    editor.redoAction()->trigger();
    QCOMPARE(editor.params().K_min, 0.2);
}

void TestParameterEditor::editsOfOneGestureMerge()
{
    ParameterEditor editor;
    ScientificSpinBox *box = spin(editor, u"K_max"_s);
    box->setFocus();
    // Arrow steps while the field has focus are one gesture.
    QTest::keyClick(box, Qt::Key_Up);
    QTest::keyClick(box, Qt::Key_Up);
    QTest::keyClick(box, Qt::Key_Up);
    QCOMPARE(editor.params().K_max, 0.43);
    QCOMPARE(editor.undoStack()->count(), 1);

    // Enter ends the gesture; the next edit of the same field is a new step.
    QTest::keyClick(box, Qt::Key_Enter);
    QTest::keyClick(box, Qt::Key_Down);
    QCOMPARE(editor.undoStack()->count(), 2);
    // Another field never merges.
    spin(editor, u"K_min"_s)->setValue(0.1);
    QCOMPARE(editor.undoStack()->count(), 3);

    editor.undoStack()->undo();
    editor.undoStack()->undo();
    QCOMPARE(editor.params().K_max, 0.43);
    editor.undoStack()->undo();
    QCOMPARE(editor.params().K_max, 0.4);
}

void TestParameterEditor::sliderDragIsOneUndoStep()
{
    ParameterEditor editor;
    QSlider *slider = editor.field(u"K_max"_s)->slider();
    slider->setSliderDown(true);
    for (int pos : {100, 150, 200, 260})
        slider->setValue(pos);
    slider->setSliderDown(false); // emits sliderReleased
    QCOMPARE(editor.undoStack()->count(), 1);
    const double dragged = editor.params().K_max;
    QVERIFY(std::abs(dragged - 5.0 * 260 / ParameterField::kSliderTicks) < 1e-12);
    QCOMPARE(spin(editor, u"K_max"_s)->value(), dragged);

    slider->setValue(300); // a new gesture
    QCOMPARE(editor.undoStack()->count(), 2);
    editor.undoStack()->undo();
    QCOMPARE(editor.params().K_max, dragged);
    editor.undoStack()->undo();
    QCOMPARE(editor.params().K_max, DeviceParams{}.K_max);
}

void TestParameterEditor::setParamsIsOneUndoStep()
{
    ParameterEditor editor;
    DeviceParams d;
    d.K_max = 1.5;
    d.Q_dz = 0.04;
    HostParams h;
    h.mode = ReferenceMode::Rotation;
    QSignalSpy host(editor.model(), &TuningModel::editedChanged);
    editor.setParams(d, h, u"Load preset"_s);
    QCOMPARE(editor.params(), d);
    QCOMPARE(editor.hostParams(), h);
    QCOMPARE(host.count(), 1); // one signal for the whole set
    QVERIFY(host.at(0).at(0).value<TuningChange>().host);
    QCOMPARE(editor.undoStack()->count(), 1);
    QCOMPARE(editor.undoStack()->undoText(), u"Load preset"_s);
    editor.undoStack()->undo();
    QCOMPARE(editor.params(), DeviceParams{});
    QCOMPARE(editor.hostParams(), HostParams{});
}

void TestParameterEditor::diffMarkersFollowDevice()
{
    ParameterEditor editor;
    QLabel *marker = label(editor, u"diff_K_max"_s);
    QVERIFY(marker->isHidden());

    DeviceParams device;
    device.N = static_cast<float>(0.1); // float32 echo of the same value: no difference
    editor.setDeviceTuning({device, std::nullopt});
    QVERIFY(marker->isHidden());
    QVERIFY(label(editor, u"diff_N"_s)->isHidden());

    spin(editor, u"K_max"_s)->setValue(0.7);
    QVERIFY(!marker->isHidden());
    QCOMPARE(marker->toolTip(), u"device: 0.4 N·m/rad"_s);
    QVERIFY(editor.revertAction()->isEnabled());

    spin(editor, u"K_max"_s)->setValue(0.4);
    QVERIFY(marker->isHidden());

    spin(editor, u"K_max"_s)->setValue(0.7);
    editor.setDeviceTuning({});
    QVERIFY(marker->isHidden());
    QVERIFY(!editor.revertAction()->isEnabled());
}

void TestParameterEditor::revertLoadsDeviceValues()
{
    ParameterEditor editor;
    editor.setCanPush(true);
    DeviceParams device;
    device.K_max = static_cast<float>(0.8); // as it comes off the wire
    device.theta0 = static_cast<float>(0.05);
    editor.setDeviceTuning({device, std::nullopt});
    QVERIFY(editor.revertAction()->isEnabled());
    editor.revertAction()->trigger();
    // The shortest decimal of the float, not 0.800000011920929.
    QCOMPARE(editor.params().K_max, 0.8);
    QCOMPARE(editor.params().theta0, 0.05);
    QCOMPARE(editor.syncState(), SyncState::InSync);
    editor.undoStack()->undo();
    QCOMPARE(editor.params(), DeviceParams{});

    QSignalSpy reads(&editor, &ParameterEditor::readRequested);
    editor.readAction()->trigger();
    QCOMPARE(reads.count(), 1);
}

void TestParameterEditor::livePushOneInFlightLastValueSent()
{
    ParameterEditor editor;
    editor.setCanPush(true);
    editor.setLivePushInterval(20);
    editor.setLivePush(true);
    QSignalSpy pushes(&editor, &ParameterEditor::pushRequested);

    for (int i = 1; i <= 30; ++i)
        spin(editor, u"K_max"_s)->setValue(0.4 + 0.01 * i);
    QCOMPARE(pushes.count(), 1); // the first edit went out; the rest wait for its answer
    QCOMPARE(pushes.at(0).at(0).value<DeviceTuning>().params->K_max, 0.41);

    // No answer yet: still one in flight, however long the event loop runs.
    QTest::qWait(60);
    QCOMPARE(pushes.count(), 1);

    editor.model()->pushFinished(echoed(*pushes.at(0).at(0).value<DeviceTuning>().params));
    QTRY_COMPARE(pushes.count(), 2);
    QCOMPARE(pushes.at(1).at(0).value<DeviceTuning>().params->K_max, 0.4 + 0.01 * 30);
    editor.model()->pushFinished(echoed(*pushes.at(1).at(0).value<DeviceTuning>().params));
    QCOMPARE(editor.syncState(), SyncState::InSync);
    QTest::qWait(60);
    QCOMPARE(pushes.count(), 2); // nothing new to send

    // Invalid values are not live-pushed.
    spin(editor, u"K_min"_s)->setValue(5.0);
    QTest::qWait(60);
    QCOMPARE(pushes.count(), 2);
}

void TestParameterEditor::livePushRateLimited()
{
    ParameterEditor editor;
    editor.setCanPush(true);
    const int interval = 40;
    editor.setLivePushInterval(interval);
    editor.setLivePush(true);

    QList<qint64> times; // [ns] when each push was requested
    QElapsedTimer clock;
    clock.start();
    bool overlapped = false;
    bool inFlight = false;
    double lastPushed = 0;
    connect(&editor, &ParameterEditor::pushRequested, &editor, [&](const DeviceTuning &t) {
        overlapped = overlapped || inFlight;
        inFlight = true;
        lastPushed = t.params->K_max;
        times << clock.nsecsElapsed();
        // The device answers at once (on the next event loop turn).
        QTimer::singleShot(0, &editor, [&, params = *t.params] {
            inFlight = false;
            editor.model()->pushFinished(echoed(params));
        });
    });

    // Drag for a bounded time, editing on every event loop turn.
    double value = 0.4;
    int edits = 0;
    while (clock.elapsed() < 8 * interval) {
        value += 1e-4;
        spin(editor, u"K_max"_s)->setValue(value);
        ++edits;
        QCoreApplication::processEvents();
    }
    // The last value is always sent, once the interval allows it.
    QTRY_COMPARE(lastPushed, value);
    QTRY_VERIFY(!inFlight);
    QVERIFY(!overlapped);
    QVERIFY(times.size() >= 2);
    QVERIFY2(times.size() < edits, "live push must not send every edit");
    for (int i = 1; i < times.size(); ++i) {
        const qint64 gapMs = (times[i] - times[i - 1]) / 1000000;
        QVERIFY2(gapMs >= interval - 1, qPrintable(u"gap %1 ms"_s.arg(gapMs)));
    }
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

    ParameterEditor editor;
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
    ParameterEditor editor;
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
    ParameterEditor editor;
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
    ParameterEditor editor;
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
    ParameterEditor editor;
    editor.setTauLimit(HostParams{}.tau_limit);
    QCOMPARE(editor.undoStack()->count(), 0); // same value: no edit
    editor.setTauLimit(0.3);
    QCOMPARE(editor.hostParams().tau_limit, 0.3);
    QCOMPARE(editor.derivedFiguresView()->figures().tauLimit, 0.3);
    QCOMPARE(editor.undoStack()->count(), 1);
}

void TestParameterEditor::relativeStepsForSmallValues()
{
    ParameterEditor editor;
    ScientificSpinBox *box = spin(editor, u"D_adm"_s);
    box->stepBy(1);
    QCOMPARE(editor.params().D_adm, 1.1e-4);
    box->stepBy(-2);
    QCOMPARE(editor.params().D_adm, 9.9e-5);
    QCOMPARE(box->text(), u"9.9e-05"_s);
}

QTEST_MAIN(TestParameterEditor)
#include "tst_parametereditor.moc"
