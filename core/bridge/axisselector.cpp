#include "axisselector.h"

namespace hatpic::bridge {

AxisSelector::AxisSelector(Component axis) : m_axis(axis) {}

void AxisSelector::setDefault(Component axis)
{
    if (!m_chosen)
        m_axis = axis;
}

void AxisSelector::request(Component axis)
{
    // The driven axis, asked for before any choice, is a choice too (the knob is to feel its
    // component): that waits for the dead zone like any other.
    if (m_chosen && axis == m_axis)
        m_pending.reset();
    else
        m_pending = axis;
}

bool AxisSelector::update(double pRef, bool inDeadZone)
{
    if (!m_pending || !inDeadZone)
        return false;
    m_held[std::size_t(m_axis.slot())] += pRef - m_anchor; // the axis left keeps its pose
    m_anchor = pRef; // the axis taken goes on from what it holds
    m_axis = *m_pending;
    m_pending.reset();
    m_chosen = true;
    ++m_switches;
    return true;
}

SlotPose AxisSelector::pose(double pRef) const
{
    SlotPose pose = m_held;
    pose[std::size_t(m_axis.slot())] += pRef - m_anchor;
    return pose;
}

} // namespace hatpic::bridge
