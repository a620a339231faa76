#include "devicesubcommand.h"

#include "common/exitcodes.h"
#include "console.h"
#include "devicerunner.h"

#include "model/axes.h"

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

DeviceSubcommand::DeviceSubcommand(SubcommandText text, Knobs knobs)
    : Subcommand(withPortHelp(std::move(text))), m_knobs(knobs)
{}

void DeviceSubcommand::addOptions(QCommandLineParser &parser)
{
    addDeviceOptions(parser);
    if (m_knobs == Knobs::One)
        parser.addOption(
            {u"knob"_s, u"The knob, 1 … %1, of a device with several (default 1)."_s.arg(kMaxAxes),
             u"N"_s});
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
    if (const int code = readKnob(parser); code != ExitSuccess)
        return code;
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

int DeviceSubcommand::readKnob(const QCommandLineParser &parser)
{
    m_knob = 0;
    if (m_knobs == Knobs::None || !parser.isSet(u"knob"_s))
        return ExitSuccess;
    const QString text = parser.value(u"knob"_s);
    bool ok = false;
    const int number = text.trimmed().toInt(&ok);
    if (!ok || number < 1 || number > kMaxAxes) {
        printError(u"--knob " +
                   unreadNumber(u"a whole number from 1 to %1"_s.arg(kMaxAxes), text, true));
        return ExitBadUsage;
    }
    m_knob = Knob(number - 1);
    return ExitSuccess;
}

QString DeviceSubcommand::ofKnob() const
{
    return m_knob ? u" of knob %1"_s.arg(int(m_knob) + 1) : QString();
}

} // namespace hatpic::cli
