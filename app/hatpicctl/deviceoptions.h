// The options every device subcommand shares: the connection options (common/connectionoptions.h)
// and --timeout.
#pragma once

#include "session/sessiontypes.h"

#include <QString>

#include <optional>

class QCommandLineParser;

namespace hatpic::cli {

struct DeviceOptions
{
    ConnectOptions connect; //!< port, baud, protocol; autoReconnect off
    double timeoutS = 5.0;  //!< longest wait for the connection and for each answer [s]
};

void addDeviceOptions(QCommandLineParser &parser);
//! Reads the shared options; on a bad value prints one sentence and returns nullopt.
std::optional<DeviceOptions> deviceOptions(const QCommandLineParser &parser);

} // namespace hatpic::cli
