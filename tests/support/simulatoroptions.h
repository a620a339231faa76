// Connection options to a new in-process simulated joystick, made as the programs make them for
// "--port sim": the test holds the joystick (its hand, its link's seams) through the options.
#pragma once

#include "session/devicesession.h"
#include "session/sessiontypes.h"
#include "sim/simlink.h"
#include "sim/simulatedjoystick.h"

#include <memory>

namespace hatpic::test {

//! A fresh SimulatedJoystick of `config` speaking the protocol `choice` asks for (Auto: the
//! config's), as the options' link.
inline ConnectOptions simulatorOptions(const SimulatedDevice::Config &config = {},
                                       ProtocolChoice choice = ProtocolChoice::Auto)
{
    ConnectOptions options;
    options.port = QString::fromUtf16(kSimPortName);
    options.protocol = choice;
    auto joystick = std::make_shared<SimulatedJoystick>(config);
    joystick->answerIn(choice);
    options.link = std::move(joystick);
    return options;
}

//! The simulated joystick of options made by simulatorOptions() (else null).
inline SimulatedJoystick *joystickOf(const ConnectOptions &options)
{
    return dynamic_cast<SimulatedJoystick *>(options.link.get());
}

//! The session's simulator link while it is connected to one (the test seams), else null.
inline SimLink *simLinkOf(const DeviceSession &session)
{
    const SimulatedJoystick *joystick = joystickOf(session.options());
    return joystick ? joystick->link() : nullptr;
}

} // namespace hatpic::test
