// Tests for the wrenches' timing as the Bridge panel shows it: median and 95th percentile of the
// recent values, the stamp's one-way delay, the device's echo of a τ_ext asked for, and the
// losses estimated from arrival gaps (a pause is not a loss).
#include "bridge/wrenchtiming.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <random>

using namespace hatpic::bridge;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

} // namespace

class TestWrenchTiming : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void spreadOfRecentValues()
    {
        RecentValues values;
        QVERIFY(std::isnan(values.spread().median));
        QCOMPARE(values.spread().count, 0u);
        for (int i = 1; i <= 100; ++i)
            values.add(i); // 1 … 100 in any order gives the same ranks
        QCOMPARE(values.spread().median, 50.0);
        QCOMPARE(values.spread().p95, 95.0);
        // Only the last kRecent count: 1000 values of 7 push the others out.
        for (int i = 0; i < 1000; ++i)
            values.add(7);
        QCOMPARE(values.spread().median, 7.0);
        QCOMPARE(values.spread().p95, 7.0);
        QCOMPARE(values.spread().count, 1100u);
    }

    void stampDelayAndAge()
    {
        WrenchTiming timing;
        // Sent 20 ms before it arrived, every 5 ms, one in ten 50 ms late.
        for (int i = 0; i < 100; ++i) {
            const double now = 10 + i * 0.005;
            const double wall = 1.7e9 + i * 0.005;
            timing.arrived(now, wall, wall - (i % 10 == 9 ? 0.05 : 0.02));
        }
        timing.arrived(11, 1.7e9 + 1, kNaN); // unstamped: not a delay
        const WrenchTiming::Stats s = timing.stats(11.25);
        QVERIFY(std::abs(s.stampDelay.median - 0.02) < 1e-6);
        QVERIFY(std::abs(s.stampDelay.p95 - 0.05) < 1e-6);
        QCOMPARE(s.stampDelay.count, 100u);
        QCOMPARE(s.unstamped, 1u);
        QVERIFY(std::abs(s.age - 0.25) < 1e-9);
        QVERIFY(std::isnan(WrenchTiming().stats(5).age));
    }

    void lossesFromGaps_data()
    {
        QTest::addColumn<int>("skipEvery"); //!< every Nth message is lost (0: none)
        //! Each arrival late or early by up to this much, uniformly (seeded) [s]
        QTest::addColumn<double>("jitter");
        QTest::addColumn<int>("lost");
        // 200 messages due, 5 ms apart.
        QTest::newRow("none lost") << 0 << 0.0 << 0;
        QTest::newRow("none lost, ±1 ms jitter") << 0 << 0.001 << 0;
        QTest::newRow("one in ten lost") << 10 << 0.0 << 19; // the first 10 teach the interval
        QTest::newRow("one in ten lost, ±1 ms jitter") << 10 << 0.001 << 19;
    }
    void lossesFromGaps()
    {
        QFETCH(int, skipEvery);
        QFETCH(double, jitter);
        QFETCH(int, lost);
        WrenchTiming timing;
        std::mt19937 rng(21);
        std::uniform_real_distribution<double> late(-jitter, jitter);
        for (int i = 0; i < 200; ++i) {
            const double now = i * 0.005 + late(rng);
            if (skipEvery && i % skipEvery == skipEvery - 1)
                continue;
            timing.arrived(now, 0, kNaN);
        }
        const WrenchTiming::Stats s = timing.stats(1);
        QCOMPARE(s.lost, std::uint64_t(lost));
        QVERIFY2(std::abs(s.interval - 0.005) <= jitter / 2 + 1e-12,
                 qPrintable(QString::number(s.interval)));
    }

    void aPauseIsNotALoss()
    {
        WrenchTiming timing;
        timing.setPauseAfter(0.5);
        for (int i = 0; i < 20; ++i)
            timing.arrived(i * 0.01, 0, kNaN);
        timing.arrived(0.19 + 3, 0, kNaN);    // three seconds of silence
        timing.arrived(0.19 + 3.04, 0, kNaN); // 40 ms: three lost
        const WrenchTiming::Stats s = timing.stats(4);
        QCOMPARE(s.pauses, 1u);
        QCOMPARE(s.lost, 3u);
    }

    void echoOfTheTorqueAsked()
    {
        WrenchTiming timing;
        timing.torqueAsked(0.077, 1.000);
        timing.sampleShows(0.0, 1.001);                  // not yet
        timing.sampleShows(double(float(0.077)), 1.003); // as float32, as it travels: 3 ms
        timing.sampleShows(0.077, 1.004);                // shown again: measured once
        WrenchTiming::Stats s = timing.stats(2);
        QCOMPARE(s.echoDelay.count, 1u);
        QVERIFY(std::abs(s.echoDelay.median - 0.003) < 1e-9);

        // Two changes in a row: the device shows only the second, which is measured; the first
        // was overtaken and is not.
        timing.torqueAsked(0.1, 2.000);
        timing.torqueAsked(0.2, 2.001);
        timing.sampleShows(0.2, 2.006);
        timing.sampleShows(0.1, 2.007); // too late: it was dropped with the second's echo
        s = timing.stats(3);
        QCOMPARE(s.echoDelay.count, 2u);
        QVERIFY(std::abs(s.echoDelay.p95 - 0.005) < 1e-9);

        // A value the device never shows is forgotten after kEchoTimeout.
        timing.torqueAsked(0.3, 3.0);
        timing.sampleShows(0.0, 3.0 + WrenchTiming::kEchoTimeout + 0.1);
        timing.sampleShows(0.3, 3.0 + WrenchTiming::kEchoTimeout + 0.2);
        QCOMPARE(timing.stats(5).echoDelay.count, 2u);

        // A sample decoded before the wrench arrived is not its echo.
        timing.torqueAsked(0.4, 6.0);
        timing.sampleShows(0.4, 5.999);
        QCOMPARE(timing.stats(7).echoDelay.count, 2u);
    }

    void pendingEchoesAreBounded()
    {
        // More changes than kPendingEchoes without an echo: the oldest are forgotten, the
        // newest still measured.
        WrenchTiming timing;
        for (std::size_t i = 0; i < 3 * WrenchTiming::kPendingEchoes; ++i)
            timing.torqueAsked(0.001 * double(i + 1), 1 + 0.001 * double(i));
        timing.sampleShows(0.001, 1.5); // the very first: long gone
        QCOMPARE(timing.stats(2).echoDelay.count, 0u);
        const std::size_t last = 3 * WrenchTiming::kPendingEchoes - 1;
        timing.sampleShows(0.001 * double(last + 1), 1.5);
        QCOMPARE(timing.stats(2).echoDelay.count, 1u);
    }
};

QTEST_GUILESS_MAIN(TestWrenchTiming)
#include "tst_wrenchtiming.moc"
