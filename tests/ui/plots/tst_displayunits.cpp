// DisplayUnits: unit text, factor from SI and readable values for every channel and mode.
#include "plots/displayunits.h"

#include <QTest>

#include <limits>
#include <numbers>

using namespace hatpic;

class TestDisplayUnits : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void units_data();
    void units();
    void formats_data();
    void formats();
};

void TestDisplayUnits::units_data()
{
    QTest::addColumn<bool>("degrees");
    QTest::addColumn<ReferenceMode>("mode");
    QTest::addColumn<Channel>("channel");
    QTest::addColumn<QString>("unit");
    QTest::addColumn<double>("scale");
    const double deg = 180.0 / std::numbers::pi;
    const auto T = ReferenceMode::Translation;
    const auto R = ReferenceMode::Rotation;
    QTest::newRow("θ in rad") << false << T << Channel::Theta << QStringLiteral("rad") << 1.0;
    QTest::newRow("θ in degrees") << true << T << Channel::Theta << QStringLiteral("°") << deg;
    QTest::newRow("ω in degrees") << true << T << Channel::Omega << QStringLiteral("°/s") << deg;
    QTest::newRow("τ_rec never converts")
        << true << R << Channel::TauRec << QStringLiteral("N·m") << 1.0;
    QTest::newRow("v_ref translation")
        << true << T << Channel::VRef << QStringLiteral("m/s") << 1.0;
    QTest::newRow("p_ref translation") << true << T << Channel::PRef << QStringLiteral("m") << 1.0;
    QTest::newRow("v_ref rotation, rad")
        << false << R << Channel::VRef << QStringLiteral("rad/s") << 1.0;
    QTest::newRow("p_ref rotation, degrees")
        << true << R << Channel::PRef << QStringLiteral("°") << deg;
}

void TestDisplayUnits::units()
{
    QFETCH(bool, degrees);
    QFETCH(ReferenceMode, mode);
    QFETCH(Channel, channel);
    QFETCH(QString, unit);
    QFETCH(double, scale);
    const DisplayUnits units(degrees, mode);
    QCOMPARE(units.unit(channel), unit);
    QCOMPARE(units.scale(channel), scale);
}

void TestDisplayUnits::formats_data()
{
    QTest::addColumn<bool>("degrees");
    QTest::addColumn<Channel>("channel");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("text");
    QTest::newRow("radians, 4 decimals")
        << false << Channel::Theta << -0.05518 << QStringLiteral("−0.0552\u2009rad");
    QTest::newRow("degrees, 2 decimals")
        << true << Channel::Theta << std::numbers::pi / 4 << QStringLiteral("45.00\u2009°");
    QTest::newRow("torque") << true << Channel::TauTotal << 0.0221
                            << QStringLiteral("0.0221\u2009N·m");
    QTest::newRow("reference, 3 decimals")
        << false << Channel::PRef << 0.2514 << QStringLiteral("0.251\u2009m");
    QTest::newRow("missing value")
        << false << Channel::Tau << std::numeric_limits<double>::quiet_NaN() << QStringLiteral("—");
}

void TestDisplayUnits::formats()
{
    QFETCH(bool, degrees);
    QFETCH(Channel, channel);
    QFETCH(double, value);
    QFETCH(QString, text);
    QCOMPARE(DisplayUnits(degrees, ReferenceMode::Translation).format(channel, value), text);
}

QTEST_GUILESS_MAIN(TestDisplayUnits)
#include "tst_displayunits.moc"
