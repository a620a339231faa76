// The port name with which a user picks the in-process simulated joystick ("--port sim", the
// connection bar): the programs read it and make the joystick (simulatedjoystick.h); the
// session never reads it.
#pragma once

namespace hatpic {

inline constexpr char16_t kSimPortName[] = u"sim";

} // namespace hatpic
