// The in-process teleoperation loop: robot.md's loop comes to rest where robot.md puts it at 0
// and 40 ms one-way delay and keeps swinging at 150 ms (as the three real programs do:
// docs/teleop.md § Measured); a seed gives the same run; bad settings are refused naming the
// field, the rule and the value; with the passivity controller off it runs bit for bit as the
// code from before the controller did (a trace recorded there, data/loop-before-passivity.txt).
#include "teleop/loopsimulation.h"

#include <QCryptographicHash>
#include <QFile>
#include <QTest>

#include <cmath>
#include <cstdio>

Q_DECLARE_METATYPE(hatpic::teleop::LoopConfig)

using namespace hatpic;
using namespace hatpic::teleop;

namespace {

//! robot.md's loop (const:0.05, force.x, gain 0.02, the robot's defaults), the passivity
//! controller off unless `controller`.
LoopConfig robotMdLoop(double delay, double duration = 12, bool controller = false)
{
    LoopConfig c;
    c.robot.faults.delay = delay;
    c.duration = duration;
    if (!controller)
        c.passivity = PassivityParams::off();
    return c;
}

} // namespace

class TestLoopSimulation : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void restsAtRobotMdsEquilibrium_data();
    void restsAtRobotMdsEquilibrium();
    void swingsForGoodAt150ms();
    void controllerOffIsTheCodeBeforeIt();
    void controllerHoldsContact_data();
    void controllerHoldsContact();
    void controllerCostsNothingWithoutDelay();
    void sameSeedSameRun();
    void jitterAndLossFollowTheSeed();
    void noContactWithoutAHandTowardsTheWall();
    void badSettingsAreNamed_data();
    void badSettingsAreNamed();
    void contactsAreTheRunsPushes();
    void everyContactCostsLittleWithoutDelay_data();
    void everyContactCostsLittleWithoutDelay();
    void everyDelayedContactSettlesUndampedAtRest_data();
    void everyDelayedContactSettlesUndampedAtRest();
    void halfASecondWithJitterAndLoss();
    void aRestThatNeedsDampingIsHeld();
};

void TestLoopSimulation::restsAtRobotMdsEquilibrium_data()
{
    QTest::addColumn<double>("delay");
    QTest::newRow("0 s") << 0.0;
    QTest::newRow("40 ms") << 0.04;
}

void TestLoopSimulation::restsAtRobotMdsEquilibrium()
{
    QFETCH(double, delay);
    const LoopConfig c = robotMdLoop(delay);
    const auto eq = LoopSimulation::equilibrium(c);
    QVERIFY(eq.has_value());
    QVERIFY(std::abs(eq->theta - 0.0625) < 1e-6);
    const LoopResult r = LoopSimulation::run(c);
    QVERIFY(r.problem.isEmpty());
    QVERIFY(r.contact);
    QVERIFY2(r.settled, qPrintable(QStringLiteral("p2p %1").arg(r.p2p)));
    // passivity.md's targets: θ 0.0625 ± 0.004, τ_ext −0.025 ± 0.003, x 0.05625 ± 0.002,
    // p2p ≤ 0.003 over the last 2 s.
    QVERIFY2(std::abs(r.thetaRest - 0.0625) < 0.004, qPrintable(QString::number(r.thetaRest)));
    QVERIFY2(std::abs(r.tauExtRest + 0.025) < 0.003, qPrintable(QString::number(r.tauExtRest)));
    QVERIFY2(std::abs(r.xRest - 0.05625) < 0.002, qPrintable(QString::number(r.xRest)));
    QVERIFY(r.p2p <= LoopResult::kBand);
    // The real programs settle in 0.35–2.7 s at these delays (issue 25).
    QVERIFY2(r.settleS > 0 && r.settleS < 5, qPrintable(QString::number(r.settleS)));
    QVERIFY(r.contactAt > 0 && r.contactAt < 2);
    QCOMPARE(r.dissipatedJ, 0.0); // no controller, nothing taken out
}

