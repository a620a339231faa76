// Tests for the derived figures a tuning UI shows (model.md § 3, last paragraph).

#include "model/derived.h"
#include "model/stiffness.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <numbers>

namespace {

using hatpic::DeviceParams;
using hatpic::HostParams;

DeviceParams params(double D, double M, double K_min, double K_max, double N, double Q_dz,
                    double theta0 = 0.0)
{
    DeviceParams p;
    p.D_adm = D;
    p.M_adm = M;
    p.K_min = K_min;
    p.K_max = K_max;
    p.N = N;
    p.Q_dz = Q_dz;
    p.theta0 = theta0;
    return p;
}

struct Scan
{
    double peak = 0; //!< largest |τ_rec| found [N·m]
    double at = 0;   //!< |e| where it was found [rad]
};

// Brute force: a dense scan of |τ_rec| over e ∈ [−π/2, π/2] on both sides of θ0, then a second
// dense scan around the best point. Knows nothing about the shape of K_rec.
Scan bruteForcePeak(const DeviceParams &p)
{
    constexpr double aMax = std::numbers::pi / 2;
    Scan best;
    auto consider = [&](double a) {
        for (double sign : {1.0, -1.0}) {
            const double tau = std::abs(hatpic::recenteringTorque(p, p.theta0 + sign * a));
            if (tau > best.peak) {
                best.peak = tau;
                best.at = a;
            }
        }
    };
    constexpr int kCoarse = 400000;
    const double step = aMax / kCoarse;
    for (int i = 0; i <= kCoarse; ++i)
        consider(i * step);
    const double lo = std::max(0.0, best.at - 2 * step);
    const double hi = std::min(aMax, best.at + 2 * step);
    constexpr int kFine = 40000;
    for (int i = 0; i <= kFine; ++i)
        consider(lo + (hi - lo) * i / kFine);
    return best;
}

} // namespace

Q_DECLARE_METATYPE(hatpic::DeviceParams)

class TestDerived : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void defaultsByHand();
    void figures_data();
    void figures();
    void zeroStiffness();
    void saturationAndRinging_data();
    void saturationAndRinging();
};

// The spec defaults, worked out by hand: K = 0.4, D = 1e-4, M = 1e-2.
void TestDerived::defaultsByHand()
{
    const auto f = hatpic::deriveFigures(DeviceParams{}, HostParams{});
    QCOMPARE(f.omega_n, std::sqrt(4000.0));              // 63.2456 rad/s
    QCOMPARE(f.zeta, 0.01 / (2 * std::sqrt(4e-5)));      // 0.7906
    QCOMPARE(f.timeConstant, 0.01);                      // s
    QCOMPARE(f.peakTauRec, 0.15 * std::numbers::pi / 2); // K_min·π/2 = 0.2356 N·m
    QCOMPARE(f.peakAngle, std::numbers::pi / 2);
    QCOMPARE(f.tauLimit, 0.44);
    QVERIFY(!f.saturates());
    QVERIFY(!f.rings());
}

void TestDerived::figures_data()
{
    QTest::addColumn<DeviceParams>("p");

    QTest::newRow("defaults") << DeviceParams{};
    QTest::newRow("K_min = K_max") << params(1e-4, 1e-2, 0.3, 0.3, 0.1, 0.02);
    QTest::newRow("Q_dz = 0") << params(1e-4, 1e-2, 0.15, 0.4, 0.1, 0.0);
    QTest::newRow("N = pi/2") << params(1e-4, 1e-2, 0.15, 0.4, std::numbers::pi / 2, 0.02);
    QTest::newRow("K_min = 0") << params(1e-4, 1e-2, 0.0, 0.4, 0.1, 0.02);
    QTest::newRow("peak inside the falling band (vertex)")
        << params(1e-4, 1e-2, 0.1, 1.0, 1.0, 0.05);
    QTest::newRow("falling band cut at pi/2") << params(1e-4, 1e-2, 0.1, 1.0, 0.9, 0.05);
    QTest::newRow("strong notch, peak near N") << params(1e-4, 1.5e-2, 0.05, 3.0, 0.12, 0.04);
    QTest::newRow("tiny notch") << params(1e-6, 1e-3, 0.2, 0.25, 1e-4, 0.0);
    QTest::newRow("theta0 = 2.5") << params(1e-4, 1e-2, 0.15, 0.4, 0.1, 0.02, 2.5);
    QTest::newRow("theta0 = -pi") << params(2e-4, 5e-3, 0.1, 2.0, 0.3, 0.1, -std::numbers::pi);
    QTest::newRow("extremes: D 1, M 10, K 50") << params(1.0, 10.0, 50.0, 50.0, 0.5, 0.0);
}

