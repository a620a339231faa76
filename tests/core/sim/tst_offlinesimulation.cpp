// OfflineSimulation's guards (issue 10, "Hostile input"): check() refuses a hand input beyond
// its bounds even when it was not parsed, and a run that leaves the finite numbers stops at
// the first such row instead of handing out rows of NaN.
#include "sim/offlinesimulation.h"

#include <QTest>

#include <cmath>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

OfflineSimulationConfig config(const HandInput &hand, bool ideal)
{
    OfflineSimulationConfig c;
    c.hand = hand;
    c.ideal = ideal;
    c.duration = 1.0;
    return c;
}

HandInput constant(double torque)
{
    HandInput hand;
    hand.kind = HandInput::Kind::Constant;
    hand.amplitude = torque;
    return hand;
}

bool finite(const Sample &s)
{
    for (double v :
         {s.t_s, s.theta, s.omega, s.tau, s.tau_rec, s.tau_ext, s.tau_total, s.v_ref, s.p_ref}) {
        if (!std::isfinite(v))
            return false;
    }
    return true;
}

} // namespace

class TestOfflineSimulation : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void checkRefusesUnparsedHand_data();
    void checkRefusesUnparsedHand();
    void stopsAtFirstNonFiniteRow_data();
    void stopsAtFirstNonFiniteRow();
    void strongestHandStaysFinite_data();
    void strongestHandStaysFinite();
};

void TestOfflineSimulation::checkRefusesUnparsedHand_data()
{
    QTest::addColumn<HandInput>("hand");
    QTest::addColumn<QString>("messagePart");
    QTest::newRow("torque") << constant(1e305) << u"beyond the ±10 N·m"_s;
    HandInput sine;
    sine.kind = HandInput::Kind::Sine;
    sine.amplitude = 1;
    sine.frequency = 1e308;
    QTest::newRow("frequency") << sine << u"above the 1000 Hz"_s;
    HandInput hand;
    hand.kind = HandInput::Kind::VirtualHand;
    hand.angle = 1e307;
    QTest::newRow("angle") << hand << u"more than one turn"_s;
}

void TestOfflineSimulation::checkRefusesUnparsedHand()
{
    QFETCH(HandInput, hand);
    QFETCH(QString, messagePart);
    const QString problem = OfflineSimulation::check(config(hand, true));
    QVERIFY2(problem.contains(messagePart), qPrintable(problem));
}

void TestOfflineSimulation::stopsAtFirstNonFiniteRow_data()
{
    // The servo saturates its registers, so only the ideal knob can overflow.
    QTest::addColumn<bool>("ideal");
    QTest::newRow("ideal") << true;
}

void TestOfflineSimulation::stopsAtFirstNonFiniteRow()
{
    QFETCH(bool, ideal);
    // Past check(), as a programming error or a future input kind might get: the run must
    // still never hand out a non-finite row as a result.
    OfflineSimulation simulation(config(constant(1.7e308), ideal));
    qint64 results = 0;
    while (!simulation.atEnd()) {
        const Sample sample = simulation.next();
        if (simulation.failed())
            break;
        QVERIFY2(finite(sample), qPrintable(u"row "_s + QString::number(results)));
        ++results;
    }
    QVERIFY(simulation.failed());
    QVERIFY(simulation.atEnd());
    QVERIFY(results < simulation.rowCount());
    QVERIFY2(simulation.problem().startsWith(u"The simulation left the finite numbers at t = "_s),
             qPrintable(simulation.problem()));
    QVERIFY(!simulation.problem().contains(u'\n'));
}

void TestOfflineSimulation::strongestHandStaysFinite_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<bool>("ideal");
    for (bool ideal : {true, false}) {
        const char *mode = ideal ? "ideal" : "servo";
        QTest::addRow("const %s", mode) << u"const:10"_s << ideal;
        QTest::addRow("sine %s", mode) << u"sine:-10:1000"_s << ideal;
        QTest::addRow("hand %s", mode) << u"hand:6.283185307179586"_s << ideal;
    }
}

void TestOfflineSimulation::strongestHandStaysFinite()
{
    QFETCH(QString, spec);
    QFETCH(bool, ideal);
    // The bounds are chosen so that anything they accept simulates to finite numbers.
    QString error;
    const auto hand = HandInput::parse(spec, &error);
    QVERIFY2(hand, qPrintable(error));
    OfflineSimulationConfig c = config(*hand, ideal);
    c.duration = 10;
    QVERIFY2(OfflineSimulation::check(c).isEmpty(), qPrintable(OfflineSimulation::check(c)));
    OfflineSimulation simulation(c);
    while (!simulation.atEnd())
        simulation.next();
    QVERIFY2(!simulation.failed(), qPrintable(simulation.problem()));
}

QTEST_GUILESS_MAIN(TestOfflineSimulation)
#include "tst_offlinesimulation.moc"
