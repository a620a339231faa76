// hatpic-bridge's settings: one table of options, read from the command line and from a
// --config file (JSON, the same names without "--"); the command line wins.
#pragma once

#include "bridge/bridgesettings.h"
#include "session/sessiontypes.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace hatpic::bridge {

struct AppOptions
{
    ConnectOptions connect;  //!< port, baud; reconnects
    QString profilePath;     //!< --profile: pushed to the device, host block used
    BridgeSettings settings; //!< everything ros.md lists
};

//! Parses `arguments` (argv, program name first) with the environment's ROS_DOMAIN_ID.
//! `--help` puts the help text in `*help` and returns nullopt with `*error` empty; a bad
//! option or file sets `*error` to one sentence.
std::optional<AppOptions> parseAppOptions(const QStringList &arguments, QString *help,
                                          QString *error);

} // namespace hatpic::bridge
