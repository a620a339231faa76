// How many knobs one device carries: the single-knob HATPIC has one, the published IMU branch's
// board four (docs/protocol.md § 1). Samples, recordings and the session carry up to this many.
#pragma once

namespace hatpic {

inline constexpr int kMaxAxes = 4; //!< axes of one device, at most

} // namespace hatpic
