// One device tuning: the parameters the device renders (model.md), its effect block
// (effects.md) and its passivity block (passivity.md), as one value from the editor to the wire and
// back. A part is absent when it is not part of this tuning: not read yet, not sent, or (effects,
// passivity) a device without the capability.
//
// Plain C++20, no Qt.
#pragma once

#include "effects.h"
#include "params.h"
#include "passivity.h"

#include <optional>

namespace hatpic {

struct DeviceTuning
{
    std::optional<DeviceParams> params;
    std::optional<EffectParams> effects;
    std::optional<PassivityParams> passivity{}; // initialised: `{params, effects}` stays valid

    //! This tuning with each part `newer` has taking its place.
    DeviceTuning updatedBy(const DeviceTuning &newer) const
    {
        return {newer.params ? newer.params : params, newer.effects ? newer.effects : effects,
                newer.passivity ? newer.passivity : passivity};
    }

    friend bool operator==(const DeviceTuning &, const DeviceTuning &) = default;
};

//! True when both have the same parts and each part travels as the same block (float32).
inline bool sameOnWire(const DeviceTuning &a, const DeviceTuning &b)
{
    const auto same = [](const auto &x, const auto &y) {
        return x.has_value() == y.has_value() && (!x || sameOnWire(*x, *y));
    };
    return same(a.params, b.params) && same(a.effects, b.effects) && same(a.passivity, b.passivity);
}

} // namespace hatpic
