#include "profileparamstore.h"

#include "profile/profile.h"

#include <QFileInfo>

namespace hatpic {

ProfileParamStore::ProfileParamStore(const QString &path, double tauLimit)
    : m_path(path), m_tauLimit(tauLimit)
{}

bool ProfileParamStore::load(fw::StoredSettings &out)
{
    m_warning.clear();
    if (!QFileInfo::exists(m_path))
        return false;
    const ProfileReadResult read = readProfile(m_path);
    if (!read.ok()) {
        m_warning = QStringLiteral("State file %1 ignored: %2")
                        .arg(m_path, read.errors.join(QStringLiteral("; ")));
        return false;
    }
    out.params = read.profile->device;
    out.effects = read.profile->effects;
    return true;
}

bool ProfileParamStore::save(const fw::StoredSettings &settings)
{
    Profile profile;
    profile.name = QStringLiteral("hatpic-fw-host state");
    profile.notes = QStringLiteral("Parameters saved by hatpic-fw-host (SAVE_PARAMS).");
    profile.device = settings.params;
    profile.effects = settings.effects;
    profile.host.tau_limit = m_tauLimit;
    m_warning = writeProfile(profile, m_path);
    return m_warning.isEmpty();
}

} // namespace hatpic
