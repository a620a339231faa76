// The network between knob and robot made worse on purpose: exact delay, jitter that keeps the
// order, a seeded loss fraction, a bound on what is in flight, and the options' rules.
#include "robot/linkfaults.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace hatpic;
using namespace hatpic::robot;

class TestLinkFaults : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void noFaultsDeliversAtOnce();
    void delayIsExact();
    void jitterKeepsTheOrder();
    void lossIsSeededAndNearItsFraction();
    void inFlightIsBounded();
    void badValuesAreNamed_data();
    void badValuesAreNamed();
};

void TestLinkFaults::noFaultsDeliversAtOnce()
{
    FaultyChannel<int> channel(LinkFaults{}, 1);
    QVERIFY(!LinkFaults{}.any());
    channel.send(7, 2.0);
    QList<int> got;
    channel.deliverDue(2.0, [&](int m) { got.append(m); });
    QCOMPARE(got, QList<int>{7});
}

void TestLinkFaults::delayIsExact()
{
    FaultyChannel<int> channel(LinkFaults{.delay = 0.02}, 1);
    channel.send(1, 1.0);
    channel.send(2, 1.001);
    QList<int> got;
    channel.deliverDue(1.0199, [&](int m) { got.append(m); });
    QVERIFY(got.isEmpty());
    channel.deliverDue(1.020, [&](int m) { got.append(m); });
    QCOMPARE(got, QList<int>{1});
    channel.deliverDue(1.021, [&](int m) { got.append(m); });
    QCOMPARE(got, (QList<int>{1, 2}));
    QCOMPARE(channel.counters().delivered, std::uint64_t(2));
}

void TestLinkFaults::jitterKeepsTheOrder()
{
    FaultyChannel<int> channel(LinkFaults{.delay = 0.01, .jitter = 0.05}, 42);
    for (int i = 0; i < 1000; ++i)
        channel.send(i, i * 1e-3);
    QList<int> got;
    double lastDue = 0;
    for (double now = 0; now < 2.0; now += 1e-3) {
        channel.deliverDue(now, [&](int m) {
            got.append(m);
            lastDue = now;
        });
    }
    QCOMPARE(got.size(), 1000);
    for (int i = 0; i < got.size(); ++i)
        QCOMPARE(got[i], i);
    QVERIFY(lastDue >= 0.999 + 0.01); // the last one was delayed at least by the delay
    QVERIFY(lastDue < 0.999 + 0.06 + 1e-3);
}

void TestLinkFaults::lossIsSeededAndNearItsFraction()
{
    const auto lost = [](std::uint64_t seed) {
        FaultyChannel<int> channel(LinkFaults{.loss = 0.2}, seed);
        for (int i = 0; i < 10000; ++i)
            channel.send(i, 0);
        return channel.counters().lost;
    };
    const std::uint64_t a = lost(7);
    QCOMPARE(lost(7), a); // the same seed drops the same messages
    QVERIFY(a > 1800 && a < 2200);
    QVERIFY(lost(8) != a);
}

void TestLinkFaults::inFlightIsBounded()
{
    FaultyChannel<int> channel(LinkFaults{.delay = 10}, 1);
    const std::size_t n = FaultyChannel<int>::kMaxInFlight + 10;
    for (std::size_t i = 0; i < n; ++i)
        channel.send(int(i), 0);
    QCOMPARE(channel.inFlight(), FaultyChannel<int>::kMaxInFlight);
    QCOMPARE(channel.counters().overflow, std::uint64_t(10));
    QList<int> got;
    channel.deliverDue(10, [&](int m) { got.append(m); });
    QCOMPARE(got.first(), 10); // the oldest went first
}

void TestLinkFaults::badValuesAreNamed_data()
{
    QTest::addColumn<double>("delay");
    QTest::addColumn<double>("jitter");
    QTest::addColumn<double>("loss");
    QTest::addColumn<QString>("message");
    QTest::newRow("negative delay")
        << -0.1 << 0.0 << 0.0 << "delay: must be from 0 to 10 s, got -0.1";
    QTest::newRow("huge jitter") << 0.0 << 11.0 << 0.0 << "jitter: must be from 0 to 10 s, got 11";
    QTest::newRow("loss above 1") << 0.0 << 0.0 << 1.5 << "loss: must be from 0 to 1, got 1.5";
    QTest::newRow("NaN loss") << 0.0 << 0.0 << std::numeric_limits<double>::quiet_NaN()
                              << "loss: must be a finite number, got nan";
}

void TestLinkFaults::badValuesAreNamed()
{
    QFETCH(double, delay);
    QFETCH(double, jitter);
    QFETCH(double, loss);
    QFETCH(QString, message);
    const auto violations = validate(LinkFaults{delay, jitter, loss});
    QCOMPARE(violations.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(violations.front().message()), message);
}

QTEST_GUILESS_MAIN(TestLinkFaults)
#include "tst_linkfaults.moc"
