#include "bridgeoptions.h"

#include "common/connectionoptions.h"
#include "profile/jsonfile.h"
#include "ros/node.h"

#include <QCommandLineParser>
#include <QJsonObject>

#include <cmath>
#include <functional>
#include <limits>
#include <variant>
#include <vector>

namespace hatpic::bridge {

using namespace Qt::StringLiterals;

namespace {

constexpr qint64 kMaxConfigBytes = 64 * 1024;
constexpr int kMaxTelemetryHz = 65535;
// The device's watchdog must never trip while the wrench is fresh: a frame at least every
// 50 ms (ros.md).
constexpr double kMinFeedbackHz = 20;
constexpr double kMaxFeedbackHz = 1000;

// Reads `text` into the options; returns an empty string or what is wrong with it.
using Apply = std::function<QString(AppOptions &, const QString &text)>;

struct Setting
{
    QString name;      //!< long option and config key
    QString valueName; //!< in --help
    QString help;
    Apply apply;
};

std::optional<double> number(const QString &text)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    return ok && std::isfinite(v) ? std::optional(v) : std::nullopt;
}

std::optional<int> whole(const QString &text)
{
    bool ok = false;
    const int v = text.trimmed().toInt(&ok);
    return ok ? std::optional(v) : std::nullopt;
}

template<typename T> QString assign(T &target, const std::optional<T> &value, const char *problem)
{
    if (!value)
        return QString::fromLatin1(problem);
    target = *value;
    return {};
}

// A twist or wrench component (either spelling): "needs CHOICES" for anything else.
std::optional<Component> component(const QString &text, const char *choices, QString *problem)
{
    const auto c = Component::parse(text.toStdString());
    if (!c)
        *problem = u"needs " + QString::fromLatin1(choices);
    return c;
}

// One of the bridge's settings (kSettings) from an option's text.
QString applySetting(const SettingSpec &spec, BridgeSettings &s, const QString &t)
{
    return std::visit(
        Overloaded{
            [&](std::string Topics::*m) {
                s.topics.*m = t.toStdString();
                return QString();
            },
            [&](std::string BridgeSettings::*m) {
                s.*m = t.toStdString();
                return QString();
            },
            [&](double BridgeSettings::*m) { return assign(s.*m, number(t), "needs a number"); },
            [&](double FeedbackSettings::*m) {
                return assign(s.feedback.*m, number(t), "needs a number");
            },
            [&](int BridgeSettings::*m) { return assign(s.*m, whole(t), "needs a whole number"); },
            [&](AxisPlace) {
                QString problem;
                if (t == u"auto")
                    s.referenceAxis.reset();
                else if (const auto c = component(t,
                                                  "linear.x, linear.y, linear.z, angular.x, "
                                                  "angular.y, angular.z or auto",
                                                  &problem))
                    s.referenceAxis = c;
                return problem;
            },
            [&](ComponentPlace) {
                QString problem;
                if (const auto c = component(
                        t, "force.x, force.y, force.z, torque.x, torque.y or torque.z", &problem))
                    s.feedback.component = *c;
                return problem;
            },
            [&](QosPlace) {
                return assign(s.qos, parseQosProfile(t.toStdString()),
                              "needs reliable or best-effort");
            },
            [&](OriginPlace) {
                const QString needs = QStringLiteral("needs three numbers X,Y,Z");
                const QStringList parts = t.split(u',');
                if (parts.size() != 3)
                    return needs;
                std::array<double, 3> origin{};
                for (std::size_t i = 0; i < 3; ++i) {
                    const auto v = number(parts[qsizetype(i)]);
                    if (!v)
                        return needs;
                    origin[i] = *v;
                }
                s.poseOrigin = origin;
                return QString();
            },
        },
        spec.place);
}

// hatpic-bridge's own options, then every setting of the bridge (kSettings), as --help lists
// them.
const std::vector<Setting> &settingTable()
{
    static const std::vector<Setting> table = [] {
        std::vector<Setting> t = {
            {u"baud"_s, u"N"_s, u"Baud rate, 300 to 4000000 (default: the protocol's)."_s,
             [](AppOptions &o, const QString &text) {
                 const auto v = baudValue(text); // the bounds of every program's --baud
                 if (!v)
                     return QString(u"needs " + baudRule());
                 o.connect.baud = *v;
                 return QString();
             }},
            {u"profile"_s, u"FILE"_s,
             u"Profile to push to the device; its host block sets v_max and mode."_s,
             [](AppOptions &o, const QString &text) {
                 o.profilePath = text;
                 return QString();
             }},
            {u"telemetry-rate"_s, u"HZ"_s, u"Telemetry rate to ask of the device (default 1000)."_s,
             [](AppOptions &o, const QString &text) {
                 const auto v = whole(text);
                 if (!v || *v < 1 || *v > kMaxTelemetryHz)
                     return QStringLiteral("needs a whole number of Hz from 1 to 65535");
                 o.connect.streamRateHz = quint16(*v);
                 return QString();
             }},
            {u"feedback-rate"_s, u"HZ"_s,
             u"SET_FEEDBACK frames per second at most; a new tau_ext goes at once (default 1000; "
             u"20 to 1000)."_s,
             [](AppOptions &o, const QString &text) {
                 const auto v = number(text);
                 if (!v || *v < kMinFeedbackHz || *v > kMaxFeedbackHz)
                     return QStringLiteral("needs a number of Hz from 20 to 1000");
                 o.connect.feedbackRateHz = *v;
                 return QString();
             }},
        };
        for (const SettingSpec &spec : kSettings) {
            const auto utf8 = [](std::string_view v) {
                return QString::fromUtf8(v.data(), qsizetype(v.size()));
            };
            t.push_back({utf8(spec.key).replace(u'_', u'-'), utf8(spec.valueName), utf8(spec.help),
                         [&spec](AppOptions &o, const QString &text) {
                             return applySetting(spec, o.settings, text);
                         }});
        }
        return t;
    }();
    return table;
}

// Text the user gave, as a message quotes it (echoedText(): a long value is cut).
QString echoed(const QString &text)
{
    return QString::fromStdString(echoedText(text.toStdString()));
}

QString optionError(const QString &name, const QString &value, const QString &problem)
{
    return u"--" + name + u" " + problem + u", got '" + echoed(value) + u"'.";
}

// The --config file's settings, applied first.
QString applyConfig(const QString &path, AppOptions &options)
{
    // The rules of a profile's file (profile.md § Reading): a regular file, read with a bound,
    // one JSON object, each key once.
    QString error;
    const std::optional<QByteArray> text =
        readBoundedFile(path, QStringLiteral("config file"), kMaxConfigBytes, &error);
    if (!text)
        return error.left(1).toUpper() + error.mid(1) + u'.';
    const JsonObjectRead read = parseJsonObject(*text);
    if (!read.object)
        return u"The config file " + path + u": " + read.error + u'.';
    const QJsonObject &object = *read.object;
    for (auto it = object.begin(); it != object.end(); ++it) {
        const Setting *setting = nullptr;
        for (const Setting &s : settingTable()) {
            if (it.key() == s.name)
                setting = &s;
        }
        if (!setting)
            return u"The config file " + path + u" has an unknown setting \"" + echoed(it.key()) +
                   u"\".";
        const QString value = it.value().isDouble()
                                  ? QString::number(it.value().toDouble(), 'g', 17)
                                  : it.value().toString();
        if (!it.value().isDouble() && !it.value().isString())
            return u"The config file " + path + u": \"" + it.key() +
                   u"\" must be a number or a string.";
        if (const QString problem = setting->apply(options, value); !problem.isEmpty())
            return u"The config file " + path + u": \"" + it.key() + u"\" " + problem + u", got '" +
                   echoed(value) + u"'.";
    }
    return {};
}

} // namespace