void TestDerived::figures()
{
    QFETCH(DeviceParams, p);
    QVERIFY(hatpic::validate(p).empty());
    HostParams host;
    host.tau_limit = 0.7;
    const auto f = hatpic::deriveFigures(p, host);

    // Definitions of model.md § 3, with K = K_max.
    QCOMPARE(f.omega_n, std::sqrt(p.K_max / p.D_adm));
    QCOMPARE(f.zeta, p.M_adm / (2 * std::sqrt(p.K_max * p.D_adm)));
    QCOMPARE(f.timeConstant, p.D_adm / p.M_adm);
    QCOMPARE(f.tauLimit, 0.7);

    // Peak against the brute-force scan: never below what the scan found, and not above the
    // true maximum (the scan resolves it to ~1e-10 rad).
    const Scan scan = bruteForcePeak(p);
    const double tolerance = 1e-9 * std::max(scan.peak, 1e-12);
    QVERIFY2(f.peakTauRec >= scan.peak - tolerance, qPrintable(QStringLiteral("peak %1 < scan %2")
                                                                   .arg(f.peakTauRec, 0, 'g', 17)
                                                                   .arg(scan.peak, 0, 'g', 17)));
    QVERIFY2(f.peakTauRec <= scan.peak + tolerance, qPrintable(QStringLiteral("peak %1 > scan %2")
                                                                   .arg(f.peakTauRec, 0, 'g', 17)
                                                                   .arg(scan.peak, 0, 'g', 17)));
    // The reported angle is where that peak is.
    QVERIFY(f.peakAngle >= 0 && f.peakAngle <= std::numbers::pi / 2);
    const double atAngle = std::abs(hatpic::recenteringTorque(p, p.theta0 + f.peakAngle));
    QVERIFY(std::abs(atAngle - f.peakTauRec) <= tolerance);
    QCOMPARE(f.saturates(), f.peakTauRec > 0.7);
}

void TestDerived::zeroStiffness()
{
    const DeviceParams p = params(1e-4, 1e-2, 0.0, 0.0, 0.1, 0.02);
    QVERIFY(hatpic::validate(p).empty());
    const auto f = hatpic::deriveFigures(p, HostParams{});
    QCOMPARE(f.omega_n, 0.0);
    QCOMPARE(f.zeta, std::numeric_limits<double>::infinity());
    QCOMPARE(f.timeConstant, 0.01);
    QCOMPARE(f.peakTauRec, 0.0);
    QVERIFY(!f.saturates());
    QVERIFY(!f.rings());
}

void TestDerived::saturationAndRinging_data()
{
    QTest::addColumn<DeviceParams>("p");
    QTest::addColumn<double>("tauLimit");
    QTest::addColumn<bool>("saturates");
    QTest::addColumn<bool>("rings");

    // K_min·π/2 = 0.2356 N·m for the defaults.
    QTest::newRow("defaults vs 0.44") << DeviceParams{} << 0.44 << false << false;
    QTest::newRow("defaults vs 0.2") << DeviceParams{} << 0.2 << true << false;
    QTest::newRow("peak exactly at the limit does not saturate")
        << DeviceParams{} << 0.15 * std::numbers::pi / 2 << false << false;
    QTest::newRow("stiff everywhere: 1 N·m/rad · pi/2")
        << params(1e-4, 1e-2, 1.0, 1.0, 0.1, 0.02) << 0.44 << true << false;
    // ζ = M/(2·sqrt(K·D)) = 1e-3/(2·sqrt(0.4e-4)) = 0.079
    QTest::newRow("light damping rings")
        << params(1e-4, 1e-3, 0.15, 0.4, 0.1, 0.02) << 0.44 << false << true;
    // ζ exactly 0.3 is not "rings" (ζ < 0.3): K·D = 0.0625, sqrt = 0.25, M = 0.15 → ζ = 0.3.
    QTest::newRow("zeta = 0.3 boundary")
        << params(0.0625, 0.15, 0.5, 1.0, 0.1, 0.02) << 10.0 << false << false;
}

void TestDerived::saturationAndRinging()
{
    QFETCH(DeviceParams, p);
    QFETCH(double, tauLimit);
    QFETCH(bool, saturates);
    QFETCH(bool, rings);
    HostParams host;
    host.tau_limit = tauLimit;
    const auto f = hatpic::deriveFigures(p, host);
    QCOMPARE(f.saturates(), saturates);
    QCOMPARE(f.rings(), rings);
}

QTEST_GUILESS_MAIN(TestDerived)
#include "tst_derived.moc"
