// Profile files: one complete tuning as JSON (profile.md).
#pragma once

#include "bridgesettings.h"

#include "model/effects.h"
#include "model/params.h"
#include "model/passivity.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <optional>

namespace hatpic {

struct Profile
{
    QString name;
    QString notes;
    DeviceParams device;
    HostParams host;
    //! host.bridge of the file; its network settings (DDS domain, ROS version) are not part of
    //! a profile and stay at their defaults.
    bridge::BridgeSettings bridge{}; // {}: aggregate initialisers may leave it out
    //! device.effects of the file; the defaults (which render nothing) when it has none. Last,
    //! so that aggregate initialisers written before it still mean what they meant.
    EffectParams effects{};
    //! device.passivity of the file (passivity.md); the defaults (the controller on) when it
    //! has none. After effects for the same reason.
    PassivityParams passivity{};

    friend bool operator==(const Profile &, const Profile &) = default;
};

//! Outcome of reading a profile: the profile, or every error; warnings either way.
struct ProfileReadResult
{
    std::optional<Profile> profile; //!< set only when errors is empty
    QStringList errors;             //!< e.g. "device.K_min: must be ≤ K_max (0.4), got 0.9"
    QStringList warnings;           //!< e.g. "unknown key \"colour\" ignored"

    bool ok() const { return profile.has_value(); }
};

constexpr int kProfileVersion = 1;
constexpr qint64 kMaxProfileBytes = 1024 * 1024;

//! Parses profile JSON. Never throws; a refused document yields errors and no profile.
ProfileReadResult parseProfile(const QByteArray &json);
//! Reads a file (refusing files larger than kMaxProfileBytes) and parses it.
ProfileReadResult readProfile(const QString &path);

//! Which of the device's optional blocks a profile's text carries whatever their values; a
//! block not named is written only when it differs from its defaults, so files that never
//! touched it stay as they were.
struct ProfileBlocks
{
    bool effects = false;   //!< device.effects
    bool passivity = false; //!< device.passivity
};

//! The JSON text of a profile (key order of profile.md, two-space indent, exact doubles).
QByteArray serializeProfile(const Profile &profile, ProfileBlocks always = {});
//! Writes atomically with QSaveFile. Returns an empty string on success, else the error.
QString writeProfile(const Profile &profile, const QString &path);

//! Built-in presets: "Default", "Soft", "Notchy", "Detents", "Walled". Their files
//! (resources/presets) are installed to <prefix>/share/hatpic-tuner/presets and also compiled
//! in (":/presets/…").
QStringList presetNames();
//! A preset by name, read from presetFile(); std::nullopt for an unknown name.
std::optional<Profile> preset(const QString &name);
//! Where preset files are looked for, first match wins: the installed presets folder found
//! from the program's own folder (so a relocated install finds its own), then ":/presets" (the
//! copy compiled in, for a program run from its build tree).
QStringList presetDirectories();
//! The file of preset `name` in the first of `dirs` that holds it; empty when none does (or
//! the name is not a preset's).
QString presetFile(const QString &name, const QStringList &dirs = presetDirectories());

} // namespace hatpic
