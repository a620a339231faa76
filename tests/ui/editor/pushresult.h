// What the editor's tests hand it as a push's outcome, as DeviceParameterLink would.
#pragma once

#include "session/request.h"

namespace hatpic {

//! A push the device took: `sent` as it travelled, and its read-back, `received`.
inline Outcome pushed(const DeviceTuning &sent, const DeviceTuning &received)
{
    using outcome::ReadBack;
    return Outcome{
        request::Push{sent},
        outcome::Done{sameOnWire(sent, received) ? ReadBack::Matches : ReadBack::Differs},
        received};
}

} // namespace hatpic
