// What the editor edits as one undoable whole: the device's parameters, the host's reference
// model and the device's effect block. A profile's tuning without its name, notes and bridge.
#pragma once

#include "model/effects.h"
#include "model/params.h"

namespace hatpic {

struct Tuning
{
    DeviceParams device;
    HostParams host;
    EffectParams effects;

    friend bool operator==(const Tuning &, const Tuning &) = default;
};

} // namespace hatpic
