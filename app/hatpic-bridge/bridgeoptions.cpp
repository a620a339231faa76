#include "bridgeoptions.h"

#include "common/connectionoptions.h"
#include "profile/jsonfile.h"
#include "ros/node.h"

#include <QCommandLineParser>
#include <QJsonObject>

#include <cmath>
#include <functional>
#include <type_traits>
#include <vector>

namespace hatpic::bridge {

namespace {

constexpr qint64 kMaxConfigBytes = 64 * 1024;
constexpr int kMaxTelemetryHz = 65535;
// The device's watchdog must never trip while the wrench is fresh: a frame at least every
// 50 ms (ros.md).
constexpr double kMinFeedbackHz = 20;
constexpr double kMaxFeedbackHz = 1000;

// Reads `text` into the settings; returns an empty string or what is wrong with it.
using Apply = std::function<QString(AppOptions &, const QString &text)>;

struct Setting
{
    const char *name;      //!< long option and config key
    const char *valueName; //!< in --help
    const char *help;
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

// The setting that `place` finds in the options, read as its type: a number, a whole number
// or text.
template<typename Place> Apply at(Place place)
{
    return [place](AppOptions &o, const QString &t) -> QString {
        auto &target = place(o);
        using T = std::remove_reference_t<decltype(target)>;
        if constexpr (std::is_same_v<T, std::string>) {
            target = t.toStdString();
        } else if constexpr (std::is_same_v<T, int>) {
            const auto v = whole(t);
            if (!v)
                return QStringLiteral("needs a whole number");
            target = *v;
        } else {
            const auto v = number(t);
            if (!v)
                return QStringLiteral("needs a number");
            target = *v;
        }
        return {};
    };
}

// A twist or wrench component (either spelling); with `allowAuto` also "auto" (nullopt).
Apply componentSetting(const char *choices, bool allowAuto,
                       void (*assign)(AppOptions &, std::optional<Component>))
{
    return [=](AppOptions &o, const QString &t) -> QString {
        if (allowAuto && t == u"auto") {
            assign(o, std::nullopt);
            return {};
        }
        const auto c = Component::parse(t.toStdString());
        if (!c)
            return u"needs " + QString::fromLatin1(choices);
        assign(o, c);
        return {};
    };
}

#define HATPIC_SETTING(expr) at([](AppOptions & o) -> auto & { return o.expr; })

const std::vector<Setting> &settingTable()
{
    static const std::vector<Setting> table = {
        {"baud", "N", "Baud rate, 300 to 4000000 (default: the protocol's).",
         [](AppOptions &o, const QString &t) {
             const auto v = baudValue(t); // the bounds of every program's --baud
             if (!v)
                 return QString(u"needs " + baudRule());
             o.connect.baud = *v;
             return QString();
         }},
        {"profile", "FILE", "Profile to push to the device; its host block sets v_max and mode.",
         [](AppOptions &o, const QString &t) {
             o.profilePath = t;
             return QString();
         }},
        {"telemetry-rate", "HZ", "Telemetry rate to ask of the device (default 1000).",
         [](AppOptions &o, const QString &t) {
             const auto v = whole(t);
             if (!v || *v < 1 || *v > kMaxTelemetryHz)
                 return QStringLiteral("needs a whole number of Hz from 1 to 65535");
             o.connect.streamRateHz = quint16(*v);
             return QString();
         }},
        {"feedback-rate", "HZ",
         "SET_FEEDBACK frames per second at most; a new tau_ext goes at once (default 1000; 20 "
         "to 1000).",
         [](AppOptions &o, const QString &t) {
             const auto v = number(t);
             if (!v || *v < kMinFeedbackHz || *v > kMaxFeedbackHz)
                 return QStringLiteral("needs a number of Hz from 20 to 1000");
             o.connect.feedbackRateHz = *v;
             return QString();
         }},
        {"ros", "VERSION",
         "2: ROS 2 over Cyclone DDS (default); 1: ROS 1 through roscpp (ROS_MASTER_URI).",
         HATPIC_SETTING(settings.rosVersion)},
        {"domain", "ID", "DDS domain (default: ROS_DOMAIN_ID, else 0).",
         HATPIC_SETTING(settings.domainId)},
        {"joint-states-topic", "NAME",
         "sensor_msgs/JointState out (default /hatpic/joint_states; "
         "empty: none).",
         HATPIC_SETTING(settings.topics.jointStates)},
        {"twist-topic", "NAME", "geometry_msgs/TwistStamped out (default /hatpic/twist).",
         HATPIC_SETTING(settings.topics.twist)},
        {"twist-unstamped-topic", "NAME",
         "geometry_msgs/Twist out, the same twist unstamped (default: none).",
         HATPIC_SETTING(settings.topics.twistUnstamped)},
        {"pose-topic", "NAME", "geometry_msgs/PoseStamped out (default /hatpic/pose).",
         HATPIC_SETTING(settings.topics.pose)},
        {"feedback-topic", "NAME", "geometry_msgs/WrenchStamped out (default /hatpic/feedback).",
         HATPIC_SETTING(settings.topics.feedback)},
        {"wrench-topic", "NAME", "geometry_msgs/WrenchStamped in (default /wrench_estimation).",
         HATPIC_SETTING(settings.topics.wrench)},
        {"wrench-unstamped-topic", "NAME", "geometry_msgs/Wrench in (default: none).",
         HATPIC_SETTING(settings.topics.wrenchUnstamped)},
        {"rate", "HZ", "Messages per topic per second, at most (default 100).",
         HATPIC_SETTING(settings.publishRateHz)},
        {"frame-id", "ID", "header.frame_id (default hatpic).", HATPIC_SETTING(settings.frameId)},
        {"joint-name", "NAME", "JointState name (default hatpic_knob).",
         HATPIC_SETTING(settings.jointName)},
        {"axis", "AXIS",
         "Twist/pose axis: linear.x … angular.z, or auto (default: linear.x, "
         "angular.z in rotation mode).",
         componentSetting(
             "linear.x, linear.y, linear.z, angular.x, angular.y, angular.z or auto", true,
             [](AppOptions &o, std::optional<Component> c) { o.settings.referenceAxis = c; })},
        {"origin", "X,Y,Z", "Pose position origin [m] (default 0,0,0; MAVROS: 0,0,0.5).",
         [](AppOptions &o, const QString &t) {
             const QStringList parts = t.split(u',');
             if (parts.size() != 3)
                 return QStringLiteral("needs three numbers X,Y,Z");
             for (int i = 0; i < 3; ++i) {
                 const auto v = number(parts[i]);
                 if (!v)
                     return QStringLiteral("needs three numbers X,Y,Z");
                 o.settings.poseOrigin[i] = *v;
             }
             return QString();
         }},
        {"component", "COMPONENT",
         "Wrench component fed back: force.x … torque.z (default "
         "force.z).",
         componentSetting("force.x, force.y, force.z, torque.x, torque.y or torque.z", false,
                          [](AppOptions &o, std::optional<Component> c) {
                              o.settings.feedback.component = *c;
                          })},
        {"gain", "NM_PER_N", "τ_ext per unit of the component (default 0.154).",
         HATPIC_SETTING(settings.feedback.gain)},
        {"limit", "NM", "|τ_ext| at most [N·m] (default 0.154).",
         HATPIC_SETTING(settings.feedback.limit)},
        {"stale", "S", "A wrench older than this gives τ_ext 0 (default 0.5).",
         HATPIC_SETTING(settings.feedback.staleAfter)},
        {"qos", "PROFILE",
         "Publishers' reliability: reliable (default) or best-effort; subscriptions take "
         "either.",
         [](AppOptions &o, const QString &t) {
             const auto p = parseQosProfile(t.toStdString());
             if (!p)
                 return QStringLiteral("needs reliable or best-effort");
             o.settings.qos = *p;
             return QString();
         }},
        {"depth", "N", "Publishers' history depth, keep last N (default 10).",
         HATPIC_SETTING(settings.depth)},
    };
    return table;
}

// Text the user gave, as a message quotes it (echoedText(): a long value is cut).
QString echoed(const QString &text)
{
    return QString::fromStdString(echoedText(text.toStdString()));
}

QString optionError(const char *name, const QString &value, const QString &problem)
{
    return u"--" + QString::fromLatin1(name) + u" " + problem + u", got '" + echoed(value) + u"'.";
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
            if (it.key() == QLatin1String(s.name))
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
        parser.addOption(QCommandLineOption(QString::fromLatin1(s.name), QString::fromUtf8(s.help),
                                            QString::fromLatin1(s.valueName)));
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
    std::string why;
    const std::optional<int> domain = ros::domainFromEnvironment(&why);
    if (!domain) {
        *error = QString::fromStdString(why);
        return std::nullopt;
    }
    options.settings.domainId = *domain;
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
            const QString name = QString::fromLatin1(s.name);
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
    options.connect.port = parser.value(portOption);
    if (options.connect.port.isEmpty()) {
        *error = QStringLiteral("--port is needed: a device path, a pseudo-terminal, or sim.");
        return std::nullopt;
    }
    if (const auto problems = validate(options.settings); !problems.empty()) {
        *error = QString::fromStdString(problems.front()) + u'.';
        return std::nullopt;
    }
    return options;
}

} // namespace hatpic::bridge
