// DeviceParameterLink against the in-process simulator: the whole round trip (edit → push →
// ACK → read-back → in sync) through a real DeviceClient, the words for each outcome, the
// marker-worthy changes, a legacy device that cannot take parameters, and a disconnect.
#include "editor/deviceparameterlink.h"
#include "editor/parametereditor.h"
#include "session/deviceclient.h"

#include <QAction>
#include <QSignalSpy>
#include <QTest>

using namespace hatpic;

namespace {

constexpr int kConnectMs = 15000; //!< generous: the machine is shared

ConnectOptions simOptions(WireProtocol protocol)
{
    ConnectOptions options;
    options.port = QStringLiteral("sim");
    options.protocol = protocol == WireProtocol::V2 ? ProtocolChoice::V2 : ProtocolChoice::Auto;
    options.sim.protocol = protocol;
    return options;
}

//! A client, an editor and the link between them, as the window wires them.
struct Rig
{
    DeviceClient client;
    ParameterEditor editor;
    DeviceParameterLink link{&client, &editor};

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
    QCOMPARE(rig.editor.deviceParams(), rig.client.deviceParams());

    QSignalSpy changed(&rig.link, &DeviceParameterLink::deviceChanged);
    QSignalSpy finished(&rig.link, &DeviceParameterLink::commandFinished);
    DeviceParams edited = rig.editor.params();
    edited.K_max = 0.6;
    rig.editor.setParams(edited, rig.editor.hostParams(), QStringLiteral("K_max"));
    QCOMPARE(rig.editor.syncState(), SyncState::Edited);
    rig.editor.pushAction()->trigger();
    QCOMPARE(rig.editor.syncState(), SyncState::Pushing);
    QTRY_COMPARE_WITH_TIMEOUT(rig.editor.syncState(), SyncState::InSync, kConnectMs);
    QCOMPARE(float(rig.client.deviceParams().K_max), 0.6f);
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
    QVERIFY(rig.editor.deviceParams().has_value());
    QVERIFY(rig.disconnect());
    QVERIFY(!rig.editor.canPush());
    QVERIFY(!rig.editor.deviceParams());
    QCOMPARE(rig.editor.syncState(), SyncState::NotConnected);
}

QTEST_MAIN(TestDeviceParameterLink)
#include "tst_deviceparameterlink.moc"
