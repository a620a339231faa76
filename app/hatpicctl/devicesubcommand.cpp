#include "devicesubcommand.h"

#include "common/exitcodes.h"
#include "devicerunner.h"

namespace hatpic::cli {

void DeviceSubcommand::addOptions(QCommandLineParser &parser)
{
    addDeviceOptions(parser);
    addCommandOptions(parser);
}

int DeviceSubcommand::prepare(const QCommandLineParser &parser, DeviceOptions &options)
{
    Q_UNUSED(parser);
    Q_UNUSED(options);
    return ExitSuccess;
}

int DeviceSubcommand::run(const QCommandLineParser &parser)
{
    auto options = deviceOptions(parser);
    if (!options)
        return ExitBadUsage;
    if (const int code = prepare(parser, *options); code != ExitSuccess)
        return code;
    DeviceRunner runner(*options);
    if (const int code = runner.connect(); code != ExitSuccess)
        return code;
    return runConnected(runner, parser);
}

QString DeviceSubcommand::portHelp()
{
    return QStringLiteral(
        "--port is required: a serial device such as /dev/ttyUSB0 or the pseudo-terminal\n"
        "hatpic-sim prints, or 'sim' for a simulated joystick inside this process (its\n"
        "state starts afresh on every run).");
}

} // namespace hatpic::cli
