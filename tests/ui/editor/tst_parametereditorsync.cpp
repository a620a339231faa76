// ParameterEditor with real widgets: pushing and undoing. The exact values pushed, Ctrl+Return,
// the sync states (in sync after the ACK and the read-back, a differing read-back, a rejection,
// a timeout), undo/redo (one step per gesture, slider drag or setParams), the diff markers
// against the device, revert, and live push's limits (one in flight, the rate).
#include "editor/parametereditor.h"
#include "editor/parameterfield.h"
#include "editor/scientificspinbox.h"
#include "editorparts.h"
#include "editorrig.h"
#include "pushresult.h"

#include <QAction>
#include <QElapsedTimer>
#include <QLabel>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <cmath>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

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

class TestParameterEditorSync : public QObject
{
    Q_OBJECT
private Q_SLOTS:
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
};

void TestParameterEditorSync::pushEmitsExactValues()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.setCanPush(true);
    QSignalSpy pushes(editor.model(), &TuningModel::pushRequested);
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

void TestParameterEditorSync::ctrlReturnPushes()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.setCanPush(true);
    editor.show();
    editor.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&editor));
    QSignalSpy pushes(editor.model(), &TuningModel::pushRequested);
    spin(editor, u"K_max"_s)->setFocus();
    QTest::keyClick(spin(editor, u"K_max"_s), Qt::Key_Return, Qt::ControlModifier);
    QCOMPARE(pushes.count(), 1);
    QCOMPARE(editor.pushAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_Return));
}

void TestParameterEditorSync::inSyncAfterAckAndReadback_data()
{
    QTest::addColumn<bool>("readBackUnanswered");
    QTest::newRow("read-back in the push's result") << false;
    QTest::newRow("read-back unanswered, read again") << true;
}

void TestParameterEditorSync::inSyncAfterAckAndReadback()
{
    QFETCH(bool, readBackUnanswered);
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.setCanPush(true);
    editor.setDeviceTuning({DeviceParams{}, std::nullopt});
    QCOMPARE(editor.syncState(), SyncState::InSync);

    spin(editor, u"K_max"_s)->setValue(0.4123457);
    spin(editor, u"N"_s)->setValue(0.3);
    QCOMPARE(editor.syncState(), SyncState::Edited);
    QCOMPARE(editor.syncText(), u"edited — not pushed"_s);
    QSignalSpy pushes(editor.model(), &TuningModel::pushRequested);
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

void TestParameterEditorSync::mismatchingReadbackIsNotInSync()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
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

void TestParameterEditorSync::rejectionShowsReasonAndKeepsValues()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
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

void TestParameterEditorSync::timeoutShown()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
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

void TestParameterEditorSync::undoRedoRestoresValues()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
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

void TestParameterEditorSync::editsOfOneGestureMerge()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
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

void TestParameterEditorSync::sliderDragIsOneUndoStep()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
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

void TestParameterEditorSync::setParamsIsOneUndoStep()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
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

void TestParameterEditorSync::diffMarkersFollowDevice()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
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

void TestParameterEditorSync::revertLoadsDeviceValues()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
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

void TestParameterEditorSync::livePushOneInFlightLastValueSent()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
    editor.setCanPush(true);
    editor.setLivePushInterval(20);
    editor.setLivePush(true);
    QSignalSpy pushes(editor.model(), &TuningModel::pushRequested);

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

void TestParameterEditorSync::livePushRateLimited()
{
    EditorRig editorRig;
    ParameterEditor &editor = editorRig.editor;
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
    connect(editor.model(), &TuningModel::pushRequested, &editor, [&](const DeviceTuning &t) {
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

QTEST_MAIN(TestParameterEditorSync)
#include "tst_parametereditorsync.moc"
