#include "subcommand.h"

#include "common/exitcodes.h"
#include "console.h"
#include "subcommands.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

#include <algorithm>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

QString overview(const std::vector<std::unique_ptr<Subcommand>> &commands)
{
    QString text =
        u"Usage: hatpicctl COMMAND [options]\n"
        "\n"
        "Talks to a HATPIC joystick (or the simulated one), and computes the haptic model\n"
        "offline. Data (CSV, JSON, tables) goes to stdout, messages to stderr.\n"
        "\n"
        "Commands:\n"_s;
    qsizetype width = 0; // the longest name, then a gap of two
    for (const auto &command : commands)
        width = std::max(width, command->text().name.size());
    for (const auto &command : commands)
        text +=
            u"  " + command->text().name.leftJustified(width + 2) + command->text().summary + u'\n';
    text += u"\n"
            "Run 'hatpicctl COMMAND --help' for the options of one command.\n"
            "Exit codes: 0 success, 2 device rejected, 3 no device / timeout / link lost,\n"
            "4 bad usage or bad file.\n"_s;
    return text;
}

// QCommandLineParser's help starts with "Usage: <program> [options]"; replace that line by the
// subcommand's own synopsis and description.
QString commandHelp(const Subcommand &command, const QCommandLineParser &parser)
{
    QString options = parser.helpText();
    const qsizetype optionsStart = options.indexOf(u"Options:"_s);
    options = optionsStart >= 0 ? options.mid(optionsStart) : QString();
    return u"Usage: hatpicctl " + command.text().synopsis + u"\n\n" + command.text().description +
           u"\n\n" + options;
}

} // namespace

std::vector<std::unique_ptr<Subcommand>> allSubcommands()
{
    std::vector<std::unique_ptr<Subcommand>> commands;
    commands.push_back(makePortsSubcommand());
    commands.push_back(makeInfoSubcommand());
    commands.push_back(makeGetSubcommand());
    commands.push_back(makeSetSubcommand());
    commands.push_back(makeZeroSubcommand());
    commands.push_back(makeSaveSubcommand());
    commands.push_back(makeStreamSubcommand());
    commands.push_back(makeCurveSubcommand());
    commands.push_back(makeSimulateSubcommand());
    commands.push_back(makeValidateSubcommand());
    commands.push_back(makeExperimentSubcommand());
    commands.push_back(makeVibrateSubcommand());
    commands.push_back(makeTeleopMapSubcommand());
    return commands;
}

int dispatch(const QStringList &arguments)
{
    const auto commands = allSubcommands();
    const QString first = arguments.value(1);
    if (first == u"--help" || first == u"-h" || first == u"help") {
        writeOut(overview(commands));
        return ExitSuccess;
    }
    if (first == u"--version") {
        writeOut(QStringLiteral("hatpicctl " HATPIC_VERSION "\n"));
        return ExitSuccess;
    }
    if (first.isEmpty()) {
        printError(u"No command given; run 'hatpicctl --help' for the list."_s);
        return ExitBadUsage;
    }

    Subcommand *command = nullptr;
    for (const auto &candidate : commands) {
        if (candidate->text().name == first)
            command = candidate.get();
    }
    if (!command) {
        printError(u"Unknown command '" + first +
                   u"'; run 'hatpicctl --help' for the list of commands.");
        return ExitBadUsage;
    }

    QCommandLineParser parser;
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help(QStringList{u"h"_s, u"help"_s}, u"Show this help and exit."_s);
    parser.addOption(help);
    command->addOptions(parser);

    // The subcommand's own arguments, with the program name in front as the parser expects.
    QStringList commandArguments = arguments.mid(2);
    commandArguments.prepend(arguments.value(0));
    if (!parser.parse(commandArguments)) {
        printError(asSentence(parser.errorText()).chopped(1) + u"; run 'hatpicctl " +
                   command->text().name + u" --help' for the options.");
        return ExitBadUsage;
    }
    if (parser.isSet(help)) {
        writeOut(commandHelp(*command, parser));
        return ExitSuccess;
    }
    if (!command->text().acceptsPositional && !parser.positionalArguments().isEmpty()) {
        printError(u"Unexpected argument '" + parser.positionalArguments().constFirst() +
                   u"'; run 'hatpicctl " + command->text().name + u" --help' for the options.");
        return ExitBadUsage;
    }
    const int code = command->run(parser);
    if (!flushOut() && code == ExitSuccess) {
        printError(u"Cannot write to standard output."_s);
        return ExitBadUsage;
    }
    return code;
}

} // namespace hatpic::cli