namespace {

//! A loop's trace as data/loop-before-passivity.txt holds it: the step count, the SHA-256 of
//! every step's t, θ, ω, τ_ext and x (8-byte doubles) and every 250th step in hex floats.
struct Trace
{
    int steps = 0;
    QByteArray sha256;
    QList<QByteArray> rows;
};

Trace traceOf(const LoopConfig &config)
{
    LoopSimulation loop(config);
    QCryptographicHash hash(QCryptographicHash::Sha256);
    Trace trace;
    while (!loop.atEnd()) {
        const LoopSimulation::Step s = loop.step();
        for (double v : {s.t, s.theta, s.omega, s.tauExt, s.x})
            hash.addData(QByteArrayView(reinterpret_cast<const char *>(&v), sizeof v));
        if (trace.steps % 250 == 0) {
            char line[256];
            std::snprintf(line, sizeof line, "%a %a %a %a %a", s.t, s.theta, s.omega, s.tauExt,
                          s.x);
            trace.rows.append(line);
        }
        ++trace.steps;
    }
    trace.sha256 = hash.result().toHex();
    return trace;
}

} // namespace

//! pc_damping_max 0 takes the device's step from before the controller, bit for bit: the trace
//! recorded on that code (commit d567bd0) at 150 ms, where the loop swings and a controller
//! that acted would show, is the trace today's code runs with the controller off.
void TestLoopSimulation::controllerOffIsTheCodeBeforeIt()
{
    QFile file(QStringLiteral(HATPIC_TEST_DATA "/loop-before-passivity.txt"));
    QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(file.fileName()));
    Trace recorded;
    for (const QByteArray &line : file.readAll().split('\n')) {
        if (line.startsWith("steps "))
            recorded.steps = line.mid(6).toInt();
        else if (line.startsWith("sha256 "))
            recorded.sha256 = line.mid(7);
        else if (!line.isEmpty() && !line.startsWith('#'))
            recorded.rows.append(line);
    }
    QCOMPARE(recorded.steps, 8001);
    QCOMPARE(recorded.rows.size(), 33);

    LoopConfig config = robotMdLoop(0.15, 8);
    const Trace off = traceOf(config);
    QCOMPARE(off.steps, recorded.steps);
    for (qsizetype i = 0; i < recorded.rows.size(); ++i)
        QCOMPARE(off.rows.at(i), recorded.rows.at(i)); // names the first sampled step that differs
    QCOMPARE(off.sha256, recorded.sha256);

    config.passivity = PassivityParams{}; // on: the same loop then runs otherwise
    const Trace on = traceOf(config);
    QVERIFY(on.sha256 != recorded.sha256);
}

void TestLoopSimulation::swingsForGoodAt150ms()
{
    const LoopResult r = LoopSimulation::run(robotMdLoop(0.15));
    QVERIFY(r.contact);
    QVERIFY(!r.settled);
    QVERIFY(std::isnan(r.settleS));
    // The real programs: 0.69 rad peak to peak, for good.
    QVERIFY2(r.p2p > 0.3, qPrintable(QString::number(r.p2p)));
}

void TestLoopSimulation::controllerHoldsContact_data()
{
    QTest::addColumn<double>("delay");
    QTest::newRow("150 ms") << 0.15;
    QTest::newRow("300 ms") << 0.3;
}

// With the controller's defaults the loop that swings for good comes to rest at robot.md's
// equilibrium, and its price shows: τ_pc during the transient, energy taken out.
void TestLoopSimulation::controllerHoldsContact()
{
    QFETCH(double, delay);
    QVERIFY(!LoopSimulation::run(robotMdLoop(delay, 20)).settled);
    const LoopResult r = LoopSimulation::run(robotMdLoop(delay, 20, true));
    QVERIFY2(r.settled, qPrintable(QStringLiteral("p2p %1").arg(r.p2p)));
    QVERIFY(std::abs(r.thetaRest - 0.0625) < 0.004);
    QVERIFY(std::abs(r.tauExtRest + 0.025) < 0.003);
    QVERIFY(r.settleS < 18);
    QVERIFY2(r.rmsTauPcRatio > 0.05, qPrintable(QString::number(r.rmsTauPcRatio)));
    QVERIFY2(r.dissipatedJ > 0.001, qPrintable(QString::number(r.dissipatedJ)));
}

