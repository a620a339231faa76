// What one incoming ROS 2 sample may cost (issue 26, item 3): hatpic-bridge and
// hatpic-robot-sim as real processes on loopback Cyclone DDS, and a test node built as
// rmw_cyclonedds builds one (rostestpeer, without type information) that publishes on their
// inputs a sample with a 50 MB frame_id. Each program drops it (Cyclone DDS's MaxSampleSize in
// the configuration core/ros gives every domain), says so on stderr, stays small — its peak
// resident memory grows by far less than the sample — and goes on with the ordinary samples
// that follow.
#include "rostestpeer.h"

#include "ros/ros2/ros2node.h"
#include "sim/simulatorhost.h"

#include <QFile>
#include <QProcess>
#include <QTest>
#include <QTimer>

#include <cmath>
#include <csignal>
#include <functional>
#include <string>

using namespace hatpic;
using hatpic::test::RosTestPeer;
using namespace Qt::StringLiterals;

namespace {

constexpr int kDomain = 82;                     //!< this test's own DDS domain
constexpr std::size_t kHostileFrame = 50000000; //!< the oversize samples' frame_id [bytes]
constexpr int kHostileSamples = 3;
//! What the oversize samples may add to a program's peak resident memory [bytes]: a fraction
//! of one of them (without the bound each was received, reassembled and copied).
constexpr qint64 kAllowedGrowth = 16 * 1024 * 1024;
constexpr double kTauExtTolerance = 1e-6; //!< τ_ext travels as float32 [N·m]

//! A value of /proc/PID/status ("VmHWM", "VmRSS") [bytes]; -1 when not there.
qint64 procStatus(qint64 pid, const char *key)
{
    QFile file(u"/proc/"_s + QString::number(pid) + u"/status"_s);
    if (!file.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray prefix = QByteArray(key).append(':');
    for (const QByteArray &line : file.readAll().split('\n')) {
        if (line.startsWith(prefix))
            return line.mid(prefix.size()).trimmed().split(' ').first().toLongLong() * 1024;
    }
    return -1;
}

//! The newest count after `label` ("| wrenches ") in a program's status lines, read from its
//! stdout into `out`; -1 before the first line.
qint64 newestCount(QProcess &process, QByteArray &out, const QByteArray &label)
{
    out += process.readAllStandardOutput();
    const qsizetype at = out.lastIndexOf(label);
    if (at < 0)
        return -1;
    const QByteArray rest = out.mid(at + label.size());
    return rest.left(rest.indexOf(',')).toLongLong();
}

//! Sends kHostileSamples oversize samples through `send` (given their frame_id), 300 ms
//! apart; then `count()` (what the program took, from its status line) must not have changed
//! and its peak resident memory must have grown by less than kAllowedGrowth. Fails the test
//! otherwise.
void sendHostileSamples(const QProcess &process, const char *name,
                        const std::function<void(const std::string &)> &send,
                        const std::function<qint64()> &count)
{
    const qint64 taken = count();
    const qint64 peakBefore = procStatus(process.processId(), "VmHWM");
    QVERIFY(peakBefore > 0);
    const std::string hostile(kHostileFrame, 'x');
    for (int i = 0; i < kHostileSamples; ++i) {
        send(hostile);
        QTest::qWait(300);
    }
    QTest::qWait(1500);       // a status line after the last
    QCOMPARE(count(), taken); // none taken
    const qint64 peakAfter = procStatus(process.processId(), "VmHWM");
    qInfo("%s's peak resident memory: %lld kB before, %lld kB after %d samples of %zu bytes", name,
          peakBefore / 1024, peakAfter / 1024, kHostileSamples, kHostileFrame);
    QVERIFY2(peakAfter - peakBefore < kAllowedGrowth,
             qPrintable(QString::number(peakAfter - peakBefore)));
}

QProcessEnvironment domainEnvironment()
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(u"ROS_DOMAIN_ID"_s, QString::number(kDomain));
    return env;
}

} // namespace

