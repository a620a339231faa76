#include "nvsparamstore.h"

#include "settingsblob.h"

#include <Preferences.h>

namespace hatpic::esp32 {

bool NvsParamStore::load(fw::StoredSettings &out)
{
    Preferences prefs;
    if (!prefs.begin(kNamespace, /*readOnly=*/true))
        return false; // the namespace does not exist yet
    SettingsBlob blob{};
    const bool read = prefs.isKey(kKey) && prefs.getBytesLength(kKey) == blob.size() &&
                      prefs.getBytes(kKey, blob.data(), blob.size()) == blob.size();
    prefs.end();
    return read && decodeSettingsBlob(blob, out);
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
