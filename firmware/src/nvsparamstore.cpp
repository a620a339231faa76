#include "nvsparamstore.h"

#include "settingsblob.h"

#include "model/axes.h"

#include <Preferences.h>
#include <esp_err.h>
#include <nvs.h>

#include <array>
#include <string_view>

namespace hatpic::esp32 {

const char *NvsParamStore::key(std::uint8_t axis)
{
    static constexpr std::array<const char *, kMaxAxes> kKeys = {kKey, "settings2", "settings3",
                                                                 "settings4"};
    return axis < kKeys.size() ? kKeys[axis] : kKey;
}

bool NvsParamStore::load(std::uint8_t axis, fw::StoredSettings &out)
{
    const char *const kKey = key(axis);
    Preferences prefs;
    if (!prefs.begin(kNamespace, /*readOnly=*/true))
        return false; // the namespace does not exist yet
    // Up to the current size: an older, shorter blob (version 1) is read too.
    SettingsBlob blob{};
    const std::size_t length = prefs.isKey(kKey) ? prefs.getBytesLength(kKey) : 0;
    const bool read =
        length > 0 && length <= blob.size() && prefs.getBytes(kKey, blob.data(), length) == length;
    prefs.end();
    return read && decodeSettingsBlob(std::span<const std::uint8_t>(blob).first(length), out);
}

bool NvsParamStore::save(std::uint8_t axis, const fw::StoredSettings &settings)
{
    const char *const kKey = key(axis);
    const SettingsBlob blob = encodeSettingsBlob(settings);
    const char *step = "nvs_open";
    nvs_handle_t handle = 0;
    esp_err_t error = nvs_open(kNamespace, NVS_READWRITE, &handle);
    if (error == ESP_OK) {
        step = "nvs_set_blob";
        error = nvs_set_blob(handle, kKey, blob.data(), blob.size());
        if (error == ESP_OK) {
            step = "nvs_commit";
            error = nvs_commit(handle);
        }
        nvs_close(handle);
    }
    m_failureSize = 0;
    if (error != ESP_OK) {
        // "NVS <step>: <error name>", cut to the buffer; no allocation.
        for (std::string_view part :
             {std::string_view("NVS "), std::string_view(step), std::string_view(": "),
              std::string_view(esp_err_to_name(error))}) {
            for (const char c : part) {
                if (m_failureSize < m_failure.size())
                    m_failure[m_failureSize++] = c;
            }
        }
    }
    return error == ESP_OK;
}

} // namespace hatpic::esp32
