#include "deviceoptions.h"

#include "console.h"

#include "common/connectionoptions.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

#include <cmath>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

void addDeviceOptions(QCommandLineParser &parser)
{
    parser.addOption(
        connectionOption(ConnectionOption::Port,
                         u"Serial device (e.g. /dev/ttyUSB0, a pty) or 'sim' for the built-in "
                         "simulated joystick. Required; 'hatpicctl ports' lists them."_s));
    parser.addOption(connectionOption(ConnectionOption::Baud));
    parser.addOption(connectionOption(ConnectionOption::Protocol));
    parser.addOption(
        QCommandLineOption(u"timeout"_s,
                           u"Longest wait for the connection and for each answer, in seconds "
                           "(default: 5)."_s,
                           u"S"_s, u"5"_s));
    parser.addOption(connectionOption(ConnectionOption::Faults));
    parser.addOption(connectionOption(ConnectionOption::Seed));
}

std::optional<DeviceOptions> deviceOptions(const QCommandLineParser &parser)
{
    DeviceOptions options;
    options.connect.autoReconnect = false;

    if (parser.value(u"port"_s).isEmpty()) {
        printError(u"This command needs --port: a serial device path, or 'sim' "
                   "for the built-in simulated joystick."_s);
        return std::nullopt;
    }
    QString error;
    if (!readConnectionOptions(parser, options.connect, &error)) {
        printError(error);
        return std::nullopt;
    }

    bool ok = false;
    const double timeout = parser.value(u"timeout"_s).toDouble(&ok);
    if (!ok || !std::isfinite(timeout) || timeout <= 0 || timeout > 3600) {
        printError(u"--timeout must be a number of seconds above 0 and at most 3600, got '" +
                   parser.value(u"timeout"_s) + u"'.");
        return std::nullopt;
    }
    options.timeoutS = timeout;
    // Detection keeps trying while hatpicctl waits: an ESP32 the port's DTR reset boots first.
    options.connect.detectForMs = static_cast<int>(timeout * 1000);
    return options;
}

} // namespace hatpic::cli
