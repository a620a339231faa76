// HandInput: SPEC parsing (every form and the refusals) and the torque it applies.
#include "sim/handinput.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace hatpic;
using namespace Qt::StringLiterals;

class TestHandInput : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parseValid_data();
    void parseValid();
    void parseInvalid_data();
    void parseInvalid();
    void roundTrip_data();
    void roundTrip();
    void torqueIdleAndConstant();
    void torqueStep();
    void torqueSine();
    void torqueChirp();
    void torqueVirtualHand();
    void torquePushes();
};

static HandInput make(HandInput::Kind kind, double amplitude = 0, double offset = 0,
                      double frequency = 0, double frequency1 = 0, double angle = 0)
{
    HandInput h;
    h.kind = kind;
    h.amplitude = amplitude;
    h.offset = offset;
    h.frequency = frequency;
    h.frequency1 = frequency1;
    h.angle = angle;
    return h;
}

void TestHandInput::parseValid_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<HandInput>("expected");
    using K = HandInput::Kind;
    QTest::newRow("idle") << u"idle"_s << make(K::Idle);
    QTest::newRow("idle with spaces and capitals") << u"  IDLE "_s << make(K::Idle);
    QTest::newRow("const positive") << u"const:0.05"_s << make(K::Constant, 0.05);
    QTest::newRow("const negative exponent") << u"const:-2e-2"_s << make(K::Constant, -0.02);
    QTest::newRow("step without T0") << u"step:0.1"_s << make(K::Step, 0.1, 0);
    QTest::newRow("step with T0") << u"step:0.1:-0.05"_s << make(K::Step, 0.1, -0.05);
    QTest::newRow("sine") << u"sine:0.03:2.5"_s << make(K::Sine, 0.03, 0, 2.5);
    QTest::newRow("sine zero frequency") << u"sine:0.03:0"_s << make(K::Sine, 0.03, 0, 0);
    QTest::newRow("chirp") << u"chirp:0.02:0.5:20"_s << make(K::Chirp, 0.02, 0, 0.5, 20);
    QTest::newRow("chirp falling") << u"chirp:0.02:8:1"_s << make(K::Chirp, 0.02, 0, 8, 1);
    QTest::newRow("virtual hand") << u"hand:0.3"_s << make(K::VirtualHand, 0, 0, 0, 0, 0.3);
    QTest::newRow("virtual hand negative")
        << u"hand:-1.2"_s << make(K::VirtualHand, 0, 0, 0, 0, -1.2);
    QTest::newRow("pushes") << u"pushes:0.05:3:20:2"_s << HandInput::pushing(0.05, 3, 20, 2);
    QTest::newRow("pushes without a release")
        << u"pushes:-0.1:1:0.5:0"_s << HandInput::pushing(-0.1, 1, 0.5, 0);
    // The bounds themselves are accepted (simulator.md § 4).
    QTest::newRow("torque at its bound") << u"step:10:-10"_s << make(K::Step, 10, -10);
    QTest::newRow("frequency at its bound")
        << u"chirp:-10:0:1000"_s << make(K::Chirp, -10, 0, 0, 1000);
    QTest::newRow("angle at its bound")
        << u"hand:-6.283185307179586"_s << make(K::VirtualHand, 0, 0, 0, 0, -2 * std::numbers::pi);
}

void TestHandInput::parseValid()
{
    QFETCH(QString, spec);
    QFETCH(HandInput, expected);
    QString error = u"untouched"_s;
    const std::optional<HandInput> parsed = HandInput::parse(spec, &error);
    QVERIFY2(parsed.has_value(), qPrintable(error));
    QCOMPARE(*parsed, expected);
}

