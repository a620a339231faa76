// What the editor's tests hand it as a push's result, as DeviceParameterLink would.
#pragma once

#include "session/sessiontypes.h"

namespace hatpic {

//! A push the device took: `sent` as it travelled, and its read-back, `received`.
inline CommandResult pushed(const DeviceTuning &sent, const DeviceTuning &received)
{
    CommandResult r;
    r.command = CommandKind::SetParams;
    r.sent = sent;
    r.received = received;
    r.readBack = true;
    r.readBackMatches = sameOnWire(sent, received);
    return r;
}

} // namespace hatpic