class TestSampleSize : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        hatpic::test::confineDdsToLoopback();
        // The figure the test is about: far below the hostile frame, above every ordinary one.
        QVERIFY(ros::ros2::kMaxSampleBytes < kHostileFrame / 100);
        QVERIFY(ros::ros2::kMaxSampleBytes >= 4096);
    }

    void bridgeDropsAnOversizeWrench()
    {
        SimulatedDevice::Config config;
        config.hand = HandInput{HandInput::Kind::VirtualHand, 0, 0, 0, 0, 0.5};
        SimulatorHost host(config);
        QCOMPARE(host.start(), QString());
        RosTestPeer peer(kDomain);
        QVERIFY(peer.isValid());
        QProcess bridge;
        bridge.setProcessEnvironment(domainEnvironment());
        bridge.start(QStringLiteral(HATPIC_BRIDGE_PATH), {u"--port"_s, host.slavePath()});
        QVERIFY(bridge.waitForStarted());
        const auto feedbackIs = [&peer](double tau) {
            peer.take();
            return !peer.feedbacks.empty() &&
                   std::abs(peer.feedbacks.back().b[2] - tau) < kTauExtTolerance;
        };

        // Ordinary wrenches work: 0.5 N → 0.077 N·m.
        QTRY_VERIFY_WITH_TIMEOUT(peer.wrenchMatched(), 15000);
        QTimer robot;
        connect(&robot, &QTimer::timeout, this, [&] { peer.publishWrench(0.5); });
        robot.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(feedbackIs(0.077), 15000);
        robot.stop();
        QTRY_VERIFY_WITH_TIMEOUT(feedbackIs(0.0), 5000); // stale
        QByteArray out;
        QTest::qWait(1500); // a status line after the last ordinary wrench
        QVERIFY(newestCount(bridge, out, "| wrenches ") > 0);

        // The hostile samples (1 N): none may reach the bridge, so none is counted.
        sendHostileSamples(
            bridge, "hatpic-bridge",
            [&](const std::string &frame) { peer.publishWrench(1.0, 0, 0, frame); },
            [&] { return newestCount(bridge, out, "| wrenches "); });
        if (QTest::currentTestFailed())
            return;
        QVERIFY(feedbackIs(0.0));

        // And the ordinary ones that follow.
        robot.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(feedbackIs(0.077), 10000);
        robot.stop();
        // (The wrench's writer is best effort, as the published driver's: Cyclone DDS drops
        // such a sample without a word. A reliable writer's it reports: the robot sim's test.)
        ::kill(pid_t(bridge.processId()), SIGINT);
        QVERIFY(bridge.waitForFinished(10000));
        QCOMPARE(bridge.exitCode(), 0);
    }

    void robotSimDropsAnOversizeTwist()
    {
        RosTestPeer peer(kDomain);
        QVERIFY(peer.isValid());
        QProcess robot;
        robot.setProcessEnvironment(domainEnvironment());
        robot.start(QStringLiteral(HATPIC_ROBOT_SIM_PATH), {});
        QVERIFY(robot.waitForStarted());
        QByteArray out;
        const auto twistsIn = [&] { return newestCount(robot, out, "twists in "); };

        // Ordinary twists reach the robot (its status line counts them, once a second).
        QTimer knob;
        connect(&knob, &QTimer::timeout, this, [&] { peer.publishTwist(0.01); });
        knob.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(twistsIn() > 0, 15000);
        knob.stop();
        QTest::qWait(1500);
        const qint64 ordinary = twistsIn();

        sendHostileSamples(
            robot, "hatpic-robot-sim",
            [&](const std::string &frame) { peer.publishTwist(0.01, frame); }, twistsIn);
        if (QTest::currentTestFailed())
            return;

        knob.start(20);
        QTRY_VERIFY_WITH_TIMEOUT(twistsIn() > ordinary, 10000);
        knob.stop();
        // Cyclone DDS says so on stderr, once per sample of this reliable writer.
        const QByteArray err = robot.readAllStandardError();
        QCOMPARE(err.count("dropping oversize"), kHostileSamples);
        qInfo("%s", err.mid(err.indexOf("dropping oversize")).split('\n').first().constData());
        ::kill(pid_t(robot.processId()), SIGTERM);
        QVERIFY(robot.waitForFinished(10000));
        QCOMPARE(robot.exitCode(), 0);
    }
};

QTEST_GUILESS_MAIN(TestSampleSize)
#include "tst_samplesize.moc"
