// Where SAVE_PARAMS puts the parameters and power-up finds them: NVS on the ESP32, a state
// file for hatpic-fw-host and the simulator, or nothing (kept in RAM only).
#pragma once

#include "model/effects.h"
#include "model/params.h"
#include "model/passivity.h"

#include <string_view>

namespace hatpic::fw {

//! Everything SAVE_PARAMS persists, as one block.
struct StoredSettings
{
    DeviceParams params;
    EffectParams effects;      //!< effects.md § 3: SAVE_PARAMS persists the effect block too
    PassivityParams passivity; //!< passivity.md: and the passivity controller's block
    friend bool operator==(const StoredSettings &, const StoredSettings &) = default;
};

class ParamStore
{
public:
    virtual ~ParamStore() = default;
    //! The saved block; false when there is none or it cannot be read (power-up then uses the
    //! configured block). Validation is the device core's job, not the store's.
    virtual bool load(StoredSettings &out) = 0;
    //! Persists `settings`; false on a storage error: the device answers STORAGE_ERROR and
    //! sends failure() in a LOG frame first.
    virtual bool save(const StoredSettings &settings) = 0;
    //! Why the last save() failed, in words for the user (UTF-8, the OS's own error text
    //! included); empty when it did not fail or no reason is known. Valid until the next save().
    virtual std::string_view failure() const { return {}; }
};

} // namespace hatpic::fw
