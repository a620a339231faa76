// The Bridge panel, real widgets offscreen, on a DeviceClient of the in-process simulated
// joystick and real Cyclone DDS confined to loopback in this test's own domain: enable, the
// references out, a wrench in shown as the last wrench and the τ_ext it produced (and felt by
// the device), gain and limit tuned while running, rejected counts, topics and rate changed
// live, bad input refused, disable leaving τ_ext 0.
#include "rostestpeer.h"

#include "connection/bridgepanel.h"
#include "connection/bridgepanelform.h"
#include "plots/qcp.h"
#include "session/deviceclient.h"
#include "simulatoroptions.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

using namespace hatpic;
using hatpic::test::RosTestPeer;
using namespace Qt::StringLiterals;

namespace {

constexpr int kDomain = 73;               //!< this test's own DDS domain
constexpr double kTauExtTolerance = 1e-6; //!< τ_ext travels as float32 [N·m]

} // namespace

class TestBridgePanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(BridgePanel::isBuilt());
        registerSessionMetaTypes();
        SimulatedDevice::Config config;
        config.hand = HandInput{HandInput::Kind::VirtualHand, 0, 0, 0, 0, 0.5};
        connect(&m_client, &DeviceClient::samplesReady, this, [this](const SampleBatch &batch) {
            if (!batch.isEmpty())
                m_deviceTauExt = batch.last().tau_ext;
        });
        m_client.connectDevice(test::simulatorOptions(config));
        QTRY_COMPARE_WITH_TIMEOUT(m_client.state(), SessionState::Connected, 10000);
        m_client.setHostParams(HostParams{});
        m_peer = std::make_unique<RosTestPeer>(kDomain);
        QVERIFY(m_peer->isValid());
        m_panel = std::make_unique<BridgePanel>(m_client);
        m_panel->show();
    }

    void offUntilEnabled()
    {
        QVERIFY(!m_panel->isRunning());
        QCOMPARE(label(u"bridge_status"_s), u"Off"_s);
        QCOMPARE(m_panel->loopState(), BridgePanel::LoopState::Off);
        QVERIFY(label(u"bridge_loop_state"_s).contains(u"Bridge off"_s));
        // What it needs, with where to find a robot when there is none (issue 27).
        QVERIFY(find<QLabel>(u"bridge_needs"_s)->isVisible());
        QVERIFY(BridgePanel::needsText().contains(u"hatpic-robot-sim"_s));
        QVERIFY(BridgePanel::needsText().contains(u"scripts/teleop-demo"_s));
        QSignalSpy edited(m_panel.get(), &BridgePanel::settingsEdited);
        find<QSpinBox>(u"bridge_domain"_s)->setValue(kDomain);
        QCOMPARE(m_panel->settings().domainId, kDomain);
        QCOMPARE(edited.size(), 1);
        QVERIFY(!m_panel->isRunning());

        find<QCheckBox>(u"bridge_enable"_s)->click();
        QVERIFY(m_panel->isRunning());
        QCOMPARE(label(u"bridge_status"_s), u"Running on domain 73"_s);
        // Running: the loop's state in the header, the needs out of the way.
        QTRY_COMPARE(m_panel->loopState(), BridgePanel::LoopState::Passive);
        QVERIFY(label(u"bridge_loop_state"_s).contains(u"Loop passive, no contact"_s));
        QVERIFY(!find<QLabel>(u"bridge_needs"_s)->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT((m_peer->take(), m_peer->twists.size() >= 20), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(label(u"bridge_published"_s).contains(u"twist "_s) &&
                                     !label(u"bridge_published"_s).contains(u"twist 0,"_s),
                                 5000);
    }

    void wrenchBecomesTauExt()
    {
        QTRY_VERIFY_WITH_TIMEOUT(m_peer->wrenchMatched(), 10000);
        // The panel's default component is force.x, the project's own robot's; this robot
        // sends force.z: the whole wrench shows, τ_ext stays 0, and the panel says why.
        QCOMPARE(find<QComboBox>(u"bridge_component"_s)->currentText(), u"force.x"_s);
        startRobot(0.5);
        QTRY_COMPARE_WITH_TIMEOUT(label(u"bridge_last_wrench"_s),
                                  u"force 0 0 0.5 N, torque 0 0 0 N·m"_s, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(label(u"bridge_other_component"_s),
                                  u"force.x stays 0 while the robot sends force.z = 0.5 N: is the "
                                  u"component right?"_s,
                                  2000);
        QVERIFY(find<QLabel>(u"bridge_other_component"_s)->isVisible());
        QCOMPARE(m_deviceTauExt, 0.0);
        QCOMPARE(label(u"bridge_tau_ext"_s), u"0 N·m"_s);

        // force.z chosen: the defaults' 0.154 N·m per N, ±0.154 N·m, and no warning.
        find<QComboBox>(u"bridge_component"_s)->setCurrentText(u"force.z"_s);
        expectTauExt(0.077);
        QTRY_VERIFY_WITH_TIMEOUT(!find<QLabel>(u"bridge_other_component"_s)->isVisible(), 2000);
        QCOMPARE(label(u"bridge_tau_ext"_s), u"0.077 N·m"_s);
    }

    void gainAndLimitWhileRunning()
    {
        QSignalSpy edited(m_panel.get(), &BridgePanel::settingsEdited);
        find<QDoubleSpinBox>(u"bridge_gain"_s)->setValue(0.5); // 0.25, clamped to 0.154
        expectTauExt(0.154);
        find<QDoubleSpinBox>(u"bridge_limit"_s)->setValue(0.2);
        expectTauExt(0.2);
        QVERIFY(m_panel->isRunning());
        QCOMPARE(edited.size(), 2);
        const auto last = edited.last().at(0).value<bridge::BridgeSettings>();
        QCOMPARE(last.feedback.gain, 0.5);
        QCOMPARE(last.feedback.limit, 0.2);
        QVERIFY(label(u"bridge_counts"_s).contains(u"limited"_s));
    }

    void nonFiniteAndStaleAreCountedAndGiveZero()
    {
        m_robotValue = std::numeric_limits<double>::quiet_NaN();
        expectTauExt(0);
        QTRY_VERIFY_WITH_TIMEOUT(!label(u"bridge_counts"_s).contains(u" 0 non-finite"_s), 2000);
        m_robotValue = 0.2; // 0.1 N·m
        expectTauExt(0.1);
        m_robot.stop(); // stale after 0.5 s
        expectTauExt(0);
        QTRY_VERIFY_WITH_TIMEOUT(!label(u"bridge_counts"_s).contains(u" 0 stale"_s), 2000);
    }

    // The robot side as measured, and the passivity observer: a robot whose wrench pushes the
    // knob the way it goes (against the virtual hand) gives it energy in contact — the warning
    // says what to do, and goes once the pushing stops.
    void robotSideAndPassivityShown()
    {
        // What the pushes of the tests before generated has left the window.
        QTRY_VERIFY_WITH_TIMEOUT(!find<QLabel>(u"bridge_passivity_warning"_s)->isVisible(), 5000);
        QVERIFY(label(u"bridge_stamp_delay"_s).startsWith(u"– (the wrenches carry no stamp)"_s));
        startRobot(0.5, 0.2); // gain 0.5, limit 0.2: τ_ext 0.2 N·m; stamps 200 ms old
        expectTauExt(0.2);
        const QRegularExpression delay(
            u"^([0-9.]+) ms median, ([0-9.]+) ms p95 \\(([0-9]+) stamped\\)$"_s);
        QTRY_VERIFY_WITH_TIMEOUT(delay.match(label(u"bridge_stamp_delay"_s)).hasMatch(), 2000);
        const double median = delay.match(label(u"bridge_stamp_delay"_s)).captured(1).toDouble();
        QVERIFY2(median >= 200 && median < 300, qPrintable(label(u"bridge_stamp_delay"_s)));
        QTRY_VERIFY_WITH_TIMEOUT(label(u"bridge_echo_delay"_s).contains(u" ms median, "_s), 2000);
        QVERIFY(label(u"bridge_robot_wrench"_s).startsWith(u"force.z 0.5 N, "_s));
        QVERIFY(label(u"bridge_arrivals"_s).startsWith(u"every "_s));

        QLabel *warning = find<QLabel>(u"bridge_passivity_warning"_s);
        QTRY_VERIFY_WITH_TIMEOUT(warning->isVisible(), 3000);
        // At a glance, above the scroll area: the header says it (the window's status bar shows
        // loopText(), tst_windowlayout).
        QTRY_COMPARE(m_panel->loopState(), BridgePanel::LoopState::Generating);
        QVERIFY(label(u"bridge_loop_state"_s).contains(u"Loop generating energy"_s));
        QCOMPARE(m_panel->loopText(), u"Loop generating energy: see Passivity below"_s);
        for (const QString &advice : {u"lower the gain"_s, u"raise M_adm"_s, u"cut the delay"_s})
            QVERIFY2(warning->text().contains(advice), qPrintable(warning->text()));
        QVERIFY2(label(u"bridge_energy"_s).startsWith(u"Bad: generating energy in contact"_s),
                 qPrintable(label(u"bridge_energy"_s)));
        QVERIFY(find<QCustomPlot>(u"bridge_energy_plot"_s)->graph(0)->dataCount() > 2);

        // Held still (the knob has settled): nothing more is generated; once the rise has
        // left the window and the hold is over, the warning goes.
        QTRY_VERIFY_WITH_TIMEOUT(!warning->isVisible(), 6000);
        QTRY_COMPARE(m_panel->loopState(), BridgePanel::LoopState::Passive);
        m_robot.stop();
        expectTauExt(0);
    }

    void topicAndRateChangeLive()
    {
        // A new topic reopens the endpoints: the twist goes out under its new name.
        QLineEdit *twist = find<QLineEdit>(u"bridge_topic_twist"_s);
        twist->setText(u"/arm/twist"_s);
        Q_EMIT twist->editingFinished();
        QVERIFY(m_panel->isRunning());
        QCOMPARE(m_panel->settings().topics.twist, std::string("/arm/twist"));
        QTRY_VERIFY_WITH_TIMEOUT(hasPublication("rt/arm/twist"), 10000);

        // The unstamped twist, off until named: then geometry_msgs/Twist goes out too.
        QLineEdit *unstamped = find<QLineEdit>(u"bridge_topic_twist_unstamped"_s);
        QCOMPARE(unstamped->text(), QString());
        QVERIFY(!hasPublication("rt/haptic_twist"));
        unstamped->setText(u"/haptic_twist"_s);
        Q_EMIT unstamped->editingFinished();
        QCOMPARE(m_panel->settings().topics.twistUnstamped, std::string("/haptic_twist"));
        QTRY_VERIFY_WITH_TIMEOUT((m_peer->take(), !m_peer->unstampedTwists.empty()), 10000);

        // The rate, at once: 10 Hz gives about 10 joint states a second.
        find<QDoubleSpinBox>(u"bridge_rate"_s)->setValue(10);
        QTest::qWait(300);
        m_peer->take();
        m_peer->clear();
        QTest::qWait(1000);
        m_peer->take();
        QVERIFY2(m_peer->joints.size() >= 5 && m_peer->joints.size() <= 15,
                 qPrintable(QString::number(m_peer->joints.size())));
    }

    void badInputIsRefusedAndKeepsTheSettings()
    {
        const bridge::BridgeSettings before = m_panel->settings();
        QLineEdit *pose = find<QLineEdit>(u"bridge_topic_pose"_s);
        pose->setText(u"/9pose"_s);
        Q_EMIT pose->editingFinished();
        QCOMPARE(label(u"bridge_status"_s),
                 u"Not applied: pose topic: '/9pose' is not a ROS topic name (letters, digits "
                 u"and '_' between single '/', not starting with a digit)."_s);
        QVERIFY(m_panel->settings() == before);
        QVERIFY(m_panel->isRunning());
        pose->setText(QString::fromStdString(before.topics.pose));
        Q_EMIT pose->editingFinished();
    }

    void profileSettingsShownAndApplied()
    {
        bridge::BridgeSettings s;
        s.feedback.gain = 0.12345678; // more digits than the box shows: kept on other edits
        s.feedback.limit = 0.3;
        s.domainId = 5; // no part of a profile: the panel keeps its own
        m_panel->setSettings(s);
        QCOMPARE(m_panel->settings().domainId, kDomain);
        QCOMPARE(find<QDoubleSpinBox>(u"bridge_gain"_s)->value(), 0.1235);
        QCOMPARE(find<QLineEdit>(u"bridge_topic_twist"_s)->text(), u"/hatpic/twist"_s);
        QVERIFY(m_panel->isRunning());
        find<QDoubleSpinBox>(u"bridge_stale"_s)->setValue(0.4);
        QCOMPARE(m_panel->settings().feedback.gain, 0.12345678);
        QCOMPARE(m_panel->settings().feedback.staleAfter, 0.4);
        startRobot(1);
        expectTauExt(0.12345678);
    }

    // The enable switch's local half (ros.md § Enable switch): released, τ_ext and the twist
    // are 0; engaged again, both come back.
    void engagedButtonReleases()
    {
        auto *engaged = find<QPushButton>(u"bridge_engaged"_s);
        QVERIFY(engaged->isChecked());
        const double tau = m_deviceTauExt; // the robot of the test before pushes
        QVERIFY(tau > 0.1);
        engaged->click();
        QCOMPARE(engaged->text(), u"Released"_s);
        expectTauExt(0);
        QTest::qWait(100);
        const auto &twists = twistsOver(200);
        QVERIFY(!twists.empty());
        for (const auto &t : twists)
            QCOMPARE(t.a[0], 0.0);
        engaged->click();
        QCOMPARE(engaged->text(), u"Engaged"_s);
        expectTauExt(tau);
    }

    // The knob's axis chosen in the panel (ros.md § Choosing the knob's axis): this knob is
    // held out of its dead zone, so the choice waits, and the panel says for what.
    void axisChosenWaitsForTheDeadZone()
    {
        auto *axis = find<QComboBox>(u"bridge_axis"_s);
        QVERIFY(axis->isEnabled());
        QCOMPARE(axis->currentText(), u"linear.x"_s);
        QTRY_COMPARE(label(u"bridge_axis_state"_s), u"Feels force.z"_s);
        axis->setFocus();
        QTest::keyClick(axis, Qt::Key_Down); // as a user picks linear.y
        QTRY_COMPARE(label(u"bridge_axis_state"_s),
                     u"Drives linear.x; linear.y once the knob rests in its dead zone"_s);
        QCOMPARE(axis->currentText(), u"linear.y"_s);
        QTest::qWait(300);
        QCOMPARE(axis->currentText(), u"linear.y"_s);
        const auto &twists = twistsOver(200);
        QVERIFY(!twists.empty());
        for (const auto &t : twists)
            QVERIFY(t.a[0] != 0 && t.a[1] == 0); // still x: the knob never rested
        QTest::keyClick(axis, Qt::Key_Up);
        QTRY_COMPARE(label(u"bridge_axis_state"_s),
                     u"Drives linear.x; feels force.x once the knob rests in its dead zone"_s);
    }

    // τ_ext as the panel words it: one knob's, or every knob's on a board (ros.md § A board's
    // knobs); the whole wrench and the warning of a robot sending on another component.
    void figuresAsWorded()
    {
        using bridgeform::torquesText;
        QCOMPARE(torquesText({0.077, 0.1, 0.2, 0.3}, 1), u"0.077 N·m"_s);
        QCOMPARE(torquesText({0.077, 0, 0.077, -0.077}, 4),
                 u"0.077 N·m; knobs 2–4: 0, 0.077, -0.077 N·m"_s);
        QCOMPARE(torquesText({0, -0.5, 0, 0}, 2), u"0 N·m; knob 2: -0.5 N·m"_s);
        QCOMPARE(bridgeform::wrenchText({NAN, NAN, NAN, NAN, NAN, NAN}),
                 u"force – – – N, torque – – – N·m"_s);
        QCOMPARE(
            bridgeform::otherComponentWarning({0, 0, 0, 0, 0, -0.25}, bridge::Component{false, 2}),
            u"force.z stays 0 while the robot sends torque.z = -0.25 N·m: is the component "
            u"right?"_s);
    }

    void disableLeavesZero()
    {
        find<QCheckBox>(u"bridge_enable"_s)->click();
        QVERIFY(!m_panel->isRunning());
        QCOMPARE(label(u"bridge_status"_s), u"Off"_s);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(m_deviceTauExt) < kTauExtTolerance, 5000);
        m_robot.stop();
        QVERIFY(!find<QComboBox>(u"bridge_axis"_s)->isEnabled()); // a choice needs a bridge
        QVERIFY(!find<QLabel>(u"bridge_axis_state"_s)->isVisible());
    }

    // hatpic-tuner --bridge: the panel picks the ROS and starts as Enable would; a ROS that
    // does not exist is refused, saying so, and nothing starts.
    void startOnPicksTheRosAndStarts()
    {
        QVERIFY(!m_panel->isRunning());
        QVERIFY(!m_panel->startOn(3));
        QVERIFY(!m_panel->isRunning());
        QVERIFY2(label(u"bridge_status"_s).contains(u"ROS 3 is not built"_s),
                 qPrintable(label(u"bridge_status"_s)));
        QVERIFY(m_panel->startOn(2));
        QVERIFY(m_panel->isRunning());
        QVERIFY(find<QCheckBox>(u"bridge_enable"_s)->isChecked());
        QCOMPARE(find<QComboBox>(u"bridge_ros"_s)->currentData().toInt(), 2);
        QTRY_VERIFY_WITH_TIMEOUT((m_peer->take(), m_peer->twists.size() >= 5), 10000);
        m_panel->setBridgeEnabled(false);
        QVERIFY(!m_panel->isRunning());
    }

    void cleanupTestCase()
    {
        m_panel.reset();
        m_peer.reset();
        m_client.disconnectDevice();
    }

private:
    template<typename T> T *find(const QString &name)
    {
        T *widget = m_panel->findChild<T *>(name);
        if (!widget)
            qFatal("no widget %s", qPrintable(name));
        return widget;
    }
    QString label(const QString &name) { return find<QLabel>(name)->text(); }
    //! The twists the test node receives in the next `ms` (what came before is dropped).
    const std::vector<hatpic::test::VectorsGot> &twistsOver(int ms)
    {
        m_peer->take();
        m_peer->clear();
        QTest::qWait(ms);
        m_peer->take();
        return m_peer->twists;
    }

    //! Wrenches at 50 Hz; stamped `stampAge` seconds before they are sent (0: no stamp).
    void startRobot(double value, double stampAge = 0)
    {
        m_robotValue = value;
        m_robot.disconnect();
        connect(&m_robot, &QTimer::timeout, this, [this, stampAge] {
            const double wall = double(QDateTime::currentMSecsSinceEpoch()) * 1e-3;
            m_peer->publishWrench(m_robotValue, 0, stampAge > 0 ? wall - stampAge : 0);
        });
        m_robot.start(20);
    }

    // τ_ext reaches the device's telemetry and the panel's readout.
    void expectTauExt(double tau)
    {
        QTRY_VERIFY2_WITH_TIMEOUT(std::abs(m_deviceTauExt - tau) < kTauExtTolerance,
                                  qPrintable(QString::number(m_deviceTauExt)), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(label(u"bridge_tau_ext"_s),
                                  QString::number(tau, 'g', 4) + u" N·m"_s, 2000);
    }

    bool hasPublication(const std::string &topic)
    {
        const auto p = m_peer->publications();
        return std::any_of(p.begin(), p.end(), [&](const auto &e) { return e.topic == topic; });
    }

    hatpic::test::LoopbackDds m_loopback; // first: before the session thread starts
    DeviceClient m_client;
    std::unique_ptr<RosTestPeer> m_peer;
    std::unique_ptr<BridgePanel> m_panel;
    QTimer m_robot;
    double m_robotValue = 0;
    double m_deviceTauExt = std::numeric_limits<double>::quiet_NaN();
};

QTEST_MAIN(TestBridgePanel)
#include "tst_bridgepanel.moc"
