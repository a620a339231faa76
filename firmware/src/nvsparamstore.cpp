#include "nvsparamstore.h"

#include "settingsblob.h"

#include <Preferences.h>

namespace hatpic::esp32 {

bool NvsParamStore::load(fw::StoredSettings &out)
{
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

bool NvsParamStore::save(const fw::StoredSettings &settings)
{
    Preferences prefs;
    if (!prefs.begin(kNamespace, /*readOnly=*/false))
        return false;
    const SettingsBlob blob = encodeSettingsBlob(settings);
    const bool written = prefs.putBytes(kKey, blob.data(), blob.size()) == blob.size();
    prefs.end();
    return written;
}

} // namespace hatpic::esp32