// passivity.md: at 0 delay the settle time is at most 1.25 × the one without it.
void TestLoopSimulation::controllerCostsNothingWithoutDelay()
{
    const LoopResult off = LoopSimulation::run(robotMdLoop(0));
    const LoopResult on = LoopSimulation::run(robotMdLoop(0, 12, true));
    QVERIFY(off.settled && on.settled);
    QVERIFY2(on.settleS <= 1.25 * off.settleS,
             qPrintable(QStringLiteral("%1 vs %2").arg(on.settleS).arg(off.settleS)));
}

void TestLoopSimulation::sameSeedSameRun()
{
    LoopConfig c = robotMdLoop(0.04, 3);
    LoopSimulation a(c), b(c);
    int n = 0;
    while (!a.atEnd()) {
        const auto sa = a.step();
        const auto sb = b.step();
        QCOMPARE(sa.theta, sb.theta);
        QCOMPARE(sa.tauExt, sb.tauExt);
        QCOMPARE(sa.x, sb.x);
        ++n;
    }
    QVERIFY(b.atEnd());
    QCOMPARE(n, 3001); // t = 0 … 3 s at 1 kHz
    // Another noise seed: another run.
    c.seed = 2;
    LoopSimulation other(c), first(robotMdLoop(0.04, 3));
    bool differs = false;
    while (!other.atEnd())
        differs |= other.step().theta != first.step().theta;
    QVERIFY(differs);
}

void TestLoopSimulation::jitterAndLossFollowTheSeed()
{
    LoopConfig c = robotMdLoop(0.02, 4);
    c.robot.faults.jitter = 0.02;
    c.robot.faults.loss = 0.2;
    const LoopResult a = LoopSimulation::run(c);
    const LoopResult b = LoopSimulation::run(c);
    QCOMPARE(a.thetaRest, b.thetaRest);
    QCOMPARE(a.p2p, b.p2p);
    c.robot.seed = 7;
    const LoopResult other = LoopSimulation::run(c);
    QVERIFY(other.contactAt != a.contactAt || other.thetaRest != a.thetaRest);
}

void TestLoopSimulation::noContactWithoutAHandTowardsTheWall()
{
    LoopConfig c = robotMdLoop(0, 3);
    c.hand = HandInput{HandInput::Kind::Constant, -0.05};
    QVERIFY(!LoopSimulation::equilibrium(c));
    const LoopResult r = LoopSimulation::run(c);
    QVERIFY(!r.contact);
    QVERIFY(!r.settled);
    QVERIFY(std::isnan(r.rmsTauPcRatio));
}

void TestLoopSimulation::badSettingsAreNamed_data()
{
    QTest::addColumn<LoopConfig>("config");
    QTest::addColumn<QString>("words");
    LoopConfig c;
    c.robot.faults.delay = -1;
    QTest::newRow("delay") << c << QStringLiteral("delay|must be from 0 to 10 s|-1");
    c = {};
    c.feedback.gain = 1000;
    QTest::newRow("gain") << c << QStringLiteral("gain|at most 100|1000");
    c = {};
    c.duration = 1;
    QTest::newRow("duration") << c << QStringLiteral("duration|from 2 to 3600 s|got 1");
    c = {};
    c.device.M_adm = -1;
    QTest::newRow("M_adm") << c << QStringLiteral("M_adm|-1");
    c = {};
    c.robot.robot.mass = 0;
    QTest::newRow("mass") << c << QStringLiteral("mass|must be > 0|0");
    c = {};
    c.robot.faults.loss = std::nan("");
    QTest::newRow("loss") << c << QStringLiteral("loss|finite");
    c = {};
    c.contacts = 0;
    QTest::newRow("contacts") << c << QStringLiteral("contacts|from 1 to 100|got 0");
    c = {};
    c.contacts = 2;
    c.hand = HandInput{HandInput::Kind::Sine, 0.05, 0, 1};
    QTest::newRow("contacts need a constant hand")
        << c << QStringLiteral("constant hand|sine:0.05:1");
    c = {};
    c.contacts = 100;
    c.duration = 100;
    QTest::newRow("contacts too long") << c << QStringLiteral("3600 s|got 10198 s");
}