void TestHandInput::parseInvalid_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<QString>("messagePart"); // a piece the sentence must contain
    QTest::newRow("empty") << QString() << u"empty"_s;
    QTest::newRow("blank") << u"   "_s << u"empty"_s;
    QTest::newRow("unknown kind") << u"push:1"_s << u"Unknown hand input kind \"push\""_s;
    QTest::newRow("idle with value") << u"idle:1"_s << u"has 1 value but idle takes 0 values"_s;
    QTest::newRow("const without value") << u"const"_s << u"has 0 values but const takes 1"_s;
    QTest::newRow("const two values") << u"const:1:2"_s << u"has 2 values"_s;
    QTest::newRow("step four values") << u"step:1:2:3:4"_s << u"takes 1 to 3 values"_s;
    QTest::newRow("step time negative") << u"step:0.1:0:-1"_s << u"step time -1 s"_s;
    QTest::newRow("step time beyond an hour") << u"step:0.1:0:3601"_s << u"from 0 to 3600 s"_s;
    QTest::newRow("sine one value") << u"sine:0.1"_s << u"sine:A:F"_s;
    QTest::newRow("chirp two values") << u"chirp:0.1:1"_s << u"chirp:A:F0:F1"_s;
    QTest::newRow("hand no angle") << u"hand"_s << u"hand:ANGLE"_s;
    QTest::newRow("non-number") << u"const:abc"_s << u"\"abc\" in \"const:abc\" is not a number"_s;
    QTest::newRow("empty value") << u"sine::1"_s << u"is not a number"_s;
    QTest::newRow("trailing colon") << u"const:1:"_s << u"has 2 values"_s;
    QTest::newRow("number with unit") << u"const:0.1Nm"_s << u"is not a number"_s;
    QTest::newRow("nan") << u"const:nan"_s << u"is not finite"_s;
    QTest::newRow("infinity") << u"hand:inf"_s << u"is not finite"_s;
    QTest::newRow("negative sine frequency") << u"sine:0.1:-2"_s
                                             << u"frequency -2 Hz in \"sine:0.1:-2\" must not be "
                                                "negative"_s;
    QTest::newRow("negative chirp F0") << u"chirp:0.1:-1:2"_s << u"must not be negative"_s;
    QTest::newRow("negative chirp F1") << u"chirp:0.1:1:-2"_s << u"must not be negative"_s;
    // Absurd magnitudes (issue 10): refused up front, naming the bound.
    QTest::newRow("huge torque") << u"const:1e305"_s
                                 << u"torque 1e+305 N·m in \"const:1e305\" is beyond the ±10 N·m"_s;
    QTest::newRow("huge step T0") << u"step:0.1:-11"_s << u"torque -11 N·m"_s;
    QTest::newRow("huge sine amplitude") << u"sine:20:1"_s << u"beyond the ±10 N·m"_s;
    QTest::newRow("huge sine frequency")
        << u"sine:1:1e308"_s << u"frequency 1e+308 Hz in \"sine:1:1e308\" is above the 1000 Hz"_s;
    QTest::newRow("huge chirp F1") << u"chirp:0.1:1:1000.5"_s << u"above the 1000 Hz"_s;
    QTest::newRow("huge angle") << u"hand:1e307"_s
                                << u"angle 1e+307 rad in \"hand:1e307\" is more than one turn"_s;
    QTest::newRow("angle beyond a turn") << u"hand:-6.3"_s << u"more than one turn"_s;
    QTest::newRow("pushes three values") << u"pushes:0.05:3:20"_s << u"pushes:T:N:ON:OFF"_s;
    QTest::newRow("pushes no count") << u"pushes:0.05:0:20:2"_s
                                     << u"push count 0 in \"pushes:0.05:0:20:2\" must be a whole "
                                        "number from 1 to 1000"_s;
    QTest::newRow("pushes half a count") << u"pushes:0.05:2.5:20:2"_s << u"push count 2.5"_s;
    QTest::newRow("pushes too many") << u"pushes:0.05:1001:1:1"_s << u"from 1 to 1000"_s;
    QTest::newRow("pushes zero push time")
        << u"pushes:0.05:3:0:2"_s << u"push time 0 s in \"pushes:0.05:3:0:2\" must be above 0"_s;
    QTest::newRow("pushes negative release") << u"pushes:0.05:3:20:-1"_s << u"release time -1 s"_s;
    QTest::newRow("pushes release beyond an hour")
        << u"pushes:0.05:3:20:3601"_s << u"from 0 to 3600 s"_s;
    QTest::newRow("pushes huge torque") << u"pushes:11:3:20:2"_s << u"beyond the ±10 N·m"_s;
}

