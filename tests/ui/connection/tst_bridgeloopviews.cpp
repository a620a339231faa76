// The Bridge panel's robot side and passivity sections, real widgets offscreen, given the
// Bridge's statistics: each field's wording and units, "none" told apart from 0, and the
// passivity warning shown exactly while the observer warns, saying what to do.
#include "connection/passivityview.h"
#include "connection/robotsideview.h"
#include "plots/qcp.h"

#include <QLabel>
#include <QTest>

#include <limits>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

QString label(const QWidget &view, const QString &name)
{
    const auto *l = view.findChild<QLabel *>(name);
    return l ? l->text() : u"(no label "_s + name + u')';
}

} // namespace

class TestBridgeLoopViews : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void robotSideBeforeAnyWrench()
    {
        RobotSideView view;
        view.setStats({}, bridge::Component{});
        QCOMPARE(label(view, u"bridge_robot_wrench"_s), u"none yet"_s);
        QCOMPARE(label(view, u"bridge_stamp_delay"_s), u"– (none measured)"_s);
        QCOMPARE(label(view, u"bridge_echo_delay"_s), u"– (none measured)"_s);
        QCOMPARE(label(view, u"bridge_arrivals"_s),
                 u"every –; ≈ 0 lost (estimated from gaps), 0 pauses"_s);
    }

    void robotSideMeasured()
    {
        bridge::BridgeStats s;
        s.lastWrench = -1.25;
        s.timing.age = 0.012;
        s.timing.stampDelay = {0.3005, 0.31, 142};
        s.timing.echoDelay = {0.0022, 0.0031, 15};
        s.timing.interval = 0.005;
        s.timing.lost = 17;
        s.timing.pauses = 1;
        RobotSideView view;
        view.setStats(s, bridge::Component{true, 2});
        QCOMPARE(label(view, u"bridge_robot_wrench"_s), u"torque.z -1.25 N·m, 12.0 ms ago"_s);
        QCOMPARE(label(view, u"bridge_stamp_delay"_s),
                 u"300.5 ms median, 310.0 ms p95 (142 stamped)"_s);
        QCOMPARE(label(view, u"bridge_echo_delay"_s), u"2.2 ms median, 3.1 ms p95 (15 changes)"_s);
        QCOMPARE(label(view, u"bridge_arrivals"_s),
                 u"every 5.0 ms; ≈ 17 lost (estimated from gaps), 1 pauses"_s);
        s.timing.stampDelay = {};
        s.timing.unstamped = 3;
        view.setStats(s, bridge::Component{false, 0});
        QCOMPARE(label(view, u"bridge_stamp_delay"_s), u"– (the wrenches carry no stamp)"_s);
        QVERIFY(label(view, u"bridge_robot_wrench"_s).startsWith(u"force.x -1.25 N, "_s));
    }

    void passivityWarning_data()
    {
        QTest::addColumn<bool>("inContact");
        QTest::addColumn<bool>("warning");
        QTest::addColumn<QString>("energy");
        // What is good and what is bad, in words first (issue 27).
        QTest::newRow("free") << false << false
                              << u"Good: no contact (|τ_ext| ≤ 0.005 N·m), nothing to "
                                 "dissipate. E 1.00 mJ."_s;
        QTest::newRow("passive contact")
            << true << false
            << u"Good: passive in contact. E 1.00 mJ; generated lately -0.40 mJ (up to 0.50 mJ "
               "is fine)."_s;
        QTest::newRow("generating")
            << true << true
            << u"Bad: generating energy in contact. E 1.00 mJ; generated lately -0.40 mJ (more "
               "than 0.50 mJ is unstable)."_s;
    }
    void passivityWarning()
    {
        QFETCH(bool, inContact);
        QFETCH(bool, warning);
        QFETCH(QString, energy);
        PassivityView view;
        view.show();
        analysis::PassivityObserver::State s;
        s.samples = 10;
        s.time = 3;
        s.energy = 1e-3;
        s.generated = inContact ? -0.4e-3 : 0;
        s.inContact = inContact;
        s.warning = warning;
        view.setState(s);
        QCOMPARE(label(view, u"bridge_energy"_s), energy);
        QCOMPARE(view.isWarning(), warning);
        QLabel *text = view.findChild<QLabel *>(u"bridge_passivity_warning"_s);
        QCOMPARE(text->isVisible(), warning);
        for (const QString &advice : {u"lower the gain"_s, u"raise M_adm"_s, u"cut the delay"_s})
            QVERIFY2(text->text().contains(advice), qPrintable(text->text()));
        QCOMPARE(view.text().contains(u"lower the gain"_s), warning);
    }

    void controllerSaysIdleOrDamping_data()
    {
        QTest::addColumn<bool>("reported");
        QTest::addColumn<bool>("damping");
        QTest::addColumn<bool>("atRest");
        QTest::addColumn<QString>("line");
        QTest::newRow("no capability")
            << false << false << false
            << u"Controller: none reported — this device's telemetry carries no τ_pc (no "
               "passivity capability); only the observer below watches."_s;
        QTest::newRow("idle") << true << false << false
                              << u"Controller: idle — nothing to damp. Took out 1.25 mJ; "
                                 "reserve 20.00 mJ."_s;
        QTest::newRow("damping")
            << true << true << false
            << u"Controller: damping — β up to 0.420 N·m·s/rad (τ_pc -0.0210 N·m). Took out "
               "1.25 mJ; reserve 0.00 mJ."_s;
        // Issue 35: damping a knob that rests is said in words, with what to do.
        QTest::newRow("damping at rest")
            << true << true << true
            << u"Controller: damping at rest — the knob rests, yet the controller damps it in "
               "87 % of the samples (β up to 0.420 N·m·s/rad), so it feels heavier than tuned: "
               "the loop does not rest on its own at this gain and delay. Lower the gain, raise "
               "M_adm or cut the delay. Took out 1.25 mJ; reserve 0.00 mJ."_s;
    }
    void controllerSaysIdleOrDamping()
    {
        QFETCH(bool, reported);
        QFETCH(bool, damping);
        QFETCH(bool, atRest);
        QFETCH(QString, line);
        PassivityView view;
        view.show();
        analysis::PassivityObserver::State s;
        view.setState(s); // no sample yet: nothing said of the controller
        QVERIFY(!view.findChild<QLabel *>(u"bridge_passivity_controller"_s)->isVisible());
        s.samples = 10;
        s.time = 3;
        s.controllerReported = reported;
        s.damping = damping;
        s.dampingCoefficient = damping ? 0.42 : 0;
        s.controllerTorque = damping ? -0.021 : 0;
        s.dissipated = reported ? 1.25e-3 : 0;
        s.reserve = damping ? 0.0 : 0.02;
        s.atRest = atRest;
        s.restDampedShare = atRest ? 0.87 : 0;
        s.dampedAtRest = atRest && damping;
        view.setState(s);
        QCOMPARE(label(view, u"bridge_passivity_controller"_s), line);
        QVERIFY(view.text().startsWith(line));
    }

    void energyPlotKeepsItsSpan()
    {
        PassivityView view;
        auto *plot = view.findChild<QCustomPlot *>(u"bridge_energy_plot"_s);
        QVERIFY(plot);
        analysis::PassivityObserver::State s;
        s.samples = 1;
        for (int i = 0; i <= 400; ++i) { // 80 s at the panel's 5 Hz
            s.time = i * 0.2;
            s.energy = i * 1e-5;
            view.setState(s);
            view.setState(s); // the same sample again: no second point
        }
        QCOMPARE(plot->graph(0)->dataCount(), int(PassivityView::kSpan / 0.2) + 1);
        QCOMPARE(plot->graph(0)->data()->at(plot->graph(0)->dataCount() - 1)->value, 4.0); // mJ
        QCOMPARE(plot->graph(0)->data()->at(plot->graph(0)->dataCount() - 1)->key, 0.0);
        s.time = 0.1; // another clock (the device reconnected): the history starts again
        view.setState(s);
        QCOMPARE(plot->graph(0)->dataCount(), 1);
        view.clear();
        QCOMPARE(plot->graph(0)->dataCount(), 0);
        QCOMPARE(label(view, u"bridge_energy"_s), u"No sample yet"_s);
    }
};

QTEST_MAIN(TestBridgeLoopViews)
#include "tst_bridgeloopviews.moc"
