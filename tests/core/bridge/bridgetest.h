// The bridge over real Cyclone DDS on loopback, against the in-process simulated joystick: what
// its tests share (tst_bridge, tst_bridgecontrol). A knob held at a known angle, a Bridge on it
// and a test node built as rmw_cyclonedds builds one, in the test's own DDS domain.
#pragma once

#include "rostestpeer.h"

#include "bridge/bridge.h"
#include "session/deviceclient.h"
#include "simulatoroptions.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QObject>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <memory>

namespace hatpic::test {

//! The base of the bridge's test classes: its initTestCase() connects the knob and starts the
//! bridge and the test node in `domain`.
class BridgeTest : public QObject
{
    Q_OBJECT
public:
    explicit BridgeTest(int domain) : kDomain(domain) {}

private Q_SLOTS:
    void initTestCase()
    {
        registerSessionMetaTypes();
        QVERIFY(connectKnob(m_client, kHeldAngle, m_deviceTauExt, &m_deviceTheta));

        bridge::BridgeSettings settings;
        settings.domainId = kDomain;
        settings.topics.wrenchUnstamped = "/robot/wrench";
        settings.topics.twistUnstamped = "/haptic_twist";
        settings.topics.jointJog = "/servo_node/delta_joint_cmds";
        m_peer = std::make_unique<RosTestPeer>(kDomain);
        QCOMPARE(m_bridge.start(settings), QString());
        QVERIFY(m_peer->isValid());
    }

protected:
    const int kDomain;                               //!< this test's own DDS domain
    static constexpr double kHeldAngle = 0.5;        //!< the simulated hand's target [rad]
    static constexpr double kTauExtTolerance = 1e-6; //!< τ_ext travels as float32 [N·m]

    static double wallNow() { return double(QDateTime::currentMSecsSinceEpoch()) * 1e-3; }

    //! Connects `client` to an in-process simulated knob whose virtual hand holds `angle`;
    //! its telemetry's τ_ext (and θ) are copied into `tauExt` (and `theta`). True once
    //! connected.
    bool connectKnob(DeviceClient &client, double angle, double &tauExt, double *theta = nullptr)
    {
        return connectKnob(client, HandInput{HandInput::Kind::VirtualHand, 0, 0, 0, 0, angle},
                           tauExt, theta);
    }
    //! … whose operator input is `hand`.
    bool connectKnob(DeviceClient &client, const HandInput &hand, double &tauExt,
                     double *theta = nullptr)
    {
        SimulatedDevice::Config config;
        config.hand = hand;
        // These tests measure the bridge and its observer against a plain knob: the device's
        // passivity controller (tst_passivity, tst_teleoploop) off. On, the deficit the ±limit
        // pushes of wrenchBecomesTauExt leave in its tank damps robotSideMeasured's push, which
        // then creeps on past the observer's approach window.
        config.passivity = PassivityParams::off();
        connect(&client, &DeviceClient::samplesReady, this, [&tauExt, theta](const SampleBatch &b) {
            if (b.isEmpty())
                return;
            tauExt = b.last().tau_ext;
            if (theta)
                *theta = b.last().theta;
        });
        client.connectDevice(test::simulatorOptions(config));
        QElapsedTimer waited;
        waited.start();
        while (client.state() != SessionState::Connected && waited.elapsed() < 10000)
            QTest::qWait(20);
        client.setHostParams(HostParams{});
        return client.state() == SessionState::Connected;
    }

    bool allTwistsZero() const
    {
        return std::all_of(m_peer->twists.begin(), m_peer->twists.end(),
                           [](const auto &t) { return t.a[0] == 0.0; }) &&
               std::all_of(m_peer->jogs.begin(), m_peer->jogs.end(),
                           [](const auto &j) { return j.velocities.at(0) == 0.0; });
    }
    double lastTwist()
    {
        m_peer->take();
        return m_peer->twists.empty() ? 0.0 : m_peer->twists.back().a[0];
    }

    bool feedbackSeen(double tau)
    {
        m_peer->take();
        return !m_peer->feedbacks.empty() &&
               std::abs(m_peer->feedbacks.back().b[2] - tau) < kTauExtTolerance;
    }

    LoopbackDds m_loopback; // first: before the session thread starts
    DeviceClient m_client;
    bridge::Bridge m_bridge{m_client};
    std::unique_ptr<RosTestPeer> m_peer;
    double m_deviceTauExt = 0;
    double m_deviceTheta = 0;
};

} // namespace hatpic::test
