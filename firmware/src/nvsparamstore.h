// ParamStore in NVS (namespace "hatpic", key "settings"): one settings blob (settingsblob.h),
// versioned and CRC-checked.
//
// load() runs once in setup(), before the tasks exist; save() runs in the link task
// (SAVE_PARAMS). A flash write stalls both cores' cache for a few tens of ms: the control task
// misses those cycles and the servo holds its last goal meanwhile.
#pragma once

#include "firmware/paramstore.h"

#include <array>
#include <cstddef>

namespace hatpic::esp32 {

class NvsParamStore final : public fw::ParamStore
{
public:
    static constexpr const char *kNamespace = "hatpic";
    static constexpr const char *kKey = "settings";

    //! False when nothing was saved (first boot, erased NVS), or the blob is of another size or
    //! version or fails its CRC: the device core then uses the spec defaults.
    bool load(fw::StoredSettings &out) override;
    //! nvs_open, nvs_set_blob, nvs_commit (what Preferences::putBytes does), so that a failure
    //! can name its step and ESP-IDF's error (failure()).
    bool save(const fw::StoredSettings &settings) override;
    std::string_view failure() const override { return {m_failure.data(), m_failureSize}; }

private:
    std::array<char, 96> m_failure{}; //!< "NVS nvs_set_blob: ESP_ERR_NVS_NOT_ENOUGH_SPACE"
    std::size_t m_failureSize = 0;
};

} // namespace hatpic::esp32