void TestLoopSimulation::badSettingsAreNamed()
{
    QFETCH(LoopConfig, config);
    QFETCH(QString, words);
    const QString problem = LoopSimulation::check(config);
    for (const QString &w : words.split(u'|'))
        QVERIFY2(problem.contains(w), qPrintable(problem + u" lacks " + w));
    QVERIFY(LoopSimulation::check(LoopConfig{}).isEmpty());
}

namespace {

//! robot.md's loop with a hand of `hand` N·m pushing three times (20 s, let go 2 s).
LoopConfig contactsLoop(double delay, double hand, bool controller)
{
    LoopConfig c = robotMdLoop(delay, 20, controller);
    c.hand = {HandInput::Kind::Constant, hand};
    c.contacts = 3;
    return c;
}

QString describe(const LoopResult &r)
{
    return QStringLiteral("contact %1: settled %2 in %3 s, p2p %4, damped at rest %5")
        .arg(r.index)
        .arg(r.settled)
        .arg(r.settleS)
        .arg(r.p2p)
        .arg(r.dampedAtRest);
}

} // namespace

//! With contacts, the hand pushes, lets go for 2 s and pushes again; each push is a contact
//! judged on its own window, and the run's result is the worst of them.
void TestLoopSimulation::contactsAreTheRunsPushes()
{
    LoopConfig c = contactsLoop(0, 0.05, false);
    c.duration = 6;
    QCOMPARE(c.runTime(), 3 * 6 + 2 * LoopConfig::kRelease);
    LoopSimulation loop(c);
    int steps = 0;
    while (!loop.atEnd()) {
        loop.step();
        ++steps;
    }
    QCOMPARE(steps, 22001);
    const std::vector<LoopResult> contacts = loop.contactResults();
    QCOMPARE(contacts.size(), std::size_t(3));
    for (int i = 0; i < 3; ++i) {
        const LoopResult &r = contacts[std::size_t(i)];
        QCOMPARE(r.index, i + 1);
        QVERIFY2(r.contact && r.settled, qPrintable(describe(r)));
        // Each contact begins within its own push.
        const double push = i * (c.duration + LoopConfig::kRelease);
        QVERIFY2(r.contactAt >= push && r.contactAt < push + 2, qPrintable(describe(r)));
        QVERIFY(std::abs(r.thetaRest - 0.0625) < 0.004);
    }
    const LoopResult worst = LoopSimulation::worst(contacts);
    for (const LoopResult &r : contacts)
        QVERIFY(worst.settleS >= r.settleS);
    QCOMPARE(loop.result().index, worst.index);
    // Not settled is worse than any settled contact.
    LoopResult swinging = contacts[0];
    swinging.settled = false;
    swinging.index = 9;
    QCOMPARE(LoopSimulation::worst({contacts[1], swinging, contacts[2]}).index, 9);
}

void TestLoopSimulation::everyContactCostsLittleWithoutDelay_data()
{
    QTest::addColumn<double>("hand");
    for (double hand : {0.03, 0.05, 0.07, 0.08})
        QTest::addRow("%g N·m", hand) << hand;
}

