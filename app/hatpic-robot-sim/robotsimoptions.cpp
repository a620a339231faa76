#include "robotsimoptions.h"

#include "model/params.h"

#include <QCommandLineParser>

namespace hatpic::robot {

namespace {

QString utf8(std::string_view v)
{
    return QString::fromUtf8(v.data(), qsizetype(v.size()));
}

// Text the user gave, as a message quotes it (echoedText(): a long value is cut).
QString quoted(const QString &value)
{
    return u'\'' + QString::fromStdString(echoedText(value.toStdString())) + u'\'';
}

} // namespace

std::optional<RobotSimSettings> parseRobotSimOptions(const QStringList &arguments, QString *help,
                                                     QString *error)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "A simulated robot for the other end of hatpic-bridge (robot.md): one axis following "
        "the knob's twist into a wall, its estimated wrench and pose published. A status line "
        "each second on stdout; runs until SIGINT or SIGTERM. See docs/teleop.md."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    for (const RobotSimOption &o : robotSimOptions())
        parser.addOption(QCommandLineOption(utf8(o.key), utf8(o.help), utf8(o.valueName)));
    if (!parser.parse(arguments)) {
        *error = parser.errorText() + u'.';
        return std::nullopt;
    }
    if (parser.isSet(helpOption)) {
        *help = parser.helpText();
        return std::nullopt;
    }
    if (!parser.positionalArguments().isEmpty()) {
        *error = u"Unexpected argument " + quoted(parser.positionalArguments().first()) + u'.';
        return std::nullopt;
    }
    RobotSimSettings settings;
    for (const RobotSimOption &o : robotSimOptions()) {
        const QString name = utf8(o.key);
        if (!parser.isSet(name))
            continue;
        if (const std::string problem = applyOption(o, settings, parser.value(name).toStdString());
            !problem.empty()) {
            *error = u"--" + name + u' ' + QString::fromStdString(problem) + u", got " +
                     quoted(parser.value(name)) + u'.';
            return std::nullopt;
        }
    }
    if (settings.node.domainId < 0) {
        // ROS_DOMAIN_ID, read as hatpic-bridge reads it (--domain wins over it).
        std::string why;
        const std::optional<int> domain = ros::domainFromEnvironment(bridge::kMaxDomainId, &why);
        if (!domain) {
            *error = QString::fromStdString(why);
            return std::nullopt;
        }
        settings.node.domainId = *domain;
    }
    if (const auto violations = validate(settings); !violations.empty()) {
        *error = u"--" + QString::fromStdString(violations.front()) + u'.';
        return std::nullopt;
    }
    return settings;
}

} // namespace hatpic::robot
