// What a device announces it has: HELLO_REPLY's capability bits (its formerly reserved byte,
// protocol.md § HELLO_REPLY; effects.md § 3, passivity.md). Wire names, defined at the bottom
// layer because the control cycle's quantities (cyclequantities.h) say which bit brings them.
//
// Plain C++20, no Qt.
#pragma once

#include <cstdint>

namespace hatpic::v2 {

constexpr std::uint8_t kCapabilityEffects = 0x01; //!< SET_EFFECTS, GET_EFFECTS, VIBRATE, τ_fx
//! SET_PASSIVITY, GET_PASSIVITY, τ_pc and R in TELEMETRY (passivity.md). A device with it has
//! the effects capability too (τ_pc follows τ_fx in TELEMETRY).
constexpr std::uint8_t kCapabilityPassivity = 0x02;
//! Several knobs on one device (docs/protocol.md § 2, Several knobs): HELLO_REPLY's `axes`,
//! the `axis` byte of the per-knob commands and replies, SET_FEEDBACK's τ_ext for knobs 2…
//! and TELEMETRY's blocks of knobs 2…. Announced only with two knobs or more; a device with
//! it has the passivity capability too (the knob blocks follow R in TELEMETRY).
constexpr std::uint8_t kCapabilityAxes = 0x04;

} // namespace hatpic::v2
