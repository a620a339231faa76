// hatpic-robot-sim's status line (docs/teleop.md): the documented form, and a value decaying at
// rest printed as 0, never as a denormal (issue 27: "v -1.745e-257").
#include "robotsim/robotsimulator.h"

#include <QTest>

#include <limits>

using namespace hatpic::robot;

class TestRobotSimStatus : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void documentedForm()
    {
        RobotSimulator::Status s;
        s.x = 0.05625;
        s.v = -1.38e-5;
        s.vRef = 0.03145;
        s.wallForce = 1.25;
        s.twistsIn = 529;
        s.wrenchesOut = 1154;
        s.posesOut = 1154;
        s.stale = false;
        QCOMPARE(QString::fromStdString(s.line()),
                 QStringLiteral("x 0.05625 m, v -1.38e-05 m/s, v_ref 0.03145 m/s, F_e 1.25 N | "
                                "twists in 529, wrenches out 1154, poses out 1154, dropped 0"));
        s.stale = true;
        s.overruns = 3;
        QVERIFY(QString::fromStdString(s.line()).endsWith(
            QStringLiteral(", stale, dropped 0, steps late 3")));
    }

    void negligibleIsZero()
    {
        RobotSimulator::Status s;
        s.v = -1.745e-257;
        s.x = std::numeric_limits<double>::denorm_min();
        s.vRef = -0.0;
        s.wallForce = 5e-13;
        const QString line = QString::fromStdString(s.line());
        QVERIFY2(line.startsWith(QStringLiteral("x 0 m, v 0 m/s, v_ref 0 m/s, F_e 0 N |")),
                 qPrintable(line));
        s.v = 2e-12; // still something
        QVERIFY(QString::fromStdString(s.line()).contains(QStringLiteral("v 2e-12 m/s")));
    }
};

QTEST_GUILESS_MAIN(TestRobotSimStatus)
#include "tst_robotsimstatus.moc"
