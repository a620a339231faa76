#include "reference.h"

#include <algorithm>
#include <cmath>

namespace hatpic {

double referenceVelocity(const HostParams &host, const DeviceParams &device, double theta)
{
    const double e = theta - device.theta0;
    if (host.ref_deadzone && std::abs(e) < device.Q_dz)
        return 0.0;
    return std::clamp(0.5 * host.v_max * e, -host.v_max, host.v_max);
}

ReferenceGenerator::Output ReferenceGenerator::update(std::uint32_t t_us, const HostParams &host,
                                                      const DeviceParams &device, double theta)
{
    Output out;
    out.v_ref = referenceVelocity(host, device, theta);
    if (m_lastT) {
        // Unsigned subtraction is modulo 2³², which is exactly the wrap rule.
        const std::uint32_t dtUs = t_us - *m_lastT;
        const double dt = dtUs * 1e-6;
        if (dt > kMaxGap) {
            ++m_gaps;
            out.gap = true;
        } else {
            m_p += 0.5 * (m_lastV + out.v_ref) * dt;
        }
    }
    m_lastT = t_us;
    m_lastV = out.v_ref;
    out.p_ref = m_p;
    return out;
}

void ReferenceGenerator::clear()
{
    m_lastT.reset();
    m_lastV = 0.0;
    m_p = 0.0;
    m_gaps = 0;
}

} // namespace hatpic
