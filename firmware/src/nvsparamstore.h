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
#include <cstdint>

namespace hatpic::esp32 {

class NvsParamStore final : public fw::ParamStore
{
public:
    static constexpr const char *kNamespace = "hatpic";
    static constexpr const char *kKey = "settings"; //!< knob 1's blob
    //! Knob `axis`'s key: kKey for knob 1, "settings2" … "settings4" for the further knobs of
    //! a board with several (each blob the same layout, settingsblob.h).
    static const char *key(std::uint8_t axis);

    //! False when nothing was saved (first boot, erased NVS), or the blob is of another size or
    //! version or fails its CRC: the device core then uses the spec defaults.
    bool load(std::uint8_t axis, fw::StoredSettings &out) override;
    //! nvs_open, nvs_set_blob, nvs_commit (what Preferences::putBytes does), so that a failure
    //! can name its step and ESP-IDF's error (failure()).
    bool save(std::uint8_t axis, const fw::StoredSettings &settings) override;
    std::string_view failure() const override { return {m_failure.data(), m_failureSize}; }

private:
    std::array<char, 96> m_failure{}; //!< "NVS nvs_set_blob: ESP_ERR_NVS_NOT_ENOUGH_SPACE"
    std::size_t m_failureSize = 0;
};

} // namespace hatpic::esp32
