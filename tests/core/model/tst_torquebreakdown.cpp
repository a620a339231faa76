// Tests for the torque balance's terms (model.md § 3): hand-computed values, the clamp's
// share, and the balance closing on a trajectory of the model's own admittance filter.

#include "model/admittance.h"
#include "model/stiffness.h"
#include "model/torquebreakdown.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace hatpic;

class TestTorqueBreakdown : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void handComputedTerms();
    void clippedIsWhatTheLimitRemoved();
    void rateOfChange();
    void balanceClosesOnTheFilter();
};

void TestTorqueBreakdown::handComputedTerms()
{
    DeviceParams p;
    p.D_adm = 2e-4; // kg·m²
    p.M_adm = 0.05; // N·m·s/rad
    TorqueBalanceInput in;
    in.omega = 3.0;      // rad/s
    in.omegaDot = 100.0; // rad/s²
    in.tau = -0.12;
    in.tauRec = -0.08;
    in.tauExt = 0.05;
    in.tauTotal = -0.03;
    const TorqueTerms t = torqueTerms(p, in);
    QCOMPARE(t.inertial, 0.02); // 2e-4 · 100
    QCOMPARE(t.damping, 0.15);  // 0.05 · 3
    QCOMPARE(t.tauOp, 0.12);    // −τ
    QCOMPARE(t.tauRec, -0.08);
    QCOMPARE(t.tauExt, 0.05);
    QCOMPARE(t.clipped + 1.0, 1.0); // nothing clamped: −0.08 + 0.05 = −0.03
    // 0.02 + 0.15 − (0.12 − 0.03) = 0.08
    QVERIFY(std::abs(t.residual - 0.08) < 1e-15);
}

void TestTorqueBreakdown::clippedIsWhatTheLimitRemoved()
{
    DeviceParams p;
    TorqueBalanceInput in;
    in.tauRec = -0.5;
    in.tauExt = -0.1;
    in.tauTotal = -0.44; // clamped to tau_limit
    in.saturated = true;
    QVERIFY(std::abs(torqueTerms(p, in).clipped - (-0.16)) < 1e-15);
    in.tauRec = 0.4;
    in.tauExt = 0.3;
    in.tauTotal = 0.44;
    QVERIFY(std::abs(torqueTerms(p, in).clipped - 0.26) < 1e-15);
    // With effects: the clamp took what τ_rec + τ_fx + τ_ext exceeded.
    in.tauFx = 0.1;
    QVERIFY(std::abs(torqueTerms(p, in).clipped - 0.36) < 1e-15);
    QCOMPARE(torqueTerms(p, in).tauFx, 0.1); // a term of its own
    // An effect torque on a sample the clamp left alone is not clipped.
    in.saturated = false;
    in.tauRec = 0.1;
    in.tauExt = 0;
    in.tauTotal = 0.2; // τ_rec + τ_fx
    QCOMPARE(torqueTerms(p, in).clipped, 0.0);
}

void TestTorqueBreakdown::rateOfChange()
{
    QCOMPARE(hatpic::rateOfChange(1.0, 2.0, 1.5, 3.0), 2.0);
    QVERIFY(std::isnan(hatpic::rateOfChange(1.0, 2.0, 1.0, 3.0)));
    QVERIFY(std::isnan(hatpic::rateOfChange(1.0, 2.0, 0.5, 3.0)));
    QVERIFY(std::isnan(hatpic::rateOfChange(0.0, std::nan(""), 1.0, 3.0)));
}

void TestTorqueBreakdown::balanceClosesOnTheFilter()
{
    // A trajectory of the device's own filter under a smooth operator torque: with ω̇ from the
    // central difference, eq. (1)'s terms balance to within the difference's error.
    DeviceParams p;
    p.D_adm = 1e-4;
    p.M_adm = 1e-2;
    const double h = 1e-3;
    const double tauLimit = 0.44;
    const AdmittanceStepper<double> stepper(AdmittanceCoefficients::compute(p, h));
    AdmittanceState s;
    struct Row
    {
        double t, omega, tau, tauRec, tauTotal;
    };
    std::vector<Row> rows;
    for (int k = 0; k < 400; ++k) {
        const double t = k * h;
        const double tau = -0.05 * std::sin(2 * 3.14159265358979 * 2 * t); // operator pushes
        const double tauRec = recenteringTorque(p, s.theta);
        const double tauTotal = std::clamp(tauRec, -tauLimit, tauLimit);
        rows.push_back({t, s.omega, tau, tauRec, tauTotal});
        s = stepper.step(s, -tau + tauTotal);
    }
    double worst = 0;
    double scale = 0;
    for (std::size_t k = 1; k + 1 < rows.size(); ++k) {
        TorqueBalanceInput in;
        in.omega = rows[k].omega;
        // The forward difference, as the breakdown plot estimates ω̇: the sample's u holds over
        // [t_k, t_k+1).
        in.omegaDot =
            hatpic::rateOfChange(rows[k].t, rows[k].omega, rows[k + 1].t, rows[k + 1].omega);
        in.tau = rows[k].tau;
        in.tauRec = rows[k].tauRec;
        in.tauTotal = rows[k].tauTotal;
        const TorqueTerms t = torqueTerms(p, in);
        worst = std::max(worst, std::abs(t.residual));
        scale = std::max(scale, std::abs(t.tauOp));
    }
    QVERIFY(scale > 0.04);
    // The mean slope over the step is u/D − α·(mean ω), against ω_k: off by about α·Δω/2.
    QVERIFY2(worst < 0.05 * scale, qPrintable(QString::number(worst)));
}

QTEST_APPLESS_MAIN(TestTorqueBreakdown)
#include "tst_torquebreakdown.moc"
