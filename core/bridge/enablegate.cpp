#include "enablegate.h"

namespace hatpic::bridge {

EnableGate::EnableGate(bool topic, double timeout) : m_topic(topic), m_timeout(timeout) {}

void EnableGate::received(bool value, double now)
{
    m_value = value;
    m_lastMessage = now;
}

bool EnableGate::engaged(double now) const
{
    if (!m_local)
        return false;
    return !m_topic || (m_value && now - m_lastMessage <= m_timeout);
}

double EnableGate::reference(double pRef, bool engaged)
{
    if (!m_started) {
        // The first sample: released from the start holds the reference where the knob is.
        m_started = true;
        m_wasEngaged = engaged;
        m_held = pRef;
    }
    if (engaged && !m_wasEngaged)
        m_offset = pRef - m_held; // re-anchored: goes on from the held reference
    m_wasEngaged = engaged;
    if (!engaged)
        return m_held;
    m_held = pRef - m_offset;
    return m_held;
}

} // namespace hatpic::bridge
