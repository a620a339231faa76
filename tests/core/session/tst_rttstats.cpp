// RttStats: last, median over a bounded window, maximum.
#include "session/rttstats.h"

#include <QTest>

using namespace hatpic;

class TestRttStats : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void empty();
    void median_data();
    void median();
    void windowIsBounded();
};

void TestRttStats::empty()
{
    RttStats r;
    QVERIFY(r.isEmpty());
    QCOMPARE(r.last(), -1.0);
    QCOMPARE(r.median(), -1.0);
    QCOMPARE(r.max(), -1.0);
}

void TestRttStats::median_data()
{
    QTest::addColumn<QList<double>>("values");
    QTest::addColumn<double>("median");
    QTest::newRow("one") << QList<double>{4} << 4.0;
    QTest::newRow("two: mean of the middle pair") << QList<double>{1, 3} << 2.0;
    QTest::newRow("odd, unsorted") << QList<double>{9, 1, 2} << 2.0;
    QTest::newRow("outlier does not move it") << QList<double>{1, 1, 1, 500} << 1.0;
}

void TestRttStats::median()
{
    QFETCH(QList<double>, values);
    QFETCH(double, median);
    RttStats r;
    for (double v : values)
        r.add(v);
    QCOMPARE(r.median(), median);
    QCOMPARE(r.last(), values.last());
    QCOMPARE(r.max(), *std::max_element(values.cbegin(), values.cend()));
    QCOMPARE(r.count(), quint64(values.size()));
}

void TestRttStats::windowIsBounded()
{
    RttStats r;
    r.add(1000); // leaves the window, stays the maximum
    for (int i = 0; i < RttStats::kWindow; ++i)
        r.add(2);
    QCOMPARE(r.median(), 2.0);
    QCOMPARE(r.max(), 1000.0);
    QCOMPARE(r.last(), 2.0);
    r.clear();
    QVERIFY(r.isEmpty());
}

QTEST_GUILESS_MAIN(TestRttStats)
#include "tst_rttstats.moc"
