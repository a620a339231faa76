// DeviceParameterLink against the in-process simulator: the whole round trip (edit → push →
// ACK → read-back → in sync) through a real DeviceClient, the words for each outcome, the
// marker-worthy changes, the effect block pushed and kept in sync with them, the vibration
// test, a legacy device that can take neither, and a disconnect.
#include "editor/deviceparameterlink.h"
#include "editor/effectssection.h"
#include "editor/parametereditor.h"
#include "editor/parameterfield.h"
#include "editor/scientificspinbox.h"
#include "session/deviceclient.h"
#include "simulatoroptions.h"

#include <QAction>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace hatpic;

namespace {

constexpr int kConnectMs = 15000; //!< generous: the machine is shared

ConnectOptions simOptions(WireProtocol protocol)
{
    SimulatedDevice::Config config;
    config.protocol = protocol;
    return test::simulatorOptions(config, protocol == WireProtocol::V2 ? ProtocolChoice::V2
                                                                       : ProtocolChoice::Auto);
}

//! A client, an editor and the link between them, as the window wires them.
struct Rig
{
    DeviceClient client;
    TuningModel model;
    QUndoStack undo;
    ParameterEditor editor{&model, &undo};
    DeviceParameterLink link{&client, &model, &editor};

    //! The editor's tau_limit, as a profile would set it.
    void setTauLimit(double tauLimit)
    {
        HostParams host = editor.hostParams();
        host.tau_limit = tauLimit;
        editor.setParams(editor.params(), host, QStringLiteral("tau_limit"));
    }
    //! Disconnects and waits until the session is down.
    bool disconnect()
    {
        client.disconnectDevice();
        return QTest::qWaitFor([this] { return client.state() == SessionState::Disconnected; },
                               kConnectMs);
    }
};

} // namespace

class TestDeviceParameterLink : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void pushReachesTheDeviceAndComesBackInSync();
    void commandsAreWorded();
    void effectsArePushedWithTheParameters();
    void passivityControllerIsPushedAndKeptInSync();
    void pushListsOnlyWhatWasEdited();
    void vibrationTestIsAcknowledged();
    void legacyDeviceCannotTakeParameters();
    void disconnectForgetsTheDevice();
};

void TestDeviceParameterLink::pushReachesTheDeviceAndComesBackInSync()
{
    Rig rig;
    QCOMPARE(rig.editor.syncState(), SyncState::NotConnected);
    ConnectOptions options = simOptions(WireProtocol::V2);
    rig.link.prepare(options);
    rig.client.connectDevice(options);
    // Connected, the device's read-back arrives by itself: the editor is in sync.
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kConnectMs);
    QVERIFY(rig.editor.canPush());
    QCOMPARE(rig.editor.deviceTuning(), rig.client.deviceTuning());

    QSignalSpy changed(&rig.link, &DeviceParameterLink::deviceChanged);
    QSignalSpy finished(&rig.link, &DeviceParameterLink::commandFinished);
    DeviceParams edited = rig.editor.params();
    edited.K_max = 0.6;
    rig.editor.setParams(edited, rig.editor.hostParams(), QStringLiteral("K_max"));
    QCOMPARE(rig.editor.syncState(), SyncState::Edited);
    rig.editor.pushAction()->trigger();
    QCOMPARE(rig.editor.syncState(), SyncState::Pushing);
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kConnectMs);
    QCOMPARE(float(rig.client.deviceTuning().params->K_max), 0.6f);
    QCOMPARE(finished.size(), 1);
    QVERIFY2(rig.link.lastMessage().contains(QStringLiteral("K_max 0.4 → 0.6")),
             qPrintable(rig.link.lastMessage()));
    QCOMPARE(finished.constFirst().at(0).toString(), rig.link.lastMessage());
    QCOMPARE(changed.size(), 1);
    QCOMPARE(changed.constFirst().at(0).toString(), QStringLiteral("K_max 0.4 → 0.6"));

    // The same values again: nothing changes, nothing to mark.
    rig.editor.pushAction()->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, kConnectMs);
    QCOMPARE(rig.link.lastMessage(), QStringLiteral("Pushed (no change)."));
    QCOMPARE(changed.size(), 1);
    QVERIFY(rig.disconnect());
}

