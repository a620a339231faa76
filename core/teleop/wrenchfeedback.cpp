#include "teleop/wrenchfeedback.h"

#include <algorithm>
#include <cmath>

namespace hatpic::bridge {

double WrenchFeedback::mapped(double value)
{
    if (!std::isfinite(value))
        return 0.0;
    const double tau = m_settings.gain * value;
    if (!std::isfinite(tau))
        return 0.0;
    return std::clamp(tau, -m_settings.limit, m_settings.limit);
}

double WrenchFeedback::receive(double value, double now, const OtherKnobs &others)
{
    ++m_counters.received;
    m_lastValue = value;
    m_otherValues = others;
    m_lastTime = now;
    m_stale = false;
    if (!std::isfinite(value)) {
        ++m_counters.nonFinite;
        return 0.0;
    }
    if (std::abs(m_settings.gain * value) > m_settings.limit)
        ++m_counters.limited;
    return mapped(value);
}

double WrenchFeedback::torqueAt(double now)
{
    if (!m_stale && now - m_lastTime > m_settings.staleAfter) {
        m_stale = true;
        ++m_counters.stale;
    }
    return m_stale ? 0.0 : mapped(m_lastValue);
}

AxisTorques WrenchFeedback::torquesAt(double now)
{
    AxisTorques torques{torqueAt(now)};
    for (std::size_t k = 0; !m_stale && k < m_otherValues.size(); ++k)
        torques[k + 1] = mapped(m_otherValues[k]);
    return torques;
}

} // namespace hatpic::bridge
