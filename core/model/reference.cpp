#include "reference.h"

#include <limits>

namespace hatpic {

ReferenceShape ReferenceShape::from(const HostParams &host, const DeviceParams &device)
{
    ReferenceShape s;
    s.theta0 = device.theta0;
    // |e| < −∞ never holds, not even for a NaN Q_dz (as |e| < NaN does not).
    s.deadZone = host.ref_deadzone ? device.Q_dz : -std::numeric_limits<double>::infinity();
    s.halfVMax = 0.5 * host.v_max;
    s.vMax = host.v_max;
    return s;
}

double referenceVelocity(const HostParams &host, const DeviceParams &device, double theta)
{
    return referenceVelocity(ReferenceShape::from(host, device), theta);
}

void ReferenceGenerator::clear()
{
    m_hasLast = false;
    m_lastT = 0;
    m_lastV = 0.0;
    m_p = 0.0;
    m_gaps = 0;
}

} // namespace hatpic