void TestDeviceParameterLink::commandsAreWorded()
{
    Rig rig;
    ConnectOptions options = simOptions(WireProtocol::V2);
    rig.client.connectDevice(options);
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kConnectMs);
    QSignalSpy finished(&rig.link, &DeviceParameterLink::commandFinished);
    QSignalSpy changed(&rig.link, &DeviceParameterLink::deviceChanged);

    rig.editor.readAction()->trigger(); // the editor's Read goes through the link
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, kConnectMs);
    QCOMPARE(rig.link.lastMessage(), QStringLiteral("Read: done."));
    rig.link.saveInDevice();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, kConnectMs);
    QCOMPARE(rig.link.lastMessage(), QStringLiteral("Save in device: done."));
    QCOMPARE(changed.size(), 0);
    rig.link.zero();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 3, kConnectMs);
    QCOMPARE(rig.link.lastMessage(), QStringLiteral("ZERO: done."));
    QCOMPARE(changed.size(), 1);
    QCOMPARE(changed.constFirst().at(0).toString(), QStringLiteral("ZERO: θ0 := current angle"));
    QVERIFY(rig.disconnect());
}

void TestDeviceParameterLink::effectsArePushedWithTheParameters()
{
    Rig rig;
    rig.client.connectDevice(simOptions(WireProtocol::V2));
    // In sync means the effects too: the default ±π walls read back as the float inside π.
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kConnectMs);
    QVERIFY(rig.client.deviceInfo().hasEffects());
    QVERIFY(rig.editor.effectsSection()->isAvailable());
    QVERIFY(rig.editor.deviceTuning().effects.has_value());
    QVERIFY(!rig.editor.field(QStringLiteral("wall_max"))->differsFromDevice());

    QSignalSpy finished(&rig.link, &DeviceParameterLink::commandFinished);
    QSignalSpy changed(&rig.link, &DeviceParameterLink::deviceChanged);
    QSignalSpy pushes(&rig.model, &TuningModel::pushRequested);
    Tuning t = rig.editor.tuning();
    t.device.K_max = 0.5;
    t.effects.detent_strength = 0.05;
    t.effects.detent_range = 0.8;
    rig.editor.setTuning(t, QStringLiteral("detents"));
    QCOMPARE(rig.editor.syncState(), SyncState::Edited);
    QVERIFY(rig.editor.field(QStringLiteral("detent_strength"))->differsFromDevice());
    rig.editor.pushAction()->trigger();
    QCOMPARE(pushes.size(), 1);
    QVERIFY(pushes.constFirst().at(0).value<DeviceTuning>().effects.has_value());
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kConnectMs);
    QCOMPARE(finished.size(), 1); // one push, one outcome, for both commands
    QVERIFY(rig.client.deviceTuning().effects && rig.client.deviceTuning().params);
    QCOMPARE(float(rig.client.deviceTuning().effects->detent_strength), 0.05f);
    QCOMPARE(float(rig.client.deviceTuning().effects->detent_range), 0.8f);
    QCOMPARE(float(rig.client.deviceTuning().params->K_max), 0.5f);
    QCOMPARE(rig.editor.deviceTuning(), rig.client.deviceTuning());
    QVERIFY2(rig.link.lastMessage().contains(QStringLiteral("K_max 0.4 → 0.5")) &&
                 rig.link.lastMessage().contains(QStringLiteral("detent_strength 0 → 0.05")),
             qPrintable(rig.link.lastMessage()));
    QCOMPARE(changed.size(), 1);
    QVERIFY(!rig.editor.field(QStringLiteral("detent_strength"))->differsFromDevice());

    // Unchanged effects are not sent again; undo brings the edit back as "edited".
    rig.editor.pushAction()->trigger();
    QCOMPARE(pushes.size(), 2);
    QVERIFY(!pushes.at(1).at(0).value<DeviceTuning>().effects.has_value());
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, kConnectMs);
    QCOMPARE(rig.link.lastMessage(), QStringLiteral("Pushed (no change)."));
    rig.editor.undoAction()->trigger();
    QCOMPARE(rig.editor.effects(), EffectParams{});
    QCOMPARE(rig.editor.syncState(), SyncState::Edited);
    // Revert takes the device's effects back (as an undoable edit).
    rig.editor.revertAction()->trigger();
    QCOMPARE(rig.editor.syncState(), SyncState::InSync);
    QCOMPARE(float(rig.editor.effects().detent_strength), 0.05f);

    // Read asks for both; one message.
    rig.editor.readAction()->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 3, kConnectMs);
    QCOMPARE(rig.link.lastMessage(), QStringLiteral("Read: done."));
    QTest::qWait(200);
    QCOMPARE(finished.size(), 3);
    QVERIFY(rig.disconnect());
    QVERIFY(!rig.editor.deviceTuning().effects);
    QVERIFY(!rig.editor.effectsSection()->isAvailable());
}

