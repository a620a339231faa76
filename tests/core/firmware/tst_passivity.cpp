// The passivity controller's law (passivity.md, "Per control cycle") on its own and inside the
// device core's control cycle: the tank's cap, the deficit carried, the cap on β, nothing at
// rest or without τ_ext, the damping entering the exact discretisation, and β_max = 0 leaving
// the cycle bit for bit as it was without the controller.
#include "firmware/controller.h"
#include "model/admittance.h"
#include "model/paramtable.h"
#include "model/passivity.h"

#include <QTest>

#include <cmath>
#include <vector>

using namespace hatpic;

namespace {

constexpr double kH = 1e-3;

PassivityParams pc(double betaMax, double reserveMax)
{
    PassivityParams p;
    p.pc_damping_max = betaMax;
    p.pc_reserve_max = reserveMax;
    return p;
}

//! A knob that follows its command perfectly, pushed by a hand of constant torque: below the
//! control cycle's actuator seam (the simulator's ideal actuator and the STS3032 are the real
//! ones, tested on their own).
class FollowingKnob : public fw::Actuator<double>
{
public:
    bool start(double &theta) override
    {
        theta = m_theta;
        return true;
    }
    bool measure(fw::Measurement<double> &m) override
    {
        m = {m_theta, m_omega, -handTorque};
        return true;
    }
    bool command(double theta, double omega) override
    {
        m_theta = theta;
        m_omega = omega;
        return true;
    }
    void disable() override {}
    double handTorque = 0;

private:
    double m_theta = 0, m_omega = 0;
};

struct Sample
{
    double theta, omega, tauPc, reserve;
};

//! The knob pushed by the hand against a feedback that follows the knob's rate with a delay of
//! `delayCycles` (a delayed spring-damper: the port gives back more than it takes).
std::vector<Sample> run(const PassivityParams *passivity, int cycles, int delayCycles = 120)
{
    FollowingKnob knob;
    knob.handTorque = 0.05;
    fw::Controller<double>::Config config;
    fw::Controller<double> controller(config, knob);
    DeviceParams params;
    if (passivity)
        controller.setPassivity(*passivity);
    controller.start(params, 0);
    std::vector<double> history;
    std::vector<Sample> out;
    for (int k = 0; k < cycles; ++k) {
        const double theta = controller.last().theta;
        history.push_back(theta);
        const int past = int(history.size()) - 1 - delayCycles;
        const double delayed = past >= 0 ? history[std::size_t(past)] : 0.0;
        const double wall = 0.05;
        controller.setFeedback(delayed > wall ? -2.0 * (delayed - wall) : 0.0,
                               std::uint32_t(k * 1000));
        const auto &r = controller.cycle(std::uint32_t(k * 1000));
        out.push_back({r.theta, r.omega, r.tau_pc, r.pc_reserve});
    }
    return out;
}

} // namespace

