// The stability map against the real programs: a few cells of `hatpicctl teleop-map` (one-way
// delays 0, 0.04 and 0.15 s at robot.md's gain) run as a user runs the loop — hatpic-sim
// --hand const:0.05, hatpic-bridge --component force.x --gain 0.02, hatpic-robot-sim --delay D
// on loopback over ROS 2 — and compared with the in-process loop's cell for the same settings:
// settled or not alike, and where a settled loop rests (θ, τ_ext, x) alike. Both run the
// device's passivity controller as hatpic-sim does, with its defaults (on; the map's cells
// with it off are compared with programs built without it: docs/teleop.md § The stability
// map).
#include "teleop/loopsimulation.h"
#include "teleoploop.h"

#include <QTest>

#include <cmath>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

constexpr double kRun = 12;                                  //!< seconds of each real run
constexpr double kEncoderStep = 2 * 3.14159265358979 / 4096; //!< one servo count [rad]

} // namespace

class TestTeleopMapAgreement : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cellAgreesWithThePrograms_data();
    void cellAgreesWithThePrograms();

private:
    int m_domain = 0;
    QTemporaryDir m_dir;
    int m_link = 0;
};

void TestTeleopMapAgreement::initTestCase()
{
    m_domain = 20 + int((QCoreApplication::applicationPid() + 101) % 200);
    QVERIFY(m_dir.isValid());
}

void TestTeleopMapAgreement::cellAgreesWithThePrograms_data()
{
    QTest::addColumn<double>("delay");
    QTest::newRow("0 s") << 0.0;
    QTest::newRow("40 ms") << 0.04;
    QTest::newRow("150 ms") << 0.15;
}

void TestTeleopMapAgreement::cellAgreesWithThePrograms()
{
    QFETCH(double, delay);

    // The map's cell: the same loop, in process, for as long as the real one runs.
    teleop::LoopConfig config;
    config.robot.faults.delay = delay;
    config.duration = kRun;
    const teleop::LoopResult cell = teleop::LoopSimulation::run(config);
    QVERIFY(cell.contact);

    LoopSetup setup;
    setup.simPath = QStringLiteral(HATPIC_SIM_PATH);
    setup.bridgePath = QStringLiteral(HATPIC_BRIDGE_PATH);
    setup.robotPath = QStringLiteral(HATPIC_ROBOT_SIM_PATH);
    setup.domain = m_domain;
    setup.env = loopEnvironment(QProcessEnvironment::systemEnvironment(), m_domain);
    setup.link = m_dir.filePath(u"knob-%1"_s.arg(++m_link));
    setup.hand = u"const:0.05"_s;
    setup.gain = config.feedback.gain;
    setup.robotArguments = {u"--delay"_s, QString::number(delay)};
    setup.nodeName = "tst_teleopmapagreement";
    Loop loop;
    const QString why = startLoop(loop, setup);
    QVERIFY2(why.isEmpty(), qPrintable(why));
    spinFor(kRun);
    const double now = monotonic();
    const Stats theta = statsOf(loop.watcher.window(&Watcher::m_theta, now - 2, now));
    const Stats tau = statsOf(loop.watcher.window(&Watcher::m_tau, now - 2, now));
    const Stats x = statsOf(loop.watcher.window(&Watcher::m_x, now - 2, now));
    QVERIFY2(theta.n > 50 && tau.n > 50 && x.n > 50, loop.bridge->output().constData());

    // Settled as the map judges it: every θ of the last 2 s within 0.003 rad of θ_eq.
    const bool settled = theta.min >= cell.thetaEq - teleop::LoopResult::kBand &&
                         theta.max <= cell.thetaEq + teleop::LoopResult::kBand;
    const QString report =
        QStringLiteral("delay %1: programs θ %2 … %3 (mean %4), τ_ext %5, x %6; map settled %7, "
                       "θ %8, p2p %9, τ_ext %10, x %11")
            .arg(delay)
            .arg(theta.min)
            .arg(theta.max)
            .arg(theta.mean)
            .arg(tau.mean)
            .arg(x.mean)
            .arg(cell.settled)
            .arg(cell.thetaRest)
            .arg(cell.p2p)
            .arg(cell.tauExtRest)
            .arg(cell.xRest);
    qInfo().noquote() << report;
    QCOMPARE(settled, cell.settled);
    if (settled) {
        QVERIFY2(std::abs(theta.mean - cell.thetaRest) < 1.5 * kEncoderStep, qPrintable(report));
        QVERIFY2(std::abs(tau.mean - cell.tauExtRest) < 0.002, qPrintable(report));
        QVERIFY2(std::abs(x.mean - cell.xRest) < 5e-4, qPrintable(report));
    } else {
        // Both keep swinging, by a like amount (the real programs: 0.69 rad at 150 ms).
        QVERIFY2(theta.spread() > 0.5 * cell.p2p && theta.spread() < 2 * cell.p2p,
                 qPrintable(report));
    }
}

QTEST_GUILESS_MAIN(TestTeleopMapAgreement)
#include "tst_teleopmapagreement.moc"
