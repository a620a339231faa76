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

double EnableGate::reference(double pRef, bool engaged, int knob)
{
    Knob &k = m_knobs[std::size_t(knob)];
    if (!k.started) {
        // The first sample: released from the start holds the reference where the knob is.
        k.started = true;
        k.wasEngaged = engaged;
        k.held = pRef;
    }
    if (engaged && !k.wasEngaged)
        k.offset = pRef - k.held; // re-anchored: goes on from the held reference
    k.wasEngaged = engaged;
    if (!engaged)
        return k.held;
    k.held = pRef - k.offset;
    return k.held;
}

} // namespace hatpic::bridge