void TestDeviceParameterLink::pushListsOnlyWhatWasEdited()
{
    // The walls stay at ±π, which travel as the float just inside π (effects.md): the device
    // holds −3.1415925, the editor −π. Edited: the detents only, typed into their fields.
    Rig rig;
    rig.editor.show();
    rig.client.connectDevice(simOptions(WireProtocol::V2));
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kConnectMs);
    QSignalSpy finished(&rig.link, &DeviceParameterLink::commandFinished);
    QSignalSpy changed(&rig.link, &DeviceParameterLink::deviceChanged);
    for (const auto &[key, text] :
         {std::pair{"detent_strength", "0.05"}, std::pair{"detent_range", "0.8"}}) {
        ScientificSpinBox *spin = rig.editor.field(QString::fromLatin1(key))->spinBox();
        spin->setFocus();
        spin->selectAll();
        QTest::keyClicks(spin, QString::fromLatin1(text));
        QTest::keyClick(spin, Qt::Key_Return);
    }
    QCOMPARE(rig.editor.effects().detent_range, 0.8);
    rig.editor.pushAction()->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, kConnectMs);
    QCOMPARE(rig.link.lastMessage(),
             QStringLiteral("Pushed: detent_strength 0 → 0.05; detent_range 0 → 0.8"));
    QCOMPARE(changed.size(), 1);
    QCOMPARE(changed.constFirst().at(0).toString(),
             QStringLiteral("detent_strength 0 → 0.05; detent_range 0 → 0.8"));
    QVERIFY(rig.disconnect());
}

void TestDeviceParameterLink::vibrationTestIsAcknowledged()
{
    Rig rig;
    EffectsSection *fx = rig.editor.effectsSection();
    QVERIFY(!fx->vibrateButton()->isEnabled()); // not connected
    rig.client.connectDevice(simOptions(WireProtocol::V2));
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kConnectMs);
    QVERIFY(fx->vibrateButton()->isEnabled());
    QSignalSpy finished(&rig.link, &DeviceParameterLink::commandFinished);
    fx->setVibration(Vibration{0.05, 40, 0.2});
    fx->vibrateButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, kConnectMs);
    QCOMPARE(rig.link.lastMessage(), QStringLiteral("Vibrate: done."));
    fx->stopButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, kConnectMs);
    QCOMPARE(rig.link.lastMessage(), QStringLiteral("Stop vibration: done."));

    // Above half the device's control rate the cue is refused at the field, before sending.
    const double nyquist = rig.client.deviceInfo().maxStreamHz / 2.0;
    fx->setVibration(Vibration{0.05, nyquist, 0.2});
    QVERIFY(!fx->vibrateButton()->isEnabled());
    QVERIFY2(fx->vibrationProblems().join(u'\n').contains(QStringLiteral("half the control rate")),
             qPrintable(fx->vibrationProblems().join(u'\n')));
    QVERIFY(rig.disconnect());
}

void TestDeviceParameterLink::passivityControllerIsPushedAndKeptInSync()
{
    Rig rig;
    rig.client.connectDevice(simOptions(WireProtocol::V2));
    // In sync means the passivity block too: the connection reads it (GET_PASSIVITY).
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kConnectMs);
    QVERIFY(rig.client.deviceInfo().hasPassivity());
    QVERIFY(rig.editor.deviceTuning().passivity.has_value());
    const auto *why = rig.editor.findChild<QLabel *>(QStringLiteral("label_passivity_unavailable"));
    QVERIFY(why && !why->isVisibleTo(&rig.editor));
    ParameterField *beta = rig.editor.field(QStringLiteral("pc_damping_max"));
    QVERIFY(beta);
    QCOMPARE(beta->value(), PassivityParams{}.pc_damping_max);
    QVERIFY(!beta->differsFromDevice());

    QSignalSpy finished(&rig.link, &DeviceParameterLink::commandFinished);
    QSignalSpy pushes(&rig.model, &TuningModel::pushRequested);
    // Typed into the field as a user does: one undoable edit, marked against the device.
    beta->spinBox()->setFocus();
    beta->spinBox()->selectAll();
    QTest::keyClicks(beta->spinBox(), QStringLiteral("0"));
    QTest::keyClick(beta->spinBox(), Qt::Key_Return);
    QCOMPARE(rig.editor.passivity().pc_damping_max, 0.0);
    QCOMPARE(rig.editor.syncState(), SyncState::Edited);
    QVERIFY(beta->differsFromDevice());
    rig.editor.pushAction()->trigger();
    QCOMPARE(pushes.size(), 1);
    const DeviceTuning pushed = pushes.constFirst().at(0).value<DeviceTuning>();
    QVERIFY(pushed.passivity && pushed.passivity->pc_damping_max == 0.0);
    QVERIFY(!pushed.effects); // the effects were in sync: not sent
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kConnectMs);
    QCOMPARE(finished.size(), 1);
    // The device's read-back holds it: the controller is off on the device.
    QVERIFY(rig.client.deviceTuning().passivity);
    QCOMPARE(rig.client.deviceTuning().passivity->pc_damping_max, 0.0);
    QVERIFY2(rig.link.lastMessage().contains(QStringLiteral("pc_damping_max 0.7 → 0")),
             qPrintable(rig.link.lastMessage()));
    QVERIFY(!beta->differsFromDevice());

    // Unchanged, it is not sent again; undo brings the edit back as "edited".
    rig.editor.pushAction()->trigger();
    QCOMPARE(pushes.size(), 2);
    QVERIFY(!pushes.at(1).at(0).value<DeviceTuning>().passivity.has_value());
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, kConnectMs);
    rig.editor.undoAction()->trigger();
    QCOMPARE(rig.editor.passivity().pc_damping_max, PassivityParams{}.pc_damping_max);
    QCOMPARE(rig.editor.syncState(), SyncState::Edited);
    // An invalid value is the editor's problem, named, and nothing is pushed.
    Tuning t = rig.editor.tuning();
    t.passivity.pc_reserve_max = -1;
    rig.editor.setTuning(t, QStringLiteral("bad reserve"));
    QVERIFY(!rig.editor.pushAction()->isEnabled());
    QVERIFY2(rig.editor.problems().join(u'\n').contains(QStringLiteral("pc_reserve_max")),
             qPrintable(rig.editor.problems().join(u'\n')));
    QVERIFY(rig.disconnect());
}