void TestHandInput::parseInvalid()
{
    QFETCH(QString, spec);
    QFETCH(QString, messagePart);
    QString error;
    QVERIFY(!HandInput::parse(spec, &error).has_value());
    QVERIFY2(error.contains(messagePart), qPrintable(error));
    // One sentence: starts with a capital, ends with a full stop, no line breaks.
    QVERIFY2(error.at(0).isUpper() && error.endsWith(QLatin1Char('.')), qPrintable(error));
    QVERIFY(!error.contains(QLatin1Char('\n')));
    QVERIFY(!HandInput::parse(spec).has_value()); // a null error pointer is fine
}

void TestHandInput::roundTrip_data()
{
    QTest::addColumn<HandInput>("hand");
    using K = HandInput::Kind;
    QTest::newRow("idle") << make(K::Idle);
    QTest::newRow("const") << make(K::Constant, 0.123456789);
    QTest::newRow("step zero T0") << make(K::Step, -0.1);
    QTest::newRow("step with T0") << make(K::Step, 0.2, 0.1 / 3);
    HandInput release = make(K::Step, 0, 0.05);
    release.stepTime = 8.25;
    QTest::newRow("step with its time") << release;
    QTest::newRow("sine") << make(K::Sine, 0.05, 0, 1.0 / 7);
    QTest::newRow("chirp") << make(K::Chirp, 0.02, 0, 0.1, 30);
    QTest::newRow("hand") << make(K::VirtualHand, 0, 0, 0, 0, std::numbers::pi / 5);
    QTest::newRow("pushes") << HandInput::pushing(0.1 / 3, 7, 12.5, 1.0 / 3);
}

void TestHandInput::roundTrip()
{
    QFETCH(HandInput, hand);
    const QString spec = hand.toSpec();
    const std::optional<HandInput> back = HandInput::parse(spec);
    QVERIFY2(back.has_value(), qPrintable(spec));
    QCOMPARE(*back, hand);
}

void TestHandInput::torqueIdleAndConstant()
{
    const HandInput idle = make(HandInput::Kind::Idle);
    QCOMPARE(idle.torque(0.0, 0.0, 0.0), 0.0);
    QCOMPARE(idle.torque(3.0, 1.0, -2.0), 0.0);
    const HandInput c = make(HandInput::Kind::Constant, -0.07);
    QCOMPARE(c.torque(0.0, 0.0, 0.0), -0.07);
    QCOMPARE(c.torque(12.5, 0.4, 3.0), -0.07);
}

void TestHandInput::torqueStep()
{
    const HandInput s = make(HandInput::Kind::Step, 0.1, -0.02);
    QCOMPARE(s.torque(0.0, 0, 0), -0.02);
    QCOMPARE(s.torque(HandInput::kStepTime * 0.999, 0, 0), -0.02);
    QCOMPARE(s.torque(HandInput::kStepTime, 0, 0), 0.1);
    QCOMPARE(s.torque(5.0, 0, 0), 0.1);

    // A later step time: a hand that pushes, then lets go.
    const std::optional<HandInput> release = HandInput::parse(u"step:0:0.05:8"_s);
    QVERIFY(release.has_value());
    QCOMPARE(release->stepTime, 8.0);
    QCOMPARE(release->torque(7.999, 0, 0), 0.05);
    QCOMPARE(release->torque(8.0, 0, 0), 0.0);
    QCOMPARE(release->toSpec(), u"step:0:0.05:8"_s);
}

