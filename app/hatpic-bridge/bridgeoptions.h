// hatpic-bridge's settings: one table of options, read from the command line and from a
// --config file (JSON, the same names without "--"); the command line wins.
#pragma once

#include "profile/bridgesettings.h"
#include "profile/profile.h"
#include "session/sessiontypes.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace hatpic::bridge {

struct AppOptions
{
    ConnectOptions connect;         //!< port, baud; reconnects
    QString profilePath;            //!< --profile: pushed to the device, host block used
    std::optional<Profile> profile; //!< read from profilePath
    //! Everything ros.md lists: defaults, then ROS_DOMAIN_ID, the profile's host.bridge, the
    //! --config file and the command line, each over the one before.
    BridgeSettings settings;
};

//! Parses `arguments` (argv, program name first) with the environment's ROS_DOMAIN_ID.
//! `--help` puts the help text in `*help` and returns nullopt with `*error` empty; a bad
//! option or file (the profile included) sets `*error` to one sentence.
std::optional<AppOptions> parseAppOptions(const QStringList &arguments, QString *help,
                                          QString *error);

} // namespace hatpic::bridge
