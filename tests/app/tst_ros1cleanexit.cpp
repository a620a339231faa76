// hatpic-bridge --ros 1 and hatpic-robot-sim --ros 1, run as real processes against a real
// roscore on loopback, stopped by SIGINT and by SIGTERM: a clean exit leaves nothing of the
// node on the master (issue 26, item 5) — no node in `rosnode list`, none of its publications
// (/rosout too), subscriptions or logger services — as a rospy node leaves it.
#include "roscore.h"

#include "sim/simulatorhost.h"

#include <QProcess>
#include <QTest>

#include <csignal>
#include <memory>

using namespace hatpic;
using hatpic::test::RosCore;
using namespace Qt::StringLiterals;

class TestRos1CleanExit : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QCOMPARE(m_core.start(), QString()); }

    void cleanExitUnregistersEverything_data()
    {
        QTest::addColumn<QString>("program");
        QTest::addColumn<int>("signal");
        QTest::addColumn<QString>("node");
        QTest::addColumn<QStringList>("expected"); //!< some of what it registers
        const QStringList bridge{u"provides /hatpic_bridge/get_loggers"_s,
                                 u"provides /hatpic_bridge/set_logger_level"_s,
                                 u"publishes /hatpic/twist"_s, u"publishes /rosout"_s,
                                 u"subscribes /wrench_estimation"_s};
        const QStringList robot{u"provides /hatpic_robot_sim/get_loggers"_s,
                                u"publishes /robot/pose"_s, u"publishes /rosout"_s,
                                u"subscribes /hatpic/twist"_s};
        QTest::newRow("bridge, SIGINT")
            << QStringLiteral(HATPIC_BRIDGE_PATH) << SIGINT << u"/hatpic_bridge"_s << bridge;
        QTest::newRow("bridge, SIGTERM")
            << QStringLiteral(HATPIC_BRIDGE_PATH) << SIGTERM << u"/hatpic_bridge"_s << bridge;
        QTest::newRow("robot sim, SIGINT")
            << QStringLiteral(HATPIC_ROBOT_SIM_PATH) << SIGINT << u"/hatpic_robot_sim"_s << robot;
        QTest::newRow("robot sim, SIGTERM")
            << QStringLiteral(HATPIC_ROBOT_SIM_PATH) << SIGTERM << u"/hatpic_robot_sim"_s << robot;
    }
    void cleanExitUnregistersEverything()
    {
        QFETCH(QString, program);
        QFETCH(int, signal);
        QFETCH(QString, node);
        QFETCH(QStringList, expected);
        std::unique_ptr<SimulatorHost> device;
        QStringList arguments{u"--ros"_s, u"1"_s};
        if (program == QStringLiteral(HATPIC_BRIDGE_PATH)) {
            device = std::make_unique<SimulatorHost>(SimulatedDevice::Config{});
            QCOMPARE(device->start(), QString());
            arguments << u"--port"_s << device->slavePath();
        }
        QProcess process;
        process.setProcessEnvironment(m_core.environment());
        process.start(program, arguments);
        QVERIFY(process.waitForStarted());

        // Registered: the node with its topics and roscpp's logger services.
        QString error;
        const auto holds = [&] {
            const QStringList now = m_core.registrations(node, &error);
            for (const QString &entry : expected) {
                if (!now.contains(entry))
                    return false;
            }
            return true;
        };
        QTRY_VERIFY2_WITH_TIMEOUT(
            holds(), qPrintable(error + u" | "_s + m_core.registrations(node).join(u", "_s)),
            15000);

        ::kill(pid_t(process.processId()), signal);
        QVERIFY(process.waitForFinished(10000));
        QCOMPARE(process.exitStatus(), QProcess::NormalExit);
        QCOMPARE(process.exitCode(), 0);
        // Nothing of it stays on the master (the unregistrations ran before the exit).
        const QStringList left = m_core.registrations(node, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY2(left.isEmpty(), qPrintable(left.join(u", "_s)));
    }

    void cleanupTestCase() { m_core.stop(); }

private:
    RosCore m_core;
};

QTEST_GUILESS_MAIN(TestRos1CleanExit)
#include "tst_ros1cleanexit.moc"