// Issue 35: at 0 delay every contact of every hand settles within 1.25 × the time it takes
// without the controller (the tank never refilled: a second contact took 4.2 s against 0.37 s;
// a tank that fitted only 0.05 N·m: 0.07 N·m took 2.4 s against 0.4 s), and the knob is not
// damped once at rest.
void TestLoopSimulation::everyContactCostsLittleWithoutDelay()
{
    QFETCH(double, hand);
    const auto off = LoopSimulation::runContacts(contactsLoop(0, hand, false));
    const auto on = LoopSimulation::runContacts(contactsLoop(0, hand, true));
    QCOMPARE(on.size(), std::size_t(3));
    QCOMPARE(off.size(), std::size_t(3));
    for (std::size_t i = 0; i < on.size(); ++i) {
        QVERIFY2(off[i].settled, qPrintable(describe(off[i])));
        QVERIFY2(on[i].settled, qPrintable(describe(on[i])));
        QVERIFY2(on[i].settleS <= 1.25 * off[i].settleS,
                 qPrintable(describe(on[i]) + u" against " + describe(off[i])));
        QVERIFY2(on[i].dampedAtRest <= 0.05, qPrintable(describe(on[i])));
    }
}

void TestLoopSimulation::everyDelayedContactSettlesUndampedAtRest_data()
{
    QTest::addColumn<double>("delay");
    QTest::addColumn<double>("hand");
    for (double delay : {0.12, 0.2, 0.3}) {
        for (double hand : {0.03, 0.05, 0.07})
            QTest::addRow("%g s, %g N·m", delay, hand) << delay << hand;
    }
}

// Issue 35: every contact of three settles within 8 s at 0.12 … 0.3 s one-way (a hand of
// 0.03 N·m took 10.5 s: its slow swing exchanged energy the tank never ran out of), and once at
// rest the knob is damped in at most 5 % of the cycles (it was in about 96 %).
void TestLoopSimulation::everyDelayedContactSettlesUndampedAtRest()
{
    QFETCH(double, delay);
    QFETCH(double, hand);
    const auto on = LoopSimulation::runContacts(contactsLoop(delay, hand, true));
    QCOMPARE(on.size(), std::size_t(3));
    for (const LoopResult &r : on) {
        QVERIFY2(r.settled && r.settleS <= 8, qPrintable(describe(r)));
        QVERIFY2(r.dampedAtRest <= 0.05, qPrintable(describe(r)));
        QVERIFY(std::abs(r.thetaRest - r.thetaEq) < 0.004);
    }
}

// Issue 35: 0.5 s one-way with 20 ms jitter and 20 % loss, every contact within 12 s.
void TestLoopSimulation::halfASecondWithJitterAndLoss()
{
    LoopConfig c = contactsLoop(0.5, 0.05, true);
    c.robot.faults.jitter = 0.02;
    c.robot.faults.loss = 0.2;
    for (const LoopResult &r : LoopSimulation::runContacts(c))
        QVERIFY2(r.settled && r.settleS <= 12 && r.dampedAtRest <= 0.05, qPrintable(describe(r)));
}

// A hand of 0.1 N·m rests beyond the notch, where the fed-back torque outweighs the knob's
// spring: without damping that rest swings away again (docs/teleop.md). The controller holds it
// within a few encoder counts of that rest (creeping toward it under the damping; six counts,
// 9.2 mrad, since the rest's anchor follows a resting knob's flicker: docs/teleop.md § Choosing
// the tank), and says so: damped at rest.
void TestLoopSimulation::aRestThatNeedsDampingIsHeld()
{
    const auto off = LoopSimulation::run(contactsLoop(0.12, 0.1, false));
    QVERIFY2(!off.settled && off.p2p > 0.1, qPrintable(describe(off)));
    for (const LoopResult &r : LoopSimulation::runContacts(contactsLoop(0.12, 0.1, true))) {
        QVERIFY2(r.p2p <= 0.010, qPrintable(describe(r)));
        QVERIFY2(std::abs(r.thetaRest - r.thetaEq) < 0.008, qPrintable(describe(r)));
        QVERIFY2(r.dampedAtRest > 0.5, qPrintable(describe(r)));
    }
}

QTEST_GUILESS_MAIN(TestLoopSimulation)
#include "tst_loopsimulation.moc"
