// Legacy protocol conversions: position ticks ↔ angle, feedback torque ↔ load units.
#include "protocol/legacy.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <numbers>

using namespace hatpic::legacy;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kTick = 2.0 * kPi / 4096.0; //!< one tick [rad]
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
} // namespace

class TestLegacyConversion : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void ticksToRad_data()
    {
        QTest::addColumn<int>("center");
        QTest::addColumn<int>("ticks");
        QTest::addColumn<double>("theta");
        QTest::newRow("default center is zero") << 1000 << 1000 << 0.0;
        QTest::newRow("quarter turn up") << 1000 << 2024 << kPi / 2;
        QTest::newRow("half turn up") << 1000 << 3048 << kPi;
        QTest::newRow("quarter turn down, below tick 0") << 1000 << -24 << -kPi / 2;
        QTest::newRow("one tick") << 1000 << 1001 << kTick;
        QTest::newRow("tick 0") << 1000 << 0 << -1000 * kTick;
        QTest::newRow("tick 4095") << 1000 << 4095 << 3095 * kTick;
        QTest::newRow("center 2048") << 2048 << 2048 << 0.0;
        QTest::newRow("center 2048, tick 0") << 2048 << 0 << -kPi;
    }
    void ticksToRad()
    {
        QFETCH(int, center);
        QFETCH(int, ticks);
        QFETCH(double, theta);
        Conversion conversion;
        conversion.centerTicks = center;
        QVERIFY(qAbs(conversion.ticksToRad(ticks) - theta) < 1e-12);
    }

    void radToTicks_data()
    {
        QTest::addColumn<int>("center");
        QTest::addColumn<double>("theta");
        QTest::addColumn<int>("ticks");
        QTest::newRow("zero") << 1000 << 0.0 << 1000;
        QTest::newRow("quarter turn") << 1000 << kPi / 2 << 2024;
        QTest::newRow("0.49 tick rounds down") << 1000 << 0.49 * kTick << 1000;
        QTest::newRow("0.51 tick rounds up") << 1000 << 0.51 * kTick << 1001;
        QTest::newRow("half tick rounds away from center") << 0 << 0.5 * kTick << 1;
        QTest::newRow("minus half tick rounds away from center") << 0 << -0.5 * kTick << -1;
        QTest::newRow("not wrapped past a turn") << 1000 << 2 * kPi << 5096;
        QTest::newRow("NaN gives the center") << 1234 << kNaN << 1234;
        QTest::newRow("+inf limited") << 1000 << kInf << kFieldLimit;
        QTest::newRow("-inf limited") << 1000 << -kInf << -kFieldLimit;
        QTest::newRow("center 2048") << 2048 << -kPi << 0;
    }
    void radToTicks()
    {
        QFETCH(int, center);
        QFETCH(double, theta);
        QFETCH(int, ticks);
        Conversion conversion;
        conversion.centerTicks = center;
        QCOMPARE(conversion.radToTicks(theta), ticks);
    }

    void ticksRoundTrip()
    {
        for (const int center : {0, 1000, 2048}) {
            Conversion conversion;
            conversion.centerTicks = center;
            for (int t = 0; t < Conversion::kTicksPerRev; ++t)
                QCOMPARE(conversion.radToTicks(conversion.ticksToRad(t)), t);
        }
    }

    void feedbackToField_data()
    {
        QTest::addColumn<double>("tauLimit");
        QTest::addColumn<int>("clamp");
        QTest::addColumn<double>("tauExt");
        QTest::addColumn<int>("field");
        QTest::newRow("no feedback") << 0.44 << 350 << 0.0 << 1000;
        QTest::newRow("10 % up") << 0.44 << 350 << 0.044 << 1100;
        QTest::newRow("10 % down") << 0.44 << 350 << -0.044 << 900;
        QTest::newRow("exactly at the clamp") << 1.0 << 350 << 0.35 << 1350;
        QTest::newRow("full torque clamped to +350") << 0.44 << 350 << 0.44 << 1350;
        QTest::newRow("beyond the limit clamped to -350") << 0.44 << 350 << -1.0 << 650;
        QTest::newRow("rounds to nearest") << 0.44 << 350 << 0.0442 << 1100;               // 100.45
        QTest::newRow("half rounds away from zero, up") << 1.0 << 350 << 0.0625 << 1063;   // 62.5
        QTest::newRow("half rounds away from zero, down") << 1.0 << 350 << -0.0625 << 937; // −62.5
        QTest::newRow("configurable clamp 500") << 0.44 << 500 << 0.2 << 1455;     // 454.5…
        QTest::newRow("configurable clamp 500 hit") << 0.44 << 500 << 0.3 << 1500; // 681.8…
        QTest::newRow("clamp 0 sends no force") << 0.44 << 0 << 0.3 << 1000;
        QTest::newRow("clamp above 100 %") << 1.0 << 2000 << 1.5 << 2500;
        QTest::newRow("NaN sends no force") << 0.44 << 350 << kNaN << 1000;
        QTest::newRow("+inf clamped") << 0.44 << 350 << kInf << 1350;
        QTest::newRow("-inf clamped") << 0.44 << 350 << -kInf << 650;
        QTest::newRow("tau_limit 0 sends no force") << 0.0 << 350 << 0.1 << 1000;
        QTest::newRow("negative tau_limit sends no force") << -0.44 << 350 << 0.1 << 1000;
        QTest::newRow("negative clamp acts as 0") << 0.44 << -5 << 0.1 << 1000;
        QTest::newRow("huge clamp kept inside a field")
            << 1e-9 << std::numeric_limits<int>::max() << 1.0 << kFieldLimit;
    }
    void feedbackToField()
    {
        QFETCH(double, tauLimit);
        QFETCH(int, clamp);
        QFETCH(double, tauExt);
        QFETCH(int, field);
        Conversion conversion;
        conversion.tauLimit = tauLimit;
        conversion.feedbackClamp = clamp;
        QCOMPARE(conversion.feedbackToField(tauExt), field);
    }

    void fieldToFeedback_data()
    {
        QTest::addColumn<int>("field");
        QTest::addColumn<double>("tauExt");
        QTest::newRow("neutral") << 1000 << 0.0;
        QTest::newRow("+350") << 1350 << 0.154;
        QTest::newRow("-350") << 650 << -0.154;
        QTest::newRow("field 0 is -100 %") << 0 << -0.44;
        QTest::newRow("not clamped") << 3000 << 0.88;
    }
    void fieldToFeedback()
    {
        QFETCH(int, field);
        QFETCH(double, tauExt);
        const Conversion conversion; // tau_limit 0.44
        QVERIFY(qAbs(conversion.fieldToFeedback(field) - tauExt) < 1e-12);
    }

    //! Inside the clamp, field → torque → field gives the same field.
    void feedbackRoundTrip()
    {
        const Conversion conversion;
        for (int a = 1000 - conversion.feedbackClamp; a <= 1000 + conversion.feedbackClamp; ++a)
            QCOMPARE(conversion.feedbackToField(conversion.fieldToFeedback(a)), a);
    }

    void defaults()
    {
        const Conversion conversion;
        QCOMPARE(conversion.centerTicks, 1000);
        QCOMPARE(conversion.feedbackClamp, 350);
        QCOMPARE(conversion.tauLimit, 0.44);
    }
};

QTEST_GUILESS_MAIN(TestLegacyConversion)
#include "tst_legacyconversion.moc"
