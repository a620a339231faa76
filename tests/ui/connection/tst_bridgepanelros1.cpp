// The Bridge panel on ROS 1, real widgets offscreen, on the in-process simulated joystick, a
// real roscore on loopback and a rospy node that is not ours: choosing ROS 1 shows the master
// instead of the domain, the references reach rospy, its wrench the knob, a profile's
// settings keep the ROS chosen, and disabling leaves τ_ext 0.
#include "roscore.h"

#include "connection/bridgepanel.h"
#include "session/deviceclient.h"
#include "simulatoroptions.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

#include <cmath>
#include <limits>
#include <memory>

using namespace hatpic;
using hatpic::test::field;
using hatpic::test::Ros1Peer;
using hatpic::test::RosCore;
using namespace Qt::StringLiterals;

namespace {

constexpr double kTauExtTolerance = 1e-6; //!< τ_ext travels as float32 [N·m]

} // namespace

class TestBridgePanelRos1 : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(BridgePanel::isBuilt());
        registerSessionMetaTypes();
        QCOMPARE(m_core.start(), QString());
        SimulatedDevice::Config config;
        config.hand = HandInput{HandInput::Kind::VirtualHand, 0, 0, 0, 0, 0.5};
        connect(&m_client, &DeviceClient::samplesReady, this, [this](const SampleBatch &batch) {
            if (!batch.isEmpty())
                m_deviceTauExt = batch.last().tau_ext;
        });
        m_client.connectDevice(test::simulatorOptions(config));
        QTRY_COMPARE_WITH_TIMEOUT(m_client.state(), SessionState::Connected, 10000);
        m_client.setHostParams(HostParams{});
        m_panel = std::make_unique<BridgePanel>(m_client);
        m_panel->show();
        QCOMPARE(m_peer.start(m_core.environment(),
                              {u"--sub"_s, u"/hatpic/twist=geometry_msgs/TwistStamped"_s,
                               u"--pub"_s, u"/wrench_estimation=geometry_msgs/WrenchStamped"_s}),
                 QString());
    }
    void cleanupTestCase()
    {
        m_panel.reset();
        m_peer.stop();
        m_core.stop();
    }

    void rosOneShowsTheMasterNotTheDomain()
    {
        auto *ros = find<QComboBox>(u"bridge_ros"_s);
        QCOMPARE(ros->currentText(), u"ROS 2"_s);
        QVERIFY(find<QSpinBox>(u"bridge_domain"_s)->isVisible());
        QVERIFY(!find<QLabel>(u"bridge_master"_s)->isVisible());

        QSignalSpy edited(m_panel.get(), &BridgePanel::settingsEdited);
        ros->setCurrentIndex(ros->findText(u"ROS 1"_s));
        QCOMPARE(m_panel->settings().rosVersion, 1);
        QCOMPARE(edited.size(), 1);
        QVERIFY(!find<QSpinBox>(u"bridge_domain"_s)->isVisible());
        QVERIFY(find<QLabel>(u"bridge_master"_s)->isVisible());
        QCOMPARE(label(u"bridge_master"_s), m_core.uri());
        QVERIFY(!m_panel->isRunning());
    }

    void runsOnRosOne()
    {
        find<QCheckBox>(u"bridge_enable"_s)->click();
        QVERIFY(m_panel->isRunning());
        QCOMPARE(label(u"bridge_status"_s),
                 u"Running on ROS 1, master "_s + m_core.uri() + u" (node /hatpic_bridge)"_s);
        QTRY_VERIFY_WITH_TIMEOUT(m_peer.received(u"/hatpic/twist"_s).size() >= 20, 10000);
        QCOMPARE(m_peer.received(u"/hatpic/twist"_s).last().value(u"callerid"_s).toString(),
                 u"/hatpic_bridge"_s);

        QTRY_VERIFY_WITH_TIMEOUT(m_peer.connections(u"/wrench_estimation"_s) >= 1, 10000);
        find<QComboBox>(u"bridge_component"_s)->setCurrentText(u"force.z"_s); // the peer's
        m_peer.send(uR"(set /wrench_estimation {"wrench": {"force": {"z": 0.5}}})"_s);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - 0.077) < kTauExtTolerance, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(label(u"bridge_tau_ext"_s), u"0.077 N·m"_s, 2000);
    }

    // A profile brings the feel, not the network: the panel stays on ROS 1.
    void aProfileKeepsTheRosChosen()
    {
        bridge::BridgeSettings profile;
        profile.feedback.gain = 0.1;
        m_panel->setSettings(profile);
        QCOMPARE(m_panel->settings().rosVersion, 1);
        QCOMPARE(find<QComboBox>(u"bridge_ros"_s)->currentText(), u"ROS 1"_s);
        QVERIFY(m_panel->isRunning());
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt - 0.05) < kTauExtTolerance, 5000);
    }

    void disableLeavesZero()
    {
        find<QCheckBox>(u"bridge_enable"_s)->click();
        QVERIFY(!m_panel->isRunning());
        QTRY_COMPARE_WITH_TIMEOUT(m_deviceTauExt, 0.0, 1000);
        m_peer.send(u"stop /wrench_estimation"_s);
    }

private:
    template<typename T> T *find(const QString &name) const
    {
        T *widget = m_panel->findChild<T *>(name);
        Q_ASSERT(widget);
        return widget;
    }
    QString label(const QString &name) const { return find<QLabel>(name)->text(); }

    // First: it sets this process's ROS 1 environment before any member starts a thread.
    RosCore m_core{RosCore::ThisProcess::Exported};
    Ros1Peer m_peer;
    DeviceClient m_client;
    std::unique_ptr<BridgePanel> m_panel;
    double m_deviceTauExt = std::numeric_limits<double>::quiet_NaN();
};

QTEST_MAIN(TestBridgePanelRos1)
#include "tst_bridgepanelros1.moc"