std::optional<AppOptions> parseAppOptions(const QStringList &arguments, QString *help,
                                          QString *error)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "The HATPIC joystick on ROS 2 (Cyclone DDS, as rmw_cyclonedds) or ROS 1 (--ros 1, "
        "roscpp): publishes its references, feeds the robot's wrench back as τ_ext. Statistics "
        "once a second on stdout; runs until SIGINT or SIGTERM. See docs/ros.md."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    const QCommandLineOption portOption = connectionOption(
        ConnectionOption::Port, QStringLiteral("Device path, a pseudo-terminal, or sim."));
    const QCommandLineOption configOption(
        QStringLiteral("config"),
        QStringLiteral("JSON file of the settings below (keys without "
                       "--); the command line wins."),
        QStringLiteral("FILE"));
    parser.addOption(portOption);
    parser.addOption(configOption);
    for (const Setting &s : settingTable()) {
        parser.addOption(QCommandLineOption(s.name, s.help, s.valueName));
    }
    if (!parser.parse(arguments)) {
        // Qt's sentence quotes an unknown option whole; ours cuts a long one.
        const QStringList unknown = parser.unknownOptionNames();
        *error = unknown.size() == 1 ? u"Unknown option '" + echoed(unknown.first()) + u"'."
                                     : echoed(parser.errorText()); // Qt's ends with a full stop
        return std::nullopt;
    }
    if (parser.isSet(helpOption)) {
        *help = parser.helpText();
        return std::nullopt;
    }
    if (!parser.positionalArguments().isEmpty()) {
        *error = u"Unexpected argument '" + echoed(parser.positionalArguments().first()) + u"'.";
        return std::nullopt;
    }

    AppOptions options;
    options.connect.autoReconnect = true;
    options.connect.detectForMs = ConnectOptions::kDetectBootMs;
    // ROS_DOMAIN_ID, unless --domain (or the config's "domain") says otherwise: a bad variable
    // is refused only when it is the one that counts.
    std::string domainProblem;
    constexpr int kDomainUnread = std::numeric_limits<int>::min();
    options.settings.domainId =
        ros::domainFromEnvironment(kMaxDomainId, &domainProblem).value_or(kDomainUnread);
    // The config file, then the command line. Run twice when a profile is named (by either):
    // its bridge settings go under both.
    const auto applyOptions = [&]() -> bool {
        if (parser.isSet(configOption)) {
            if (const QString problem = applyConfig(parser.value(configOption), options);
                !problem.isEmpty()) {
                *error = problem;
                return false;
            }
        }
        for (const Setting &s : settingTable()) {
            const QString &name = s.name;
            if (!parser.isSet(name))
                continue;
            if (const QString problem = s.apply(options, parser.value(name)); !problem.isEmpty()) {
                *error = optionError(s.name, parser.value(name), problem);
                return false;
            }
        }
        return true;
    };
    if (!applyOptions())
        return std::nullopt;
    if (!options.profilePath.isEmpty()) {
        const ProfileReadResult read = readProfile(options.profilePath);
        if (!read.ok()) {
            *error = u"The profile " + options.profilePath + u" cannot be used: " +
                     read.errors.join(QStringLiteral("; ")) + u'.';
            return std::nullopt;
        }
        options.profile = read.profile;
        // A profile holds no network settings (domain, ROS version).
        options.settings = withNetworkOf(read.profile->bridge, options.settings);
        if (!applyOptions())
            return std::nullopt;
    }
    if (options.settings.domainId == kDomainUnread) {
        *error = QString::fromStdString(domainProblem);
        return std::nullopt;
    }
    options.connect.port = parser.value(portOption);
    if (options.connect.port.isEmpty()) {
        *error = QStringLiteral("--port is needed: a device path, a pseudo-terminal, or sim.");
        return std::nullopt;
    }
    linkSimulator(options.connect);
    if (const auto problems = validate(options.settings); !problems.empty()) {
        *error = QString::fromStdString(problems.front()) + u'.';
        return std::nullopt;
    }
    return options;
}

} // namespace hatpic::bridge
