// The stability map: value lists and ranges (and their refusals), the cells spread over
// threads give the same figures as one thread, the CSV's columns and the SVG's cells and mark.
#include "teleop/stabilitymap.h"

#include <QTest>

#include <cmath>

using namespace hatpic;
using namespace hatpic::teleop;

class TestStabilityMap : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void lists_data();
    void lists();
    void badLists_data();
    void badLists();
    void threadsGiveTheSameCells();
    void csvAndSvg();
    void variesATuningField();
    void controllerOffAndOn();
    void handsAndContacts();
    void badSpecs();
};

void TestStabilityMap::lists_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QList<double>>("values");
    QTest::newRow("one") << QStringLiteral("0.02") << QList<double>{0.02};
    QTest::newRow("list") << QStringLiteral("0, 0.15,0.3") << QList<double>{0, 0.15, 0.3};
    QTest::newRow("step") << QStringLiteral("0:0.3:0.1") << QList<double>{0, 0.1, 0.2, 0.3};
    QTest::newRow("count") << QStringLiteral("0:1/5") << QList<double>{0, 0.25, 0.5, 0.75, 1};
    QTest::newRow("mixed") << QStringLiteral("0.5,0:0.02:0.01")
                           << QList<double>{0.5, 0, 0.01, 0.02};
}

void TestStabilityMap::lists()
{
    QFETCH(QString, text);
    QFETCH(QList<double>, values);
    QString error;
    const auto parsed = parseValueList(text, &error);
    QVERIFY2(parsed.has_value(), qPrintable(error));
    QCOMPARE(qsizetype(parsed->size()), values.size());
    for (qsizetype i = 0; i < values.size(); ++i)
        QVERIFY(std::abs((*parsed)[std::size_t(i)] - values[i]) < 1e-12);
}

void TestStabilityMap::badLists_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("words");
    QTest::newRow("word") << QStringLiteral("fast") << QStringLiteral("needs a number|'fast'");
    QTest::newRow("empty item") << QStringLiteral("0,,1") << QStringLiteral("empty item");
    QTest::newRow("backwards") << QStringLiteral("1:0:0.1") << QStringLiteral("FROM ≤ TO|1:0:0.1");
    QTest::newRow("zero step") << QStringLiteral("0:1:0") << QStringLiteral("STEP above 0");
    QTest::newRow("one point") << QStringLiteral("0:1/1") << QStringLiteral("N from 2");
    QTest::newRow("too many") << QStringLiteral("0:1:0.0001") << QStringLiteral("more than 1000");
    QTest::newRow("nan") << QStringLiteral("nan") << QStringLiteral("needs a number");
}

void TestStabilityMap::badLists()
{
    QFETCH(QString, text);
    QFETCH(QString, words);
    QString error;
    QVERIFY(!parseValueList(text, &error));
    for (const QString &w : words.split(u'|'))
        QVERIFY2(error.contains(w), qPrintable(error + u" lacks " + w));
}

void TestStabilityMap::threadsGiveTheSameCells()
{
    MapSpec spec;
    spec.base.duration = 4;
    spec.delays = {0, 0.15};
    spec.gains = {0.01, 0.02};
    spec.threads = 1;
    QVERIFY(checkSpec(spec).isEmpty());
    const auto one = runMap(spec);
    spec.threads = 2;
    qsizetype last = 0;
    const auto two = runMap(spec, [&](qsizetype done, qsizetype total) {
        QCOMPARE(total, 4);
        last = std::max(last, done);
    });
    QCOMPARE(last, 4);
    QCOMPARE(one.size(), std::size_t(4));
    QCOMPARE(two.size(), std::size_t(4));
    for (std::size_t i = 0; i < 4; ++i) {
        QCOMPARE(one[i].delay, two[i].delay);
        QCOMPARE(one[i].gain, two[i].gain);
        QCOMPARE(one[i].result.p2p, two[i].result.p2p);
        QCOMPARE(one[i].result.settled, two[i].result.settled);
    }
    // Delay fastest, then gain.
    QCOMPARE(one[1].delay, 0.15);
    QCOMPARE(one[2].gain, 0.02);
    // A cancelled map stops.
    std::atomic<bool> cancel{true};
    QVERIFY(runMap(spec, {}, &cancel).empty());
}

void TestStabilityMap::csvAndSvg()
{
    MapSpec spec;
    spec.base.duration = 6;
    spec.base.passivity = PassivityParams::off();
    spec.delays = {0, 0.15};
    spec.gains = {0.02};
    const auto cells = runMap(spec);
    const QByteArray csv = mapCsv(cells, {});
    const QList<QByteArray> lines = csv.trimmed().split('\n');
    QCOMPARE(lines.size(), 3);
    QVERIFY(lines[0].startsWith("delay,gain,pc,settled,settle_s,p2p,rms_tau_pc_ratio,"
                                "dissipated_j,"));
    QVERIFY2(lines[1].startsWith("0,0.02,0,1,"), lines[1].constData());     // settles
    QVERIFY2(lines[2].startsWith("0.15,0.02,0,0,,"), lines[2].constData()); // does not
    const QByteArray svg = mapSvg(cells, {}, 6, MapMark{0.15, 0.02, NAN});
    QVERIFY(svg.startsWith("<svg"));
    QCOMPARE(svg.count("<title>delay "), 2);
    QVERIFY(svg.contains("not settled, θ p2p"));
    QVERIFY(svg.contains("settled in "));
    QVERIFY(svg.contains("the settings in use"));
    QVERIFY(!mapSvg(cells, {}, 6).contains("the settings in use"));
}

