// Turns received frames into complete Samples: session clock plus the host's reference model.
//
// Plain value logic with no I/O, owned by the session thread; testable on its own.
#pragma once

#include "model/params.h"
#include "model/reference.h"
#include "model/stiffness.h"
#include "protocol/legacy.h"
#include "protocol/messages.h"
#include "telemetry/sample.h"

#include <QtGlobal>

#include <array>

namespace hatpic {

class SampleBuilder
{
public:
    //! Longest device-clock step that t_s follows; longer steps (gaps) use the host clock [s].
    static constexpr double kMaxDeviceStep = ReferenceGenerator::kMaxGap;

    //! The device's parameters as the host believes them in force (θ0, Q_dz of the reference;
    //! the whole model for legacy estimation).
    void setDeviceParams(const DeviceParams &params)
    {
        m_device = params;
        m_stiffness = StiffnessShape<double>::from(params);
        m_referenceShape = ReferenceShape::from(m_host, m_device);
    }
    const DeviceParams &deviceParams() const { return m_device; }
    void setHostParams(const HostParams &host)
    {
        m_host = host;
        m_referenceShape = ReferenceShape::from(m_host, m_device);
    }
    const HostParams &hostParams() const { return m_host; }
    //! Torque limit τ_total is clamped to [N·m].
    void setTauLimit(double tauLimit) { m_tauLimit = tauLimit; }

    //! p_ref := 0, on every axis.
    void resetReference()
    {
        m_reference.resetPosition();
        for (ReferenceGenerator &reference : m_moreReferences)
            reference.resetPosition();
    }
    //! The next sample comes from a new connection: its device clock is not comparable with
    //! the last one, so t_s advances by host time there.
    void markDiscontinuity() { m_discontinuity = true; }
    //! Back to a fresh session: t_s restarts at 0, p_ref at 0, gap count 0.
    void clear();

    //! @param hostUs host monotonic time of reception [µs]
    Sample fromTelemetry(const v2::Telemetry &telemetry, qint64 hostUs);
    //! A legacy frame: θ from ticks, τ_rec estimated from the model; ω and τ unknown (NaN).
    //! The IMU branch's frame (with its tilt) makes a four-axis sample with roll and pitch,
    //! every knob estimated the same way and given its own reference.
    //! @param tauExt the feedback torque each knob renders (after its conversion) [N·m]
    Sample fromLegacy(const legacy::Frame &frame, const legacy::Conversion &conversion,
                      const AxisTorques &tauExt, qint64 hostUs);

    quint64 referenceGaps() const { return m_reference.gapCount(); }
    //! [s]; divided (not multiplied by 1e-6) so that whole µs give the nearest double
    double sessionTime() const { return static_cast<double>(m_sessionUs) / 1e6; }

private:
    //! Advances the session clock for a sample stamped `deviceUs` (device or host clock).
    void advanceClock(quint32 deviceUs, qint64 hostUs);
    void addReference(Sample &sample);
    //! v_ref and p_ref of further knob k + 2 (board->more[k]), from its own generator.
    void addReference(std::size_t k, AxisSample &axis);

    DeviceParams m_device;
    HostParams m_host;
    // What a sample needs of the parameters, taken once per change.
    StiffnessShape<double> m_stiffness = StiffnessShape<double>::from(m_device);
    ReferenceShape m_referenceShape = ReferenceShape::from(m_host, m_device);
    double m_tauLimit = 0.44;
    ReferenceGenerator m_reference;
    std::array<ReferenceGenerator, kMaxAxes - 1> m_moreReferences; //!< axes 2…
    bool m_started = false;
    bool m_discontinuity = false;
    quint32 m_lastDeviceUs = 0;
    qint64 m_lastHostUs = 0;
    quint64 m_sessionUs = 0; //!< session clock [µs]
    //! Clock the reference integrates over: the device steps it follows, and a step longer
    //! than kMaxGap wherever it did not, so p_ref holds there whatever the host time [µs]
    quint32 m_referenceUs = 0;
};

} // namespace hatpic
