// What the editor edits as one undoable whole: the device's parameters, the host's reference
// model, the device's effect block and its passivity controller. A profile's tuning without its
// name, notes and bridge.
#pragma once

#include "model/effects.h"
#include "model/params.h"
#include "model/passivity.h"

namespace hatpic {

struct Tuning
{
    DeviceParams device;
    HostParams host;
    EffectParams effects;
    PassivityParams passivity;

    friend bool operator==(const Tuning &, const Tuning &) = default;
};

} // namespace hatpic