void TestStabilityMap::variesATuningField()
{
    MapSpec spec;
    spec.base.duration = 3;
    spec.delays = {0};
    spec.gains = {0.02};
    spec.field = {QStringLiteral("M_adm"), {0.01, 0.05}};
    QVERIFY(checkSpec(spec).isEmpty());
    QCOMPARE(spec.cellCount(), 2);
    QCOMPARE(spec.cellConfig(1).device.M_adm, 0.05);
    const auto cells = runMap(spec);
    QCOMPARE(cells[1].field, 0.05);
    QVERIFY(mapCsv(cells, spec.field.name).startsWith("delay,gain,pc,M_adm,settled"));
    QVERIFY(mapSvg(cells, spec.field.name, 3).contains("M_adm = 0.05"));
}

// The controller off and on side by side: 150 ms swings off and settles on; the pc column says
// which.
void TestStabilityMap::controllerOffAndOn()
{
    MapSpec spec;
    spec.base.duration = 12;
    spec.delays = {0.15};
    spec.field = {QStringLiteral("pc_damping_max"), {0, 0.5}};
    QVERIFY(checkSpec(spec).isEmpty());
    const auto cells = runMap(spec);
    QCOMPARE(cells.size(), std::size_t(2));
    QCOMPARE(cells[0].pc, 0.0);
    QVERIFY(!cells[0].result.settled);
    QCOMPARE(cells[1].pc, 0.5);
    QVERIFY(cells[1].result.settled);
    const QByteArray csv = mapCsv(cells, spec.field.name);
    QVERIFY(csv.startsWith("delay,gain,pc,settled,"));
    QVERIFY(csv.contains("\n0.15,0.02,0.5,1,"));
    QVERIFY(mapSvg(cells, spec.field.name, 12).contains("pc_damping_max = 0.5"));
    QVERIFY(mapFieldNames().contains(u"pc_reserve_max"));
}

// Issue 35: hands are a sweep axis like gains, each contact a row of the CSV (columns hand and
// contact), a cell's chart colour its worst contact's, a panel per hand.
void TestStabilityMap::handsAndContacts()
{
    MapSpec spec;
    spec.base.duration = 4;
    spec.base.contacts = 2;
    spec.delays = {0, 0.04};
    spec.gains = {0.02};
    spec.hands = {0.03, 0.07};
    QVERIFY(checkSpec(spec).isEmpty());
    QCOMPARE(spec.cellCount(), 4);
    // Delay fastest, then gain, then hand.
    QCOMPARE(spec.cellConfig(1).robot.faults.delay, 0.04);
    QCOMPARE(spec.cellConfig(2).hand, (HandInput{HandInput::Kind::Constant, 0.07}));
    QCOMPARE(spec.cellConfig(2).robot.faults.delay, 0.0);
    const auto cells = runMap(spec);
    QCOMPARE(cells.size(), std::size_t(4));
    for (const MapCell &c : cells) {
        QCOMPARE(c.contacts.size(), std::size_t(2));
        QCOMPARE(c.contacts[0].index, 1);
        QCOMPARE(c.contacts[1].index, 2);
        QCOMPARE(c.result.index, LoopSimulation::worst(c.contacts).index);
    }
    QCOMPARE(cells[0].hand, 0.03);
    QCOMPARE(cells[3].hand, 0.07);
    const QByteArray csv = mapCsv(cells, {});
    const QList<QByteArray> lines = csv.trimmed().split('\n');
    QCOMPARE(lines.size(), 1 + 4 * 2);
    QVERIFY2(lines[0].endsWith(",contact_s,hand,contact,damped_at_rest,theta_eq"),
             lines[0].constData());
    QVERIFY2(lines[1].contains(",0.03,1,"), lines[1].constData());
    QVERIFY2(lines[2].contains(",0.03,2,"), lines[2].constData());
    QVERIFY2(lines[8].contains(",0.07,2,"), lines[8].constData());
    // A panel per hand, each cell telling which contact coloured it.
    const QByteArray svg = mapSvg(cells, {}, 4);
    QVERIFY(svg.contains("hand 0.03 N·m"));
    QVERIFY(svg.contains("hand 0.07 N·m"));
    QCOMPARE(svg.count("of 2, the worst)"), 4);
    // Hands are checked like any value, naming the hand.
    spec.hands = {0.05, 11};
    QVERIFY2(checkSpec(spec).contains(u"hand 11 N·m"), qPrintable(checkSpec(spec)));
}

void TestStabilityMap::badSpecs()
{
    MapSpec spec;
    spec.field = {QStringLiteral("speed"), {1}};
    QVERIFY(checkSpec(spec).contains(u"no tuning field 'speed'"));
    spec.field = {QStringLiteral("M_adm"), {-1}};
    QVERIFY(checkSpec(spec).contains(u"M_adm"));
    spec.field = {};
    spec.delays = {0, 11};
    QVERIFY(checkSpec(spec).contains(u"delay"));
    spec.delays = {0};
    spec.threads = 0;
    QVERIFY(checkSpec(spec).contains(u"threads must be from 1 to 64, got 0"));
}

QTEST_GUILESS_MAIN(TestStabilityMap)
#include "tst_stabilitymap.moc"
