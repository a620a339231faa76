// fw::ParamStore as a profile file (profile.md), the way hatpic-sim keeps its --state file:
// SAVE_PARAMS writes the whole profile atomically, power-up reads it.
#pragma once

#include "firmware/paramstore.h"

#include <QString>

namespace hatpic {

class ProfileParamStore : public fw::ParamStore
{
public:
    //! @param tauLimit written into the profile's host section [N·m]
    ProfileParamStore(const QString &path, double tauLimit);

    //! False without a warning when the file does not exist; false with warning() set when it
    //! cannot be read or parsed. (Whether the block is valid is the device core's call.)
    bool load(fw::StoredSettings &out) override;
    bool save(const fw::StoredSettings &settings) override;

    QString path() const { return m_path; }
    //! Why the last load() or save() failed; empty when it did not.
    QString warning() const { return m_warning; }

private:
    QString m_path;
    double m_tauLimit;
    QString m_warning;
};

} // namespace hatpic
