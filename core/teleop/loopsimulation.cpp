#include "teleop/loopsimulation.h"

#include "model/reference.h"
#include "protocol/v2codec.h"
#include "telemetry/numbertext.h"
#include "teleop/ratelimiter.h"
#include "teleop/wrenchfeedback.h"

#include <algorithm>
#include <cmath>

namespace hatpic::teleop {

namespace {

constexpr double kStep = robot::RobotModel::kStep; //!< the loop's tick, the device's 1 kHz [s]
constexpr double kMaxDuration = 3600;              //!< an hour of virtual time at most [s]
//! The session resends the newest τ_ext this often (FeedbackStream's keep-alive) [s].
constexpr double kKeepAlive = 0.05;

QString sentence(const std::vector<Violation> &violations, const char *what)
{
    return QString::fromUtf8(what) + QString::fromStdString(violations.front().message()) + u'.';
}

} // namespace

class LoopSimulation::Private
{
public:
    explicit Private(const LoopConfig &c);

    LoopConfig config;
    std::unique_ptr<SimulatedDevice> device;
    ReferenceShape shape;
    bridge::WrenchFeedback feedback;
    bridge::RateLimiter rate;
    robot::RobotEnd<double> robot;
    std::int64_t cycles = 0;
    std::int64_t total = 0;
    //! The hand the device is given: config.hand, or its pushes with several contacts.
    HandInput hand;
    double tauExt = 0;    //!< the bridge's τ_ext, last sent to the device [N·m]
    double lastSent = -1; //!< when it was last sent [s]
    bool sendNow = true;  //!< a new τ_ext waits for the next cycle
    quint8 seq = 0;

    // What the figures need, per cycle.
    std::vector<double> theta, x, tauExtSeen;
    std::vector<double> tauPc2, tauExt2; //!< running sums of τ_pc², τ_ext²
    std::vector<double> dissipated;      //!< running sum of −τ_pc·ω·h [J]
    std::vector<char> damped;            //!< τ_pc ≠ 0 (β > 0)
    QString problem;

