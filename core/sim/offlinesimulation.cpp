#include "offlinesimulation.h"

#include "firmware/devicecore.h"
#include "protocol/v2codec.h"
#include "sim/simulateddevice.h"
#include "telemetry/numbertext.h"

#include <cmath>

namespace hatpic {

namespace {

// floor(duration·rate) must not lose the last row to rounding (2 s · 1000 Hz = 1999.9999…).
constexpr double kRowSlack = 1e-9;
// The simulated device's control rates: its device core's.
constexpr double kMinRateHz = fw::DeviceCore<double>::kMinControlRate;
constexpr double kMaxRateHz = fw::DeviceCore<double>::kMaxControlRate;

bool isFinite(const Sample &s)
{
    for (double value : {s.t_s, s.theta, s.omega, s.tau, s.tau_rec, s.tau_ext, s.tau_fx,
                         s.tau_total, s.v_ref, s.p_ref}) {
        if (!std::isfinite(value))
            return false;
    }
    return true;
}

} // namespace

qint64 OfflineSimulation::rowsFor(const OfflineSimulationConfig &config)
{
    return static_cast<qint64>(std::floor(config.duration * config.rateHz + kRowSlack)) + 1;
}

QString OfflineSimulation::check(const OfflineSimulationConfig &config)
{
    if (!std::isfinite(config.rateHz) || config.rateHz < kMinRateHz || config.rateHz > kMaxRateHz)
        return u"The rate must be from " + compactNumberText(kMinRateHz) + u" to " +
               compactNumberText(kMaxRateHz) + u" Hz, got " + compactNumberText(config.rateHz) +
               u'.';
    if (!std::isfinite(config.duration) || config.duration < 0)
        return u"The duration must be 0 s or more, got " + compactNumberText(config.duration) +
               u'.';
    if (!std::isfinite(config.noise) || config.noise < 0)
        return u"The noise must be 0 N·m or more, got " + compactNumberText(config.noise) + u'.';
    // The hand's own bounds (simulator.md § 4), also for an input that was not parsed.
    if (QString error; !HandInput::parse(config.hand.toSpec(), &error))
        return error;
    if (config.duration * config.rateHz + 1 > static_cast<double>(kMaxRows))
        return u"The simulation would have more than " + QString::number(kMaxRows) +
               u" rows; shorten the duration or lower the rate.";
    if (const auto violations = validate(config.device); !violations.empty())
        return u"The device parameters are not valid: " +
               QString::fromStdString(violations.front().message()) + u'.';
    if (const auto violations = validate(roundedForWire(config.device)); !violations.empty())
        return u"The device parameters are not valid once rounded to the device's 32-bit "
               u"floats: " +
               QString::fromStdString(violations.front().message()) + u'.';
    if (const auto violations = validate(config.host); !violations.empty())
        return u"The host settings are not valid: " +
               QString::fromStdString(violations.front().message()) + u'.';
    if (const auto violations = validate(config.effects, config.host.tau_limit);
        !violations.empty())
        return u"The effects are not valid: " +
               QString::fromStdString(violations.front().message()) + u'.';
    return {};
}

OfflineSimulation::OfflineSimulation(const OfflineSimulationConfig &config)
    : m_config(config), m_rows(rowsFor(config))
{
    SimulatedDevice::Config device;
    device.protocol = WireProtocol::V2;
    device.controlRateHz = config.rateHz;
    device.throttle = false;
    device.ideal = config.ideal;
    device.noise = config.ideal ? 0.0 : config.noise;
    device.seed = config.seed;
    device.hand = config.hand;
    device.tauLimit = config.host.tau_limit;
    device.params = config.device;
    m_device = std::make_unique<SimulatedDevice>(device);
    m_rendered = m_device->params();
    // A host that streams τ_ext = 0, so the device's feedback watchdog stays quiet.
    m_feedback = v2::encodeFrame(0, v2::SetFeedback{0.0f});
    // The effects travel as a host sends them: SET_EFFECTS, rounded for the wire (±π are not
    // floats), before the first cycle, which renders them (its ACK waits in the output nobody
    // takes; no stream was asked for).
    if (config.effects != EffectParams{}) {
        const EffectParams wire = roundedForWire(config.effects, config.host.tau_limit);
        m_device->receive(v2::encodeFrame(1, v2::SetEffects{wire}));
    }
}

OfflineSimulation::~OfflineSimulation() = default;

Sample OfflineSimulation::next()
{
    m_device->receive(m_feedback);
    const SimulatedDevice::Cycle cycle = m_device->step();
    ++m_done;

    Sample sample = cycle.toSample();
    const auto reference = m_reference.update(sample.t_us, m_config.host, m_rendered, cycle.theta);
    sample.v_ref = reference.v_ref;
    sample.p_ref = reference.p_ref;
    if (reference.gap)
        sample.flags |= kFlagReferenceGap;
    if (!isFinite(sample)) {
        m_failed = true;
        m_problem = u"The simulation left the finite numbers at t = " + compactNumberText(cycle.t) +
                    u" s; the hand input or the profile drives the knob beyond what the model "
                    u"can represent.";
    }
    return sample;
}

} // namespace hatpic