void TestHandInput::torqueSine()
{
    const double a = 0.04;
    const double f = 2.0;
    const HandInput s = make(HandInput::Kind::Sine, a, 0, f);
    QCOMPARE(s.torque(0.0, 0, 0), 0.0);
    QVERIFY(std::abs(s.torque(1.0 / (4 * f), 0, 0) - a) < 1e-15); // quarter period: +A
    QVERIFY(std::abs(s.torque(3.0 / (4 * f), 0, 0) + a) < 1e-15); // three quarters: −A
    QVERIFY(std::abs(s.torque(0.1, 0, 0) - a * std::sin(2 * std::numbers::pi * f * 0.1)) < 1e-15);
}

void TestHandInput::torqueChirp()
{
    const double a = 0.03;
    const double f0 = 1.0;
    const double f1 = 11.0;
    const HandInput c = make(HandInput::Kind::Chirp, a, 0, f0, f1);
    const double period = HandInput::kChirpPeriod;
    auto expected = [&](double t) {
        const double k = (f1 - f0) / period;
        return a * std::sin(2 * std::numbers::pi * (f0 * t + 0.5 * k * t * t));
    };
    for (const double t : {0.0, 0.013, 0.5, 2.7, 9.99}) {
        QVERIFY2(std::abs(c.torque(t, 0, 0) - expected(t)) < 1e-12, qPrintable(QString::number(t)));
        // The sweep repeats with the chirp period.
        QVERIFY2(std::abs(c.torque(t + period, 0, 0) - expected(t)) < 1e-9,
                 qPrintable(QString::number(t)));
    }
    // With F0 = F1 the chirp is a sine of that frequency (within one sweep).
    const HandInput flat = make(HandInput::Kind::Chirp, a, 0, 3.0, 3.0);
    const HandInput sine = make(HandInput::Kind::Sine, a, 0, 3.0);
    for (const double t : {0.01, 0.37, 4.2})
        QVERIFY(std::abs(flat.torque(t, 0, 0) - sine.torque(t, 0, 0)) < 1e-12);
}

void TestHandInput::torqueVirtualHand()
{
    const HandInput h = make(HandInput::Kind::VirtualHand, 0, 0, 0, 0, 0.5);
    const double k = HandInput::kHandStiffness;
    const double b = HandInput::kHandDamping;
    QCOMPARE(h.torque(0.0, 0.5, 0.0), 0.0);
    QVERIFY(std::abs(h.torque(1.0, 0.2, 0.0) - k * 0.3) < 1e-15);
    QVERIFY(std::abs(h.torque(1.0, 0.5, 2.0) + b * 2.0) < 1e-15);
    QVERIFY(std::abs(h.torque(7.0, 0.7, -1.0) - (k * -0.2 + b * 1.0)) < 1e-15);
    QVERIFY(h.torque(0, 0.0, 0) > 0); // pulls toward its angle
}

//! pushes:T:N:ON:OFF — T for ON s, nothing for OFF s, N times, then nothing: the same contact
//! made again and again (teleop-map --contacts, bench/teleop-passivity).
void TestHandInput::torquePushes()
{
    const HandInput p = HandInput::pushing(0.05, 3, 20, 2);
    QCOMPARE(p.torque(-0.001, 0, 0), 0.0);
    QCOMPARE(p.torque(0.0, 0, 0), 0.05);
    QCOMPARE(p.torque(19.999, 0, 0), 0.05);
    QCOMPARE(p.torque(20.0, 0, 0), 0.0);
    QCOMPARE(p.torque(21.999, 0, 0), 0.0);
    QCOMPARE(p.pushStart(1), 22.0);
    QCOMPARE(p.torque(22.0, 0, 0), 0.05);
    QCOMPARE(p.torque(44.0 + 19.9, 0, 0), 0.05); // the third push
    QCOMPARE(p.torque(64.0, 0, 0), 0.0);         // over: it lets go…
    QCOMPARE(p.torque(66.5, 0, 0), 0.0);         // …and does not push a fourth time
    QCOMPARE(p.torque(1e6, 0.3, 1.0), 0.0);
}

QTEST_GUILESS_MAIN(TestHandInput)
#include "tst_handinput.moc"