class TestPassivity : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void tankStartsFullAndIsCapped()
    {
        PassivityTank<double> tank;
        tank.configure(pc(0.5, 0.02));
        tank.fill();
        QCOMPARE(tank.reserve(), 0.02);
        // The port absorbs (τ_ext opposes ω): R would grow, but stays at R_max.
        const auto s = tank.step(-0.1, 1.0, kH);
        QCOMPARE(s.beta, 0.0);
        QCOMPARE(s.tauPc, 0.0);
        QCOMPARE(s.reserve, 0.02);
    }

    void smallerReserveMaxCapsAtOnce()
    {
        PassivityTank<double> tank;
        tank.configure(pc(0.5, 0.02));
        tank.fill();
        tank.configure(pc(0.5, 0.005));
        QCOMPARE(tank.reserve(), 0.005);
        tank.configure(pc(0.5, 0.05)); // a larger tank does not fill itself
        QCOMPARE(tank.reserve(), 0.005);
    }

    void dampsExactlyTheExcess()
    {
        PassivityTank<double> tank;
        tank.configure(pc(0.5, 0.0));
        tank.fill(); // R = 0: every joule given back is excess
        const double tau = 0.2, omega = 2.0;
        const auto s = tank.step(tau, omega, kH); // R* = −τ·ω·h = −4e-4 J
        const double expected = tau * omega * kH / (omega * omega * kH);
        QCOMPARE(s.beta, expected); // 0.1 < β_max
        QCOMPARE(s.tauPc, -expected * omega);
        QVERIFY(std::abs(s.reserve) < 1e-15);
    }

    void betaIsCappedAndTheDeficitCarried()
    {
        PassivityTank<double> tank;
        tank.configure(pc(0.02, 0.0));
        tank.fill();
        const double tau = 0.2, omega = 2.0;
        const auto s = tank.step(tau, omega, kH);
        QCOMPARE(s.beta, 0.02); // wanted 0.1
        const double deficit = -tau * omega * kH + 0.02 * omega * omega * kH;
        QCOMPARE(s.reserve, deficit);
        QVERIFY(s.reserve < 0);
        // The port now neither gives nor takes (τ_ext·ω = 0 is impossible with τ_ext ≠ 0 and
        // ω ≠ 0 unless tiny): a small opposing τ_ext; the deficit keeps β up until repaid.
        const auto next = tank.step(-1e-9, omega, kH);
        QCOMPARE(next.beta, 0.02);
        QVERIFY(next.reserve > s.reserve);
        QVERIFY(next.reserve < 0);
    }

    void nothingAtRestOrWithoutFeedback()
    {
        PassivityTank<double> tank;
        tank.configure(pc(0.05, 0.0));
        tank.fill();
        tank.step(0.2, 2.0, kH); // leaves a deficit
        const double deficit = tank.reserve();
        QVERIFY(deficit < 0);
        // No feedback (no robot, stale, watchdog): nothing, R holds, even with a deficit.
        auto s = tank.step(0.0, 2.0, kH);
        QCOMPARE(s.beta, 0.0);
        QCOMPARE(s.tauPc, 0.0);
        QCOMPARE(s.reserve, deficit);
        // At rest: nothing, and the static force is untouched.
        s = tank.step(0.2, 0.0, kH);
        QCOMPARE(s.beta, 0.0);
        QCOMPARE(s.reserve, deficit);
        // ω²·h ≤ 1e-12: still nothing.
        s = tank.step(0.2, 1e-5, kH);
        QCOMPARE(s.beta, 0.0);
    }

    void offDoesNothing()
    {
        PassivityTank<double> tank;
        tank.configure(pc(0.0, 0.02));
        tank.fill();
        const auto s = tank.step(0.2, 2.0, kH);
        QCOMPARE(s.beta, 0.0);
        QCOMPARE(s.reserve, 0.02);
    }

    void floatRunsTheSameLaw()
    {
        PassivityTank<float> tank;
        tank.configure(pc(0.5, 0.0));
        tank.fill();
        const auto s = tank.step(0.2f, 2.0f, 1e-3f);
        QVERIFY(std::abs(s.beta - 0.1f) < 1e-6f);
    }

    void parametersValidateNamingFieldRuleAndValue()
    {
        PassivityParams p;
        QVERIFY(validate(p).empty());
        QCOMPARE(kPassivityFields[0].name, std::string_view("pc_damping_max"));
        QCOMPARE(kPassivityFields[1].name, std::string_view("pc_reserve_max"));
        p.pc_damping_max = 1.5;
        p.pc_reserve_max = std::nan("");
        const auto v = validate(p);
        QCOMPARE(v.size(), std::size_t(2));
        QCOMPARE(v[0].field, std::string("pc_damping_max"));
        QVERIFY(v[0].rule.find("≤ 1") != std::string::npos);
        QCOMPARE(v[1].field, std::string("pc_reserve_max"));
        QCOMPARE(v[1].rule, std::string("must be finite"));
        QCOMPARE(firstViolatingField(p), 0);
        p.pc_damping_max = -0.1;
        p.pc_reserve_max = 0.02;
        QCOMPARE(firstViolatingField(p), 0);
        p.pc_damping_max = 0.0;
        p.pc_reserve_max = 1.0;
        QCOMPARE(firstViolatingField(p), -1);
    }

    // ---- in the control cycle ----

    void offIsBitIdenticalToTheCycleWithoutIt()
    {
        // The reference: the controller as it was, with no passivity block set at all (the
        // legacy emulation's path), against β_max = 0 with any tank.
        const std::vector<Sample> without = run(nullptr, 4000);
        const PassivityParams off = pc(0.0, 0.3);
        const std::vector<Sample> with = run(&off, 4000);
        QCOMPARE(with.size(), without.size());
        for (std::size_t k = 0; k < with.size(); ++k) {
            QCOMPARE(with[k].theta, without[k].theta); // exact, not fuzzy
            QCOMPARE(with[k].omega, without[k].omega);
            QCOMPARE(with[k].tauPc, 0.0);
        }
        // The delayed wall does make this loop oscillate: the test would see a difference.
        double lo = 1e9, hi = -1e9;
        for (std::size_t k = 3000; k < without.size(); ++k) {
            lo = std::min(lo, without[k].theta);
            hi = std::max(hi, without[k].theta);
        }
        QVERIFY2(hi - lo > 0.01, qPrintable(QString::number(hi - lo)));
    }

    void onDampsTheDelayedWall()
    {
        const PassivityParams on = pc(0.5, 0.02);
        const std::vector<Sample> with = run(&on, 4000);
        double lo = 1e9, hi = -1e9, mostDamping = 0;
        for (std::size_t k = 0; k < with.size(); ++k) {
            mostDamping = std::max(mostDamping, std::abs(with[k].tauPc));
            QVERIFY(with[k].reserve <= 0.02);
            if (k >= 3000) {
                lo = std::min(lo, with[k].theta);
                hi = std::max(hi, with[k].theta);
            }
        }
        QVERIFY(mostDamping > 0);
        QVERIFY2(hi - lo < 0.003, qPrintable(QString::number(hi - lo)));
    }

    void dampingEntersTheExactDiscretisation()
    {
        // One cycle that the tank must damp: the filter moves as model.md § 3's step with
        // M_adm + β in place of M_adm.
        FollowingKnob knob;
        fw::Controller<double>::Config config;
        fw::Controller<double> controller(config, knob);
        controller.setPassivity(pc(0.5, 0.0));
        DeviceParams params;
        controller.start(params, 0);
        // Get the knob moving with no feedback (no energy through the port yet).
        knob.handTorque = 0.05;
        for (int k = 0; k < 50; ++k)
            controller.cycle(std::uint32_t(k * 1000));
        // Feedback that pushes along the motion: the port gives energy back.
        controller.setFeedback(0.02, 50000);
        const auto &r = controller.cycle(50000);
        // The knob follows perfectly: the filter's state is what this cycle measured.
        const AdmittanceState before{r.theta, r.omega};
        QVERIFY(before.omega > 0.01);
        QVERIFY(r.tau_pc < 0);
        const double beta = -r.tau_pc / before.omega;
        QVERIFY(beta > 0 && beta <= 0.5);
        DeviceParams damped = params;
        damped.M_adm += beta;
        const AdmittanceState expected = admittanceStep(damped, before, -r.tau + r.tau_total, kH);
        controller.cycle(51000); // the next measurement reads the commanded state
        QCOMPARE(controller.last().theta, expected.theta);
        QCOMPARE(controller.last().omega, expected.omega);
    }

    void tankRefillsAtStart()
    {
        FollowingKnob knob;
        fw::Controller<double>::Config config;
        fw::Controller<double> controller(config, knob);
        controller.setPassivity(pc(0.5, 0.02));
        controller.start(DeviceParams{}, 0);
        QCOMPARE(controller.last().pc_reserve, 0.02);
        controller.setPassivity(pc(0.5, 0.01));
        controller.cycle(0);
        QCOMPARE(controller.last().pc_reserve, 0.01);
    }
};

QTEST_GUILESS_MAIN(TestPassivity)
#include "tst_passivity.moc"
