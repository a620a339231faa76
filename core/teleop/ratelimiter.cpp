#include "teleop/ratelimiter.h"

namespace hatpic::bridge {

bool RateLimiter::due(double t)
{
    constexpr double kTolerance = 1e-6; // a device clock's microsecond rounding [s]
    // A clock that went back (a new connection) starts over.
    if (!m_next || t < *m_next - 2 * m_period) {
        m_next = t + m_period;
        return true;
    }
    if (t < *m_next - kTolerance)
        return false;
    *m_next += m_period;
    if (*m_next <= t) // fell behind (a gap): the next one is a period from now
        *m_next = t + m_period;
    return true;
}

} // namespace hatpic::bridge
