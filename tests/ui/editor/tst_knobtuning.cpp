// The editor's knob selector on a device with several knobs: hatpic-fw-host --servos 2 driving
// hatpic-servo-sim --servos 2 over real ptys, a real DeviceClient on a real QSerialPort, the
// editor and DeviceParameterLink as the window wires them. Each knob is read, pushed, zeroed
// and kept in sync on its own; knob 1's tuning stays the session's.
#include "editor/deviceparameterlink.h"
#include "editor/parametereditor.h"
#include "model/params.h"
#include "ptyprogram.h"
#include "session/deviceclient.h"

#include <QAction>
#include <QComboBox>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

constexpr int kTimeoutMs = 15000; //!< generous: the machine is shared

struct Rig
{
    DeviceClient client;
    TuningModel model;
    QUndoStack undo;
    ParameterEditor editor{&model, &undo};
    DeviceParameterLink link{&client, &model, &editor};

    //! Connects to the device on `port` as the window does (the link prepares the options).
    void connectTo(const QString &port)
    {
        ConnectOptions options;
        options.port = port;
        options.autoReconnect = false;
        link.prepare(options);
        client.connectDevice(options);
    }
};

QComboBox *knobBox(ParameterEditor &editor)
{
    return editor.findChild<QComboBox *>(u"combo_knob"_s);
}

//! Chooses knob `k` (0 for knob 1) as the user does: the selector's item.
void chooseKnob(ParameterEditor &editor, int k)
{
    QComboBox *box = knobBox(editor);
    box->setCurrentIndex(k);
    Q_EMIT box->activated(k);
}

} // namespace

class TestKnobTuning : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void eachKnobIsTunedOnItsOwn();
    void aSingleKnobHasNoSelector();
};

void TestKnobTuning::eachKnobIsTunedOnItsOwn()
{
    PtyProgram servo(hatpicServoSim(), {u"--servos"_s, u"2"_s, u"--hand-2"_s, u"const:0.02"_s});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    PtyProgram host(hatpicFwHost(),
                    QStringList{u"--servo"_s, servo.path(), u"--servos"_s, u"2"_s, u"--quiet"_s} +
                        patientBus());
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));

    Rig rig;
    rig.connectTo(host.path());
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kTimeoutMs);
    QCOMPARE(rig.client.deviceInfo().axes, quint8(2));
    QComboBox *box = knobBox(rig.editor);
    QVERIFY(box);
    QVERIFY(!box->isHidden());
    QCOMPARE(box->count(), 2);
    QCOMPARE(rig.link.knob(), Knob(0));

    // Knob 2 chosen: its tuning is read, and the editor compares with it.
    QSignalSpy finished(&rig.link, &DeviceParameterLink::commandFinished);
    chooseKnob(rig.editor, 1);
    QCOMPARE(rig.link.knob(), Knob(1));
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, kTimeoutMs);
    QCOMPARE(rig.link.lastMessage(), u"Read (knob 2): done."_s);
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kTimeoutMs);

    // A push reaches knob 2 alone; knob 1 (the session's) keeps its K_max.
    QSignalSpy changed(&rig.link, &DeviceParameterLink::deviceChanged);
    const double knob1Kmax = rig.client.deviceTuning().params->K_max;
    DeviceParams edited = rig.editor.params();
    edited.K_max = 0.5;
    rig.editor.setParams(edited, rig.editor.hostParams(), u"K_max"_s);
    QCOMPARE(rig.editor.syncState(), SyncState::Edited);
    rig.editor.pushAction()->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kTimeoutMs);
    QCOMPARE(float(rig.editor.deviceTuning().params->K_max), 0.5f);
    QCOMPARE(rig.client.deviceTuning().params->K_max, knob1Kmax);
    QVERIFY2(rig.link.lastMessage().startsWith(u"Pushed: knob 2: K_max 0.4 → 0.5"_s),
             qPrintable(rig.link.lastMessage()));
    QCOMPARE(changed.size(), 1);

    // ZERO on knob 2: its hand holds it off centre, so θ0 moves there; knob 1's stays 0.
    rig.link.zero();
    QTRY_VERIFY_WITH_TIMEOUT(rig.link.lastMessage() == u"ZERO (knob 2): done."_s, kTimeoutMs);
    QVERIFY2(rig.editor.deviceTuning().params->theta0 > 0.02,
             qPrintable(QString::number(rig.editor.deviceTuning().params->theta0)));
    QCOMPARE(rig.client.deviceTuning().params->theta0, 0.0);
    QCOMPARE(changed.constLast().at(0).toString(), u"knob 2: ZERO: θ0 := current angle"_s);

    // Back to knob 1: the editor compares with the session's tuning again, which differs from
    // the K_max 0.5 still edited.
    chooseKnob(rig.editor, 0);
    QCOMPARE(rig.editor.deviceTuning(), rig.client.deviceTuning());
    QCOMPARE(rig.editor.syncState(), SyncState::Edited);

    // Disconnected: the selector goes, knob 1 is tuned again.
    rig.client.disconnectDevice();
    QTRY_COMPARE_WITH_TIMEOUT(rig.client.state(), SessionState::Disconnected, kTimeoutMs);
    QVERIFY(box->isHidden());
    QCOMPARE(rig.link.knob(), Knob(0));
}

void TestKnobTuning::aSingleKnobHasNoSelector()
{
    PtyProgram servo(hatpicServoSim(), {});
    QVERIFY2(!servo.path().isEmpty(), qPrintable(servo.errors()));
    PtyProgram host(hatpicFwHost(),
                    QStringList{u"--servo"_s, servo.path(), u"--quiet"_s} + patientBus());
    QVERIFY2(!host.path().isEmpty(), qPrintable(host.errors()));
    Rig rig;
    rig.connectTo(host.path());
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kTimeoutMs);
    QCOMPARE(rig.client.deviceInfo().axes, quint8(1));
    QVERIFY(knobBox(rig.editor)->isHidden());
    rig.client.disconnectDevice();
    QTRY_COMPARE_WITH_TIMEOUT(rig.client.state(), SessionState::Disconnected, kTimeoutMs);
}

QTEST_MAIN(TestKnobTuning)
#include "tst_knobtuning.moc"
