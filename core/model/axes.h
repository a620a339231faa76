// How many knobs one device carries: the single-knob HATPIC has one, the published IMU branch's
// board four (docs/protocol.md § 1). Samples, recordings and the session carry up to this many.
#pragma once

#include <array>

namespace hatpic {

inline constexpr int kMaxAxes = 4; //!< axes of one device, at most

//! One torque per knob, knob 1 first: the τ_ext the host asks of each [N·m]. A device with
//! fewer knobs ignores the rest.
using AxisTorques = std::array<double, kMaxAxes>;

} // namespace hatpic