    //! The cycles of contact `index` (from 0): from its push to the next release.
    std::pair<std::int64_t, std::int64_t> window(int index) const;
    //! The figures of contact `index` over the cycles run so far.
    LoopResult figures(int index) const;
};

LoopSimulation::Private::Private(const LoopConfig &c)
    : config(c), feedback(c.feedback), rate(c.twistRateHz), robot(c.robot),
      total(std::int64_t(std::floor(c.runTime() / kStep + 1e-9)) + 1),
      hand(c.contacts > 1
               ? HandInput::pushing(c.hand.amplitude, c.contacts, c.duration, LoopConfig::kRelease)
               : c.hand)
{
    SimulatedDevice::Config dc;
    dc.protocol = WireProtocol::V2;
    dc.controlRateHz = 1.0 / kStep;
    dc.throttle = false;
    dc.noise = c.noise;
    dc.seed = c.seed;
    dc.hand = hand;
    dc.tauLimit = c.host.tau_limit;
    dc.params = c.device;
    dc.passivity = roundedForWire(c.passivity); // as the device holds it: float32
    device = std::make_unique<SimulatedDevice>(dc);
    // The host's reference reads the parameters the device holds (its floats).
    shape = ReferenceShape::from(c.host, device->params());
    if (c.effects != EffectParams{}) {
        const EffectParams wire = roundedForWire(c.effects, c.host.tau_limit);
        device->receive(v2::encodeFrame(seq++, v2::SetEffects{wire}));
    }
    for (auto *v : {&theta, &x, &tauExtSeen, &tauPc2, &tauExt2, &dissipated})
        v->reserve(std::size_t(total));
    damped.reserve(std::size_t(total));
}

QString LoopSimulation::check(const LoopConfig &config)
{
    if (!std::isfinite(config.duration) || config.duration < LoopResult::kRestWindow ||
        config.duration > kMaxDuration)
        return u"duration must be from 2 to 3600 s, got " + compactNumberText(config.duration) +
               u'.';
    if (config.contacts < 1 || config.contacts > LoopConfig::kMaxContacts)
        return u"contacts must be from 1 to " + QString::number(LoopConfig::kMaxContacts) +
               u", got " + QString::number(config.contacts) + u'.';
    if (config.contacts > 1 && config.hand.kind != HandInput::Kind::Constant)
        return u"contacts above 1 need a constant hand (const:T), got " + config.hand.toSpec() +
               u'.';
    if (config.runTime() > kMaxDuration)
        return u"contacts × duration must be at most 3600 s of virtual time with the releases, "
               u"got " +
               compactNumberText(config.runTime()) + u" s.";
    if (!std::isfinite(config.noise) || config.noise < 0 || config.noise > 1)
        return u"noise must be from 0 to 1 N·m, got " + compactNumberText(config.noise) + u'.';
    if (QString error; !HandInput::parse(config.hand.toSpec(), &error))
        return error;
    if (const auto v = validate(config.device); !v.empty())
        return sentence(v, "The device parameters are not valid: ");
    if (const auto v = validate(roundedForWire(config.device)); !v.empty())
        return sentence(v, "The device parameters are not valid once rounded to the device's "
                           "32-bit floats: ");
    if (const auto v = validate(config.passivity); !v.empty())
        return sentence(v, "The passivity controller's settings are not valid: ");
    if (const auto v = validate(config.host); !v.empty())
        return sentence(v, "The host settings are not valid: ");
    if (const auto v = validate(config.effects, config.host.tau_limit); !v.empty())
        return sentence(v, "The effects are not valid: ");
    if (const auto v = robot::validate(config.robot.robot); !v.empty())
        return sentence(v, "The robot is not valid: ");
    if (const auto v = robot::validate(config.robot.faults); !v.empty())
        return sentence(v, "The network is not valid: ");
    const auto range = [](const char *name, double value, double low, double high,
                          const char *unit) -> QString {
        if (std::isfinite(value) && value > low && value <= high)
            return {};
        return QString::fromUtf8(name) + u" must be above " + compactNumberText(low) +
               u" and at most " + compactNumberText(high) + u' ' + QString::fromUtf8(unit) +
               u", got " + compactNumberText(value) + u'.';
    };
    for (const QString &problem :
         {range("gain", std::abs(config.feedback.gain), -1, bridge::kMaxFeedbackGain, "N·m/N"),
          range("limit", config.feedback.limit, 0, bridge::kMaxFeedbackLimit, "N·m"),
          range("stale", config.feedback.staleAfter, 0, bridge::kMaxStaleAfter, "s"),
          range("twist rate", config.twistRateHz, 0, bridge::kMaxPublishRateHz, "Hz"),
          range("wrench rate", config.robot.rateHz, 0, 1000, "Hz"),
          range("robot stale", config.robot.staleAfter, 0, 10, "s")}) {
        if (!problem.isEmpty())
            return problem;
    }
    return {};
}

std::optional<robot::LoopEquilibrium> LoopSimulation::equilibrium(const LoopConfig &config)
{
    if (config.hand.kind != HandInput::Kind::Constant &&
        config.hand.kind != HandInput::Kind::Step && config.hand.kind != HandInput::Kind::Pushes)
        return std::nullopt;
    // The device renders its floats; the rest is where they balance.
    return robot::loopEquilibrium(roundedToFloat(config.device), config.host, config.hand.amplitude,
                                  config.feedback.gain, config.feedback.limit, config.robot.robot);
}

LoopSimulation::LoopSimulation(const LoopConfig &config) : d(std::make_unique<Private>(config)) {}

LoopSimulation::~LoopSimulation() = default;

bool LoopSimulation::atEnd() const
{
    return d->cycles >= d->total || !d->problem.isEmpty();
}

LoopSimulation::Step LoopSimulation::step()
{
    Private &p = *d;
    const double t = double(p.cycles++) * kStep;
    // The host's τ_ext reaches the device before this cycle: when it changed, and as the
    // session's keep-alive.
    if (p.sendNow || t - p.lastSent >= kKeepAlive - 1e-9) {
        p.device->receive(v2::encodeFrame(p.seq++, v2::SetFeedback{float(p.tauExt)}));
        p.lastSent = t;
        p.sendNow = false;
    }
    const SimulatedDevice::Cycle cycle = p.device->step();

    // The host: the sample's reference, the bridge's stale check, its twist at its rate.
    const double vRef = referenceVelocity(p.shape, cycle.theta);
    const auto setTorque = [&p](double tau) {
        if (tau != p.tauExt) {
            p.tauExt = tau;
            p.sendNow = true;
        }
    };
    setTorque(p.feedback.torqueAt(t));
    if (p.rate.due(cycle.t))
        p.robot.twistSent(vRef, t);

    // The robot's millisecond, and the wrenches the network delivers now.
    p.robot.step(
        t, [](const robot::RobotModel &model) { return model.estimatedForce(); },
        [&](double force) { setTorque(p.feedback.receive(force, t)); });

    Step s;
    s.t = t;
    s.theta = cycle.theta;
    s.omega = cycle.omega;
    s.tauExt = cycle.tau_ext;
    s.tauPc = cycle.tau_pc;
    s.reserve = cycle.pc_reserve;
    s.x = p.robot.model().position();

    if (!std::isfinite(s.theta) || !std::isfinite(s.omega) || !std::isfinite(s.x)) {
        p.problem = u"The loop left the finite numbers at t = " + compactNumberText(t) + u" s.";
        return s;
    }
    const auto last = [](const std::vector<double> &v) { return v.empty() ? 0.0 : v.back(); };
    p.tauPc2.push_back(last(p.tauPc2) + s.tauPc * s.tauPc);
    p.tauExt2.push_back(last(p.tauExt2) + s.tauExt * s.tauExt);
    p.dissipated.push_back(last(p.dissipated) - s.tauPc * s.omega * kStep);
    p.theta.push_back(s.theta);
    p.x.push_back(s.x);
    p.tauExtSeen.push_back(s.tauExt);
    p.damped.push_back(s.tauPc != 0);
    return s;
}

std::pair<std::int64_t, std::int64_t> LoopSimulation::Private::window(int index) const
{
    if (config.contacts <= 1)
        return {0, total};
    const std::int64_t begin = std::llround(hand.pushStart(index) / kStep);
    const std::int64_t end =
        index == config.contacts - 1 ? total : begin + std::llround(hand.pushTime / kStep);
    return {begin, end};
}

LoopResult LoopSimulation::Private::figures(int index) const
{
    LoopResult r;
    r.index = index + 1;
    r.problem = problem;
    const auto [begin, end] = window(index);
    const std::int64_t n = std::min(end, std::int64_t(theta.size()));
    if (n <= begin)
        return r;
    r.dissipatedJ =
        dissipated[std::size_t(n - 1)] - (begin > 0 ? dissipated[std::size_t(begin - 1)] : 0.0);
    const std::int64_t window =
        std::min<std::int64_t>(n - begin, std::llround(LoopResult::kRestWindow / kStep));
    const std::int64_t from = n - window;
    double lo = theta[std::size_t(from)], hi = lo, sumTheta = 0, sumTau = 0, sumX = 0;
    std::int64_t dampedCycles = 0;
    for (std::int64_t i = from; i < n; ++i) {
        const double th = theta[std::size_t(i)];
        lo = std::min(lo, th);
        hi = std::max(hi, th);
        sumTheta += th;
        sumTau += tauExtSeen[std::size_t(i)];
        sumX += x[std::size_t(i)];
        dampedCycles += damped[std::size_t(i)];
    }
    r.p2p = hi - lo;
    r.thetaRest = sumTheta / double(window);
    r.tauExtRest = sumTau / double(window);
    r.xRest = sumX / double(window);
    r.dampedAtRest = double(dampedCycles) / double(window);

    std::int64_t contactCycle = -1;
    for (std::int64_t i = begin; i < n && contactCycle < 0; ++i) {
        if (tauExtSeen[std::size_t(i)] != 0)
            contactCycle = i;
    }
    r.contact = contactCycle >= 0;
    if (!r.contact)
        return r;
    r.contactAt = double(contactCycle) * kStep;
    if (const auto eq = LoopSimulation::equilibrium(config))
        r.thetaEq = eq->theta;

    // The last cycle out of the band around θ_eq.
    std::int64_t lastOut = -1;
    if (std::isfinite(r.thetaEq)) {
        for (std::int64_t i = n - 1; i >= begin; --i) {
            if (std::abs(theta[std::size_t(i)] - r.thetaEq) > LoopResult::kBand) {
                lastOut = i;
                break;
            }
        }
        r.settled = problem.isEmpty() && lastOut < from;
    }
    std::int64_t restCycle = n - 1;
    if (r.settled) {
        restCycle = std::max(lastOut, contactCycle);
        r.settleS = double(restCycle - contactCycle) * kStep;
    }
    const auto span = [&](const std::vector<double> &sums) {
        const double start = contactCycle > 0 ? sums[std::size_t(contactCycle - 1)] : 0.0;
        return sums[std::size_t(restCycle)] - start;
    };
    const double ext = span(tauExt2);
    r.rmsTauPcRatio = ext > 0 ? std::sqrt(span(tauPc2) / ext) : LoopResult::kNaN;
    return r;
}

std::vector<LoopResult> LoopSimulation::contactResults() const
{
    std::vector<LoopResult> out;
    for (int i = 0; i < d->config.contacts; ++i) {
        if (d->window(i).first >= std::int64_t(d->theta.size()) && i > 0)
            break; // not reached yet
        out.push_back(d->figures(i));
    }
    return out;
}

LoopResult LoopSimulation::worst(const std::vector<LoopResult> &contacts)
{
    if (contacts.empty())
        return {};
    const auto badness = [](const LoopResult &r) {
        // Not settled (the wider the swing, the worse) before settled (the slower, the worse).
        return r.settled ? std::pair{0.0, r.settleS}
                         : std::pair{1.0, std::isfinite(r.p2p) ? r.p2p : HUGE_VAL};
    };
    return *std::max_element(
        contacts.begin(), contacts.end(),
        [&](const LoopResult &a, const LoopResult &b) { return badness(a) < badness(b); });
}

LoopResult LoopSimulation::result() const
{
    return worst(contactResults());
}

LoopResult LoopSimulation::run(const LoopConfig &config)
{
    return worst(runContacts(config));
}

std::vector<LoopResult> LoopSimulation::runContacts(const LoopConfig &config)
{
    LoopSimulation loop(config);
    while (!loop.atEnd())
        loop.step();
    return loop.contactResults();
}

} // namespace hatpic::teleop
