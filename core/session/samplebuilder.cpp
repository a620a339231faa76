#include "samplebuilder.h"

#include "model/cyclequantities.h"
#include "protocol/messages.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace hatpic {

void SampleBuilder::clear()
{
    m_reference.clear();
    for (ReferenceGenerator &reference : m_moreReferences)
        reference.clear();
    m_started = false;
    m_discontinuity = false;
    m_lastDeviceUs = 0;
    m_lastHostUs = 0;
    m_sessionUs = 0;
    m_referenceUs = 0;
}

void SampleBuilder::advanceClock(quint32 deviceUs, qint64 hostUs)
{
    if (m_started) {
        // Unsigned subtraction is the modulo-2³² step of the device clock.
        const quint32 deviceStep = deviceUs - m_lastDeviceUs;
        if (!m_discontinuity && deviceStep * 1e-6 <= kMaxDeviceStep) {
            m_sessionUs += deviceStep;
            m_referenceUs += deviceStep;
        } else {
            m_sessionUs += static_cast<quint64>(std::max<qint64>(1, hostUs - m_lastHostUs));
            // Not integrated across even when the host saw the samples close together
            // (a device clock that jumped, a quick reconnect): model.md § 4 holds p_ref.
            m_referenceUs += static_cast<quint32>(std::lround(kMaxDeviceStep * 1e6)) + 1;
        }
    }
    m_started = true;
    m_discontinuity = false;
    m_lastDeviceUs = deviceUs;
    m_lastHostUs = hostUs;
}

void SampleBuilder::addReference(Sample &sample)
{
    // The reference integrates over device deltas within a connection and holds (counting a
    // gap) wherever t_s did not follow the device clock.
    const auto out = m_reference.update(m_referenceUs, m_referenceShape, sample.theta);
    sample.v_ref = out.v_ref;
    sample.p_ref = out.p_ref;
    if (out.gap)
        sample.flags |= kFlagReferenceGap;
}

Sample SampleBuilder::fromTelemetry(const v2::Telemetry &telemetry, qint64 hostUs)
{
    advanceClock(telemetry.t_us, hostUs);
    Sample s;
    s.t_s = sessionTime();
    forEachCycleQuantity<Sample, v2::Telemetry>([&](const CycleQuantity &, auto to, auto from) {
        const auto &value = telemetry.*from;
        if constexpr (requires { value.has_value(); }) // not sent: unknown
            s.*to = value ? double(*value) : std::numeric_limits<double>::quiet_NaN();
        else
            s.*to = value;
    });
    const double fx = telemetry.tau_fx ? s.tau_fx : 0.0;
    s.tau_total = std::clamp(s.tau_rec + fx + s.tau_ext, -m_tauLimit, m_tauLimit);
    addReference(s);
    if (telemetry.more[0]) {
        // A device with several knobs (kCapabilityAxes): each further knob as it rendered it.
        auto board = std::make_shared<BoardSample>();
        for (std::size_t k = 0; k < telemetry.more.size() && telemetry.more[k]; ++k) {
            const v2::KnobTelemetry &knob = *telemetry.more[k];
            AxisSample &axis = board->more[k];
            axis.theta = knob.theta;
            axis.omega = knob.omega;
            axis.tau = knob.tau;
            axis.tau_rec = knob.tau_rec;
            axis.tau_ext = knob.tau_ext;
            axis.tau_total = std::clamp(double(knob.tau_rec) + knob.tau_fx + knob.tau_ext,
                                        -m_tauLimit, m_tauLimit);
            addReference(k, axis);
            board->axes = int(k) + 2;
        }
        s.board = std::move(board);
    }
    return s;
}

void SampleBuilder::addReference(std::size_t k, AxisSample &axis)
{
    const auto reference = m_moreReferences[k].update(m_referenceUs, m_referenceShape, axis.theta);
    axis.v_ref = reference.v_ref;
    axis.p_ref = reference.p_ref;
}

Sample SampleBuilder::fromLegacy(const legacy::Frame &frame, const legacy::Conversion &conversion,
                                 const AxisTorques &tauExt, qint64 hostUs)
{
    const auto hostClock = static_cast<quint32>(hostUs);
    advanceClock(hostClock, hostUs);
    Sample s;
    s.t_s = sessionTime();
    s.t_us = hostClock;
    constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
    // The IMU branch centres every servo on 1000 itself; the master's centre is configurable.
    s.theta = frame.tilt ? legacy::imuBranchAngle(frame.a) : conversion.ticksToRad(frame.a);
    s.omega = kUnknown;
    s.tau = kUnknown;
    s.tau_rec = recenteringTorque(m_stiffness, s.theta);
    s.tau_ext = tauExt[0];
    // The published firmware has no capability (effects, passivity controller): what one brings
    // is unknown.
    forEachCycleQuantity<Sample>([&s](const CycleQuantity &q, auto member) {
        if constexpr (std::is_same_v<decltype(member), double Sample::*>) {
            if (q.optional())
                s.*member = std::numeric_limits<double>::quiet_NaN();
        }
    });
    const double total = s.tau_rec + s.tau_ext;
    s.tau_total = std::clamp(total, -m_tauLimit, m_tauLimit);
    quint16 flags = kFlagModelEstimated | v2::zoneFlag(stiffnessZone(m_stiffness, s.theta));
    if (std::abs(total) > m_tauLimit)
        flags |= v2::kFlagSaturated;
    s.flags = flags;
    addReference(s);
    if (frame.tilt) {
        auto board = std::make_shared<BoardSample>();
        board->axes = legacy::kImuBranchServos;
        const std::array<int, 4> fields = frame.fields();
        for (std::size_t k = 0; k + 1 < std::size_t(legacy::kImuBranchServos); ++k) {
            AxisSample &axis = board->more[k];
            axis.theta = legacy::imuBranchAngle(fields[k + 1]);
            axis.omega = kUnknown;
            axis.tau = kUnknown;
            axis.tau_rec = recenteringTorque(m_stiffness, axis.theta);
            axis.tau_ext = tauExt[k + 1];
            axis.tau_total = std::clamp(axis.tau_rec + axis.tau_ext, -m_tauLimit, m_tauLimit);
            addReference(k, axis);
        }
        board->roll = legacy::TiltConversion::rollFromField(frame.tilt->roll);
        board->pitch = legacy::TiltConversion::pitchFromField(frame.tilt->pitch);
        s.board = std::move(board);
    }
    return s;
}

} // namespace hatpic
