#include "profileparamstore.h"

#include "profile/profile.h"

#include <QDir>
#include <QFileInfo>

namespace hatpic {

namespace {

//! `file` with the device's blocks in it. A field the device holds as the same float keeps
//! the file's value (0.15 stays 0.15, not 0.15000000596…); a changed one is written as the
//! shortest decimal of the device's float (0.45, not 0.44999998807907104: the same numbers
//! `hatpicctl get --json` writes); a block whose mix would break a cross-field rule is the
//! device's whole. When the device's effects need more torque than the file's own
//! host.tau_limit allows (a file written for a weaker device), that limit becomes the
//! device's: the file must read back with what the device holds.
Profile merged(const Profile &file, const fw::StoredSettings &settings, double tauLimit)
{
    const DeviceParams device = tidyDeviceParams(settings.params);
    const EffectParams effects = tidyEffectParams(settings.effects);
    Profile out = file;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        if (float(file.device.field(i)) != float(settings.params.field(i)))
            out.device.setField(i, device.field(i));
    }
    if (!validate(out.device).empty())
        out.device = device;
    const EffectParams fileOnWire = roundedForWire(file.effects, tauLimit);
    for (int i = 0; i < EffectParams::kFieldCount; ++i) {
        if (fileOnWire.field(i) != settings.effects.field(i))
            out.effects.setField(i, effects.field(i));
    }
    if (!validate(out.effects, out.host.tau_limit).empty())
        out.effects = effects;
    if (!validate(out.effects, out.host.tau_limit).empty())
        out.host.tau_limit = shortestFloatDecimal(tauLimit);
    const PassivityParams passivity = tidyPassivityParams(settings.passivity);
    const PassivityParams pcOnWire = roundedForWire(file.passivity);
    for (int i = 0; i < PassivityParams::kFieldCount; ++i) {
        if (pcOnWire.field(i) != settings.passivity.field(i))
            out.passivity.setField(i, passivity.field(i));
    }
    return out;
}

} // namespace

ProfileParamStore::ProfileParamStore(const QString &path, const QString &owner, double tauLimit)
    : m_path(path), m_owner(owner), m_tauLimit(tauLimit)
{}

QString ProfileParamStore::knobPath(const QString &path, int axis)
{
    if (axis == 0)
        return path;
    const QFileInfo file(path);
    const QString knob = QStringLiteral(".knob%1").arg(axis + 1);
    if (file.suffix().isEmpty())
        return path + knob;
    return file.dir().filePath(file.completeBaseName() + knob + u'.' + file.suffix());
}

bool ProfileParamStore::load(std::uint8_t axis, fw::StoredSettings &out)
{
    m_warning.clear();
    const QString path = knobPath(m_path, axis);
    if (!QFileInfo::exists(path))
        return false;
    const ProfileReadResult read = readProfile(path);
    if (!read.ok()) {
        m_warning = QStringLiteral("State file %1 ignored: %2")
                        .arg(path, read.errors.join(QStringLiteral("; ")));
        return false;
    }
    out.params = read.profile->device;
    out.effects = read.profile->effects;
    out.passivity = read.profile->passivity;
    return true;
}

QString ProfileParamStore::refusal(const ProfileReadResult &read) const
{
    if (!read.ok())
        return QStringLiteral("it is not a profile this program reads (%1)")
            .arg(read.errors.join(QStringLiteral("; ")));
    if (!read.warnings.isEmpty())
        return QStringLiteral("rewriting it would drop what this program does not read (%1)")
            .arg(read.warnings.join(QStringLiteral("; ")));
    return {};
}

bool ProfileParamStore::save(std::uint8_t axis, const fw::StoredSettings &settings)
{
    m_failure.clear();
    const QString path = knobPath(m_path, axis);
    Profile profile;
    if (QFileInfo::exists(path)) {
        // Read again at each save: what the user changed in the file meanwhile is kept too.
        const ProfileReadResult read = readProfile(path);
        if (const QString why = refusal(read); !why.isEmpty()) {
            m_failure = QStringLiteral("not overwriting %1: %2").arg(path, why).toUtf8();
            return false;
        }
        profile = merged(*read.profile, settings, m_tauLimit);
    } else {
        profile.name = m_owner + QStringLiteral(" state");
        if (axis > 0)
            profile.name += QStringLiteral(", knob %1").arg(axis + 1);
        profile.notes = QStringLiteral("Parameters saved by %1 (SAVE_PARAMS).").arg(m_owner);
        profile.device = tidyDeviceParams(settings.params);
        profile.effects = tidyEffectParams(settings.effects);
        profile.passivity = tidyPassivityParams(settings.passivity);
        profile.host.tau_limit = shortestFloatDecimal(m_tauLimit);
    }
    const QString error = writeProfile(profile, path);
    m_failure = error.toUtf8();
    return error.isEmpty();
}

QString ProfileParamStore::saveProblem() const
{
    const QFileInfo file(m_path);
    const QFileInfo folder(file.absolutePath());
    const QString cannot =
        QStringLiteral("SAVE_PARAMS cannot write state file %1: its folder %2 %3.");
    if (!folder.isDir())
        return cannot.arg(m_path, folder.filePath(), QStringLiteral("does not exist"));
    if (!folder.isWritable())
        return cannot.arg(m_path, folder.filePath(), QStringLiteral("is not writable"));
    if (file.exists()) {
        if (const QString why = refusal(readProfile(m_path)); !why.isEmpty())
            return QStringLiteral("SAVE_PARAMS will not overwrite state file %1: %2.")
                .arg(m_path, why);
    }
    return {};
}

} // namespace hatpic
