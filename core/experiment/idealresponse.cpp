#include "idealresponse.h"

#include "protocol/v2codec.h"
#include "sim/simulateddevice.h"

#include <cmath>

namespace hatpic {

QList<Sample> idealResponse(const ExperimentPlan &plan, const DeviceParams &params, double tauLimit,
                            double rateHz)
{
    SimulatedDevice::Config config;
    config.protocol = WireProtocol::V2;
    config.controlRateHz = rateHz;
    config.throttle = false;
    config.ideal = true;
    config.tauLimit = tauLimit;
    config.params = params;
    // The model's knob alone: the runner turns the device's passivity controller off too.
    config.passivity = PassivityParams::off();
    SimulatedDevice device(config);
    QList<Sample> out;
    const auto steps = static_cast<qsizetype>(std::floor(plan.totalDuration() * rateHz)) + 1;
    out.reserve(steps);
    for (qsizetype i = 0; i < steps; ++i) {
        const double t = static_cast<double>(i) / rateHz;
        device.receive(v2::encodeFrame(0, v2::SetFeedback{static_cast<float>(plan.tauExt(t))}));
        const SimulatedDevice::Cycle cycle = device.step();
        Sample s = cycle.toSample();
        s.t_s = t; // the plan's time, as the measured run's samples are aligned to it
        out.append(s);
    }
    return out;
}

} // namespace hatpic
