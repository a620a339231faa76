// The name by which a user picks the in-process simulated joystick ("--port sim", the
// connection bar's first entry). Only the reading of a typed port compares a port with it
// (app/common/connectionoptions.cpp: it makes the joystick the program connects through); the
// tuner lists its joystick as a link source under it (ConnectionBar::addSource), and from there
// on the link, not the name, says what is simulated. The session never reads it.
#pragma once

namespace hatpic {

inline constexpr char16_t kSimPortName[] = u"sim";

} // namespace hatpic
