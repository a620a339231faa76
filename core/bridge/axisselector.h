// The operator's choice of the axis knob 1 drives (ros.md § Choosing the knob's axis): the
// paper's way of steering several dimensions with one knob. A request takes effect only while
// the knob rests in its dead zone, and the references go on without a jump: the pose the knob
// gave the axis it leaves stays there, and the pose on the axis it takes goes on from what that
// axis held. Plain C++, no middleware, no Qt; the caller holds the lock.
#pragma once

#include "profile/bridgesettings.h"

#include <array>
#include <cstdint>
#include <optional>

namespace hatpic::bridge {

//! Knob 1's pose on each of the six twist places (Component::slot()): what it gives the axis it
//! drives, and holds on the axes it drove before [m or rad].
using SlotPose = std::array<double, 6>;

class AxisSelector
{
public:
    //! Knob 1 drives `axis`, nothing chosen yet.
    explicit AxisSelector(Component axis = {});

    //! The default axis (the settings' for the reference mode) while the operator has chosen
    //! none; once they have, theirs stays.
    void setDefault(Component axis);
    //! The operator asks for `axis`: it becomes pending, and is driven (and its component felt)
    //! from the first sample in the dead zone (update()). Asking for the axis a choice already
    //! drives cancels a pending one.
    void request(Component axis);

    //! Every sample, with knob 1's p_ref as the robot sees it and whether the knob is in its
    //! dead zone: switches to the pending axis when `inDeadZone`. True when it switched.
    bool update(double pRef, bool inDeadZone);

    Component axis() const { return m_axis; }                      //!< driven now
    std::optional<Component> pending() const { return m_pending; } //!< asked, not yet driven
    //! Whether the axis driven is the operator's choice (rather than the settings'): the knob
    //! then feels the wrench component of that axis (force.x for linear.x, …).
    bool chosen() const { return m_chosen; }
    std::uint64_t switches() const { return m_switches; } //!< taken effect since construction

    //! Knob 1's pose on every place for its p_ref `pRef`: the driven axis's goes on from what
    //! it held when it was taken, the others hold what they had when they were left.
    SlotPose pose(double pRef) const;

private:
    Component m_axis;
    std::optional<Component> m_pending;
    bool m_chosen = false;
    SlotPose m_held{};   //!< each place's pose when it was left (the driven one's when taken)
    double m_anchor = 0; //!< p_ref when the driven axis was taken
    std::uint64_t m_switches = 0;
};

} // namespace hatpic::bridge
