// Host-side reference generation v_ref, p_ref (paper eq. 5, model.md § 4).
#pragma once

#include "params.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

namespace hatpic {

//! The fields of the host and device parameters that v_ref reads, taken once per parameter
//! change (a sample then costs a subtraction, a comparison and a clamp).
struct ReferenceShape
{
    double theta0 = 0.0;   //!< [rad]
    double deadZone = 0.0; //!< v_ref is 0 while |θ−θ0| < deadZone; −∞: never [rad]
    double halfVMax = 0.0; //!< v_max/2 [m/s or rad/s per rad]
    double vMax = 0.0;     //!< [m/s or rad/s]

    static ReferenceShape from(const HostParams &host, const DeviceParams &device);
};

//! v_ref = clamp((v_max/2)·(θ−θ0), −v_max, v_max), held at 0 inside the dead zone when
//! ref_deadzone is set [m/s or rad/s].
inline double referenceVelocity(const ReferenceShape &shape, double theta)
{
    const double e = theta - shape.theta0;
    if (std::abs(e) < shape.deadZone)
        return 0.0;
    return std::clamp(shape.halfVMax * e, -shape.vMax, shape.vMax);
}
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
    Output update(std::uint32_t t_us, const ReferenceShape &shape, double theta)
    {
        Output out;
        out.v_ref = referenceVelocity(shape, theta);
        if (m_hasLast) {
            // Unsigned subtraction is modulo 2³², which is exactly the wrap rule.
            const std::uint32_t dtUs = t_us - m_lastT;
            const double dt = dtUs * 1e-6;
            if (dt > kMaxGap) {
                ++m_gaps;
                out.gap = true;
            } else {
                m_p += 0.5 * (m_lastV + out.v_ref) * dt;
            }
        }
        m_hasLast = true;
        m_lastT = t_us;
        m_lastV = out.v_ref;
        out.p_ref = m_p;
        return out;
    }
    Output update(std::uint32_t t_us, const HostParams &host, const DeviceParams &device,
                  double theta)
    {
        return update(t_us, ReferenceShape::from(host, device), theta);
    }

    //! Sets p_ref to 0; the next sample integrates from the last one as usual.
    void resetPosition() { m_p = 0.0; }
    //! Forgets everything: p_ref = 0, no previous sample, gap count 0.
    void clear();

    double position() const { return m_p; }
    std::uint64_t gapCount() const { return m_gaps; }

private:
    bool m_hasLast = false; //!< m_lastT and m_lastV hold the previous sample
    std::uint32_t m_lastT = 0;
    double m_lastV = 0.0;
    double m_p = 0.0;
    std::uint64_t m_gaps = 0;
};

} // namespace hatpic
