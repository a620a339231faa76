// The quantities of one control cycle, described once: name, unit and meaning, in TELEMETRY's
// order (protocol.md § 3). The device's record (fw::CycleRecord), TELEMETRY (v2::Telemetry), the
// simulator's cycle and the host's Sample each hold a member of that name; TELEMETRY's layout,
// the copies from one record to the next and the sample CSV's columns (kSampleColumns) walk
// this list. A new quantity is a line here, a member of that name in each record, and the code
// that computes it.
//
// Plain C++20, constexpr: the device core reads it too.
#pragma once

#include "capabilities.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace hatpic {

//! One quantity of the control cycle, in SI units.
struct CycleQuantity
{
    std::string_view name;    //!< the member's name in every record; the CSV column's name
    std::string_view unit;    //!< SI unit, e.g. "N·m"; empty for the flags
    std::string_view meaning; //!< what it is, in a few words
    //! The capability (v2::kCapability*) of the devices that send it, after the flags
    //! (effects.md, passivity.md); 0: every device does. Optional in TELEMETRY, read only from a
    //! device that announced it, NaN in a Sample when not sent, a CSV column added later.
    std::uint8_t capability = 0;

    constexpr bool optional() const { return capability != 0; }
};

//! Calls `visit(quantity, &R::member...)` for each quantity of one knob, every quantity of the
//! cycle but its time, in TELEMETRY's order: what a device with several knobs sends again for
//! each further knob (v2::KnobTelemetry, protocol.md § 2).
template<typename... R, typename Visit> constexpr void forEachKnobQuantity(Visit &&visit)
{
    using Q = CycleQuantity;
    visit(Q{"theta", "rad", "knob angle, absolute"}, &R::theta...);
    visit(Q{"omega", "rad/s", "knob rate"}, &R::omega...);
    visit(Q{"tau", "N·m", "interaction torque of eq. (1); the operator's torque is -tau"},
          &R::tau...);
    visit(Q{"tau_rec", "N·m", "re-centering torque"}, &R::tau_rec...);
    visit(Q{"tau_ext", "N·m", "external feedback torque"}, &R::tau_ext...);
    visit(Q{"flags", "", "the device's flags, v2::kFlag* bits"}, &R::flags...);
    visit(Q{"tau_fx", "N·m", "effect torque tau_det + tau_wall + tau_vib", v2::kCapabilityEffects},
          &R::tau_fx...);
    visit(Q{"tau_pc", "N·m", "passivity controller torque -beta*omega", v2::kCapabilityPassivity},
          &R::tau_pc...);
    visit(Q{"pc_reserve", "J", "passivity controller's energy reserve R", v2::kCapabilityPassivity},
          &R::pc_reserve...);
}

//! Calls `visit(quantity, &R::member...)` for each quantity, in TELEMETRY's order: for each
//! record type R, the member of the quantity's name.
template<typename... R, typename Visit> constexpr void forEachCycleQuantity(Visit &&visit)
{
    visit(CycleQuantity{"t_us", "µs", "the cycle's time on the device clock, wraps at 2^32"},
          &R::t_us...);
    forEachKnobQuantity<R...>(visit);
}

//! How many quantities forEachCycleQuantity() visits.
inline constexpr std::size_t kCycleQuantityCount = [] {
    std::size_t n = 0;
    forEachCycleQuantity<>([&n](const CycleQuantity &) { ++n; });
    return n;
}();

} // namespace hatpic
