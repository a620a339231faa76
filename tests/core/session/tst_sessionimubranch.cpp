// The session with the published IMU branch's board: the simulated one behind a real
// pseudo-terminal, found by auto-detection; four-axis samples with the tilt; knob 1's feedback
// leaves knobs 2–4 without force, and each knob feels its own.
#include "model/reference.h"
#include "model/stiffness.h"
#include "session/devicesession.h"
#include "sessionharness.h"
#include "sim/simulatorhost.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

class TestSessionImuBranch : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void fourKnobsAndTheTiltArrive()
    {
        SimulatedDevice::Config config;
        config.board = SimulatedDevice::Board::ImuBranch;
        config.otherHands[1] = *HandInput::parse(u"const:0.05"_s); // knob 3
        config.roll = 0.3;
        config.pitch = -0.2;
        SimulatorHost host(config);
        const QString error = host.start();
        QVERIFY2(error.isEmpty(), qPrintable(error));

        Harness h;
        QSignalSpy infos(&h.session, &DeviceSession::deviceInfoChanged);
        ConnectOptions o;
        o.port = host.slavePath(); // auto-detection: it listens at 115200 first
        h.session.connectDevice(o);
        QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
        QCOMPARE(h.session.deviceInfo().protocol, WireProtocol::Legacy);
        QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() >= 8, kConnectTimeoutMs);

        // The board shows what it is in its frames: the info says so once.
        const DeviceInfo info = h.session.deviceInfo();
        QCOMPARE(info.axes, quint8(4));
        QVERIFY(info.tilt);
        QCOMPARE(info.firmware, u"published IMU branch (legacy)"_s);
        QVERIFY(!infos.isEmpty());
        QCOMPARE(infos.last().first().value<DeviceInfo>().axes, quint8(4));

        const Sample last = h.samples.last();
        QCOMPARE(last.axes(), 4);
        QVERIFY(std::abs(last.roll() - 0.3) < 1e-3);
        QVERIFY(std::abs(last.pitch() + 0.2) < 1e-3);
        QVERIFY2(last.axis(3)->theta > 0.02, qPrintable(QString::number(last.axis(3)->theta)));
        QVERIFY(std::abs(last.theta) < 0.01);
        QVERIFY(std::abs(last.axis(2)->theta) < 0.01 && std::abs(last.axis(4)->theta) < 0.01);
        // Knob 3 is estimated as knob 1 would be: the spring's torque, its own reference.
        const AxisSample &knob3 = *last.axis(3);
        QCOMPARE(knob3.tau_rec, recenteringTorque(DeviceParams{}, knob3.theta));
        QVERIFY(knob3.tau_rec != 0);
        QVERIFY(std::isnan(knob3.omega) && std::isnan(knob3.tau));
        QCOMPARE(knob3.v_ref, referenceVelocity(HostParams{}, DeviceParams{}, knob3.theta));
        QVERIFY(knob3.p_ref != 0 || knob3.v_ref == 0);
        QVERIFY(std::abs(knob3.tau_total - knob3.tau_rec) < 1e-12);
        QCOMPARE(knob3.tau_ext, 0.0);

        // Feedback for knob 1 only: B, C and D say "no force" (1000), so knobs 2 and 4 stay.
        h.session.setFeedback(0.1);
        QTest::qWait(1200);
        const std::vector<double> angles = host.device().knobAngles();
        QVERIFY2(std::abs(angles[0]) > 0.01, qPrintable(QString::number(angles[0])));
        QVERIFY2(std::abs(angles[1]) < 0.01, qPrintable(QString::number(angles[1])));
        QVERIFY2(std::abs(angles[3]) < 0.01, qPrintable(QString::number(angles[3])));
        h.session.setFeedback(0);
        h.session.disconnectDevice();
    }

    void eachKnobFeelsItsOwnFeedback()
    {
        SimulatedDevice::Config config;
        config.board = SimulatedDevice::Board::ImuBranch;
        SimulatorHost host(config);
        Harness h;
        QVERIFY(connectTo(host, h));
        QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(h.session.deviceInfo().axes, quint8(4), kConnectTimeoutMs);

        // Knobs 2 and 4 pushed opposite ways, 1 and 3 left alone.
        h.session.setFeedback(AxisTorques{0.0, 0.1, 0.0, -0.1});
        QTest::qWait(1200);
        const std::vector<double> angles = host.device().knobAngles();
        QVERIFY2(angles[1] > 0.01, qPrintable(QString::number(angles[1])));
        QVERIFY2(angles[3] < -0.01, qPrintable(QString::number(angles[3])));
        QVERIFY2(std::abs(angles[0]) < 0.01, qPrintable(QString::number(angles[0])));
        QVERIFY2(std::abs(angles[2]) < 0.01, qPrintable(QString::number(angles[2])));
        // The samples say what each knob was sent, after the wire's rounding.
        const legacy::Conversion conversion = h.session.options().legacy;
        const double sent = conversion.fieldToFeedback(conversion.feedbackToField(0.1));
        const Sample last = h.samples.last();
        QCOMPARE(last.tau_ext, 0.0);
        QCOMPARE(last.axis(2)->tau_ext, sent);
        QCOMPARE(last.axis(3)->tau_ext, 0.0);
        QCOMPARE(last.axis(4)->tau_ext, -sent);

        // Knob 1's setter leaves the others' as they were.
        h.session.setFeedback(0.05);
        QTest::qWait(300);
        QCOMPARE(h.samples.last().axis(2)->tau_ext, sent);
        QVERIFY(h.samples.last().tau_ext > 0.04);
        h.session.setFeedback(AxisTorques{});
        QTest::qWait(300);
        QCOMPARE(h.samples.last().axis(4)->tau_ext, 0.0);
        h.session.disconnectDevice();
    }

    void aSingleKnobStaysOneAxis()
    {
        SimulatedDevice::Config config;
        config.protocol = WireProtocol::Legacy;
        SimulatorHost host(config);
        Harness h;
        QVERIFY(connectTo(host, h));
        QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() >= 3, kConnectTimeoutMs);
        QCOMPARE(h.session.deviceInfo().axes, quint8(1));
        QVERIFY(!h.session.deviceInfo().tilt);
        QCOMPARE(h.samples.last().axes(), 1);
        QVERIFY(!h.samples.last().board);
        h.session.disconnectDevice();
    }

private:
    //! Starts `host` and has `h`'s session connect to it, auto-detecting (it listens at
    //! 115200 first). False when the host did not start.
    static bool connectTo(SimulatorHost &host, Harness &h)
    {
        if (!host.start().isEmpty())
            return false;
        ConnectOptions o;
        o.port = host.slavePath();
        h.session.connectDevice(o);
        return true;
    }
};

QTEST_GUILESS_MAIN(TestSessionImuBranch)
#include "tst_sessionimubranch.moc"
