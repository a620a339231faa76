// Where SAVE_PARAMS puts the parameters and power-up finds them: NVS on the ESP32, a state
// file for hatpic-fw-host and the simulator, or nothing (kept in RAM only).
#pragma once

#include "model/effects.h"
#include "model/params.h"
#include "model/passivity.h"

#include <cstdint>
#include <string_view>

namespace hatpic::fw {

//! Everything SAVE_PARAMS persists of one knob, as one block.
struct StoredSettings
{
    DeviceParams params;
    EffectParams effects;      //!< effects.md § 3: SAVE_PARAMS persists the effect block too
    PassivityParams passivity; //!< passivity.md: and the passivity controller's block
    friend bool operator==(const StoredSettings &, const StoredSettings &) = default;
};

//! A store keeps one block per knob: `axis` 0 is knob 1 (a single-knob device's only one), 1…3
//! the further knobs of a device with several.
class ParamStore
{
public:
    virtual ~ParamStore() = default;
    //! Knob `axis`'s saved block; false when there is none or it cannot be read (power-up then
    //! uses the configured block). Validation is the device core's job, not the store's.
    virtual bool load(std::uint8_t axis, StoredSettings &out) = 0;
    //! Persists knob `axis`'s `settings`; false on a storage error: the device answers
    //! STORAGE_ERROR and sends failure() in a LOG frame first.
    virtual bool save(std::uint8_t axis, const StoredSettings &settings) = 0;
    //! Why the last save() failed, in words for the user (UTF-8, the OS's own error text
    //! included); empty when it did not fail or no reason is known. Valid until the next save().
    virtual std::string_view failure() const { return {}; }
};

} // namespace hatpic::fw
