// Host-side reference generation v_ref, p_ref (paper eq. 5, model.md § 4).
#pragma once

#include "params.h"

#include <cstdint>
#include <optional>

namespace hatpic {

//! v_ref = clamp((v_max/2)·(θ−θ0), −v_max, v_max), held at 0 inside the dead zone when
//! ref_deadzone is set [m/s or rad/s].
double referenceVelocity(const HostParams &host, const DeviceParams &device, double theta);

//! Integrates v_ref into p_ref over device timestamps with the trapezoidal rule.
//!
//! Timestamps are unsigned 32-bit microseconds that wrap; Δt is taken modulo 2³². A step
//! longer than kMaxGap is not integrated across: p_ref holds and the gap is counted.
class ReferenceGenerator
{
public:
    static constexpr double kMaxGap = 0.25; //!< longest step that is integrated [s]

    struct Output
    {
        double v_ref = 0.0; //!< reference velocity [m/s or rad/s]
        double p_ref = 0.0; //!< reference position [m or rad]
        bool gap = false;   //!< this sample followed a gap that was not integrated
    };

    //! Feeds one sample; returns the reference at that sample.
    Output update(std::uint32_t t_us, const HostParams &host, const DeviceParams &device,
                  double theta);

    //! Sets p_ref to 0; the next sample integrates from the last one as usual.
    void resetPosition() { m_p = 0.0; }
    //! Forgets everything: p_ref = 0, no previous sample, gap count 0.
    void clear();

    double position() const { return m_p; }
    std::uint64_t gapCount() const { return m_gaps; }

private:
    std::optional<std::uint32_t> m_lastT;
    double m_lastV = 0.0;
    double m_p = 0.0;
    std::uint64_t m_gaps = 0;
};

} // namespace hatpic
