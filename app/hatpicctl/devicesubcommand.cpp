#include "devicesubcommand.h"

#include "common/exitcodes.h"
#include "devicerunner.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

SubcommandText withPortHelp(SubcommandText text)
{
    text.description +=
        u"\n\n--port is required: a serial device such as /dev/ttyUSB0 or the pseudo-terminal\n"
        "hatpic-sim prints, or 'sim' for a simulated joystick inside this process (its\n"
        "state starts afresh on every run)."_s;
    return text;
}

} // namespace

DeviceSubcommand::DeviceSubcommand(SubcommandText text) : Subcommand(withPortHelp(std::move(text)))
{}

void DeviceSubcommand::addOptions(QCommandLineParser &parser)
{
    addDeviceOptions(parser);
    addCommandOptions(parser);
}

int DeviceSubcommand::prepare(const QCommandLineParser &, DeviceOptions &)
{
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

void DeviceSubcommand::addJsonOption(QCommandLineParser &parser)
{
    parser.addOption({u"json"_s, u"Print a profile (JSON)."_s});
}

} // namespace hatpic::cli