void TestDeviceParameterLink::legacyDeviceCannotTakeParameters()
{
    Rig rig;
    rig.setTauLimit(0.3);
    ConnectOptions options = simOptions(WireProtocol::Legacy);
    rig.link.prepare(options);
    // The legacy feedback is scaled by the editor's torque limit (the device reports none).
    QCOMPARE(options.legacy.tauLimit, 0.3);
    rig.client.connectDevice(options);
    QTRY_COMPARE_WITH_TIMEOUT(rig.client.state(), SessionState::Connected, kConnectMs);
    QCOMPARE(rig.client.deviceInfo().protocol, WireProtocol::Legacy);
    QVERIFY(!rig.editor.canPush());
    QVERIFY(!rig.editor.pushAction()->isEnabled());
    QCOMPARE(rig.editor.syncText(), QStringLiteral("the legacy protocol cannot carry parameters"));
    QCOMPARE(rig.editor.hostParams().tau_limit, 0.3); // not replaced
    // Nor effects: the editor says so instead of pretending, and keeps them for the profile.
    EffectsSection *fx = rig.editor.effectsSection();
    QVERIFY(!fx->isAvailable());
    const auto *why = fx->findChild<QLabel *>(QStringLiteral("label_effects_unavailable"));
    QVERIFY(why && why->isVisibleTo(&rig.editor));
    QVERIFY2(why->text().contains(QStringLiteral("published firmware")), qPrintable(why->text()));
    QVERIFY(!fx->vibrateButton()->isEnabled());
    QVERIFY(rig.editor.field(QStringLiteral("detent_strength"))->spinBox()->isEnabled());
    // Nor a passivity controller: said above its fields, which stay editable.
    const auto *noController =
        rig.editor.findChild<QLabel *>(QStringLiteral("label_passivity_unavailable"));
    QVERIFY(noController && noController->isVisibleTo(&rig.editor));
    QVERIFY2(noController->text().contains(QStringLiteral("no passivity controller")),
             qPrintable(noController->text()));
    QVERIFY(rig.editor.field(QStringLiteral("pc_damping_max"))->spinBox()->isEnabled());
    QVERIFY(rig.disconnect());
}

void TestDeviceParameterLink::disconnectForgetsTheDevice()
{
    Rig rig;
    rig.setTauLimit(0.3);
    rig.client.connectDevice(simOptions(WireProtocol::V2));
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kConnectMs);
    // A v2 device reports its actuator limit: the editor takes it, as an undoable edit.
    QCOMPARE(float(rig.editor.hostParams().tau_limit), float(rig.client.deviceInfo().tauLimit));
    QVERIFY(rig.editor.deviceTuning().params.has_value());
    QVERIFY(rig.disconnect());
    QVERIFY(!rig.editor.canPush());
    QVERIFY(!rig.editor.deviceTuning().params);
    QCOMPARE(rig.editor.syncState(), SyncState::NotConnected);
}

QTEST_MAIN(TestDeviceParameterLink)
#include "tst_deviceparameterlink.moc"
