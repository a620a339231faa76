#include "robotsimoptions.h"

#include "model/params.h"

#include <QCommandLineParser>

#include <cmath>
#include <functional>
#include <vector>

namespace hatpic::robot {

namespace {

// Reads `text` into the settings; returns an empty string or what is wrong with it.
using Apply = std::function<QString(RobotSimSettings &, const QString &text)>;

struct Option
{
    const char *name;
    const char *valueName;
    const char *help;
    Apply apply;
};

//! Reads a number and hands it to `assign`.
Apply number(std::function<void(RobotSimSettings &, double)> assign)
{
    return [assign = std::move(assign)](RobotSimSettings &s, const QString &t) -> QString {
        bool ok = false;
        const double v = t.trimmed().toDouble(&ok);
        if (!ok)
            return QStringLiteral("needs a number");
        assign(s, v);
        return {};
    };
}

Apply number(double RobotSimSettings::*field)
{
    return number([field](RobotSimSettings &s, double v) { s.*field = v; });
}

Apply robotNumber(double RobotParams::*field)
{
    return number([field](RobotSimSettings &s, double v) { s.robot.*field = v; });
}

Apply faultNumber(double LinkFaults::*field)
{
    return number([field](RobotSimSettings &s, double v) { s.faults.*field = v; });
}

Apply text(std::string RobotSimSettings::*field)
{
    return [field](RobotSimSettings &s, const QString &t) -> QString {
        s.*field = t.toStdString();
        return {};
    };
}

const std::vector<Option> &optionTable()
{
    static const std::vector<Option> table = {
        {"ros", "1|2", "ROS 1 (roscpp, ROS_MASTER_URI) or ROS 2 (Cyclone DDS; the default).",
         [](RobotSimSettings &s, const QString &t) -> QString {
             if (t == u"2")
                 s.node.version = ros::RosVersion::Ros2;
             else if (t == u"1" && ros::Node::isAvailable(ros::RosVersion::Ros1))
                 s.node.version = ros::RosVersion::Ros1;
             else if (t == u"1")
                 return QStringLiteral("ROS 1 is not built into this program");
             else
                 return QStringLiteral("needs 1 or 2");
             return {};
         }},
        {"domain", "ID", "ROS 2's DDS domain (default: ROS_DOMAIN_ID, else 0).",
         [](RobotSimSettings &s, const QString &t) -> QString {
             bool ok = false;
             const int v = t.trimmed().toInt(&ok);
             if (!ok || v < 0 || v > bridge::kMaxDomainId)
                 return u"needs a whole number from 0 to " + QString::number(bridge::kMaxDomainId);
             s.node.domainId = v;
             return {};
         }},
        {"axis", "AXIS", "Twist component followed, and the wrench's (default linear.x).",
         [](RobotSimSettings &s, const QString &t) -> QString {
             const auto c = bridge::Component::parse(t.toStdString());
             if (!c)
                 return QStringLiteral("needs linear.x … angular.z");
             s.axis = *c;
             return {};
         }},
        {"twist-topic", "TOPIC", "Reference in: geometry_msgs/TwistStamped (/hatpic/twist).",
         text(&RobotSimSettings::twistTopic)},
        {"wrench-topic", "TOPIC",
         "Estimated wrench out, best effort (/wrench_estimation; empty: off).",
         text(&RobotSimSettings::wrenchTopic)},
        {"pose-topic", "TOPIC", "Pose out, reliable (/robot/pose; empty: off).",
         text(&RobotSimSettings::poseTopic)},
        {"rate", "HZ", "Outputs per second (default 200; at most 1000).",
         number(&RobotSimSettings::rateHz)},
        {"stale", "S", "v_ref = 0 once the last twist is this old (default 0.5 s).",
         number(&RobotSimSettings::staleAfter)},
        {"mass", "KG", "Robot mass m (default 1.5 kg).", robotNumber(&RobotParams::mass)},
        {"kv", "NS/M", "Velocity gain K_v (default 40 N·s/m).", robotNumber(&RobotParams::kv)},
        {"fmax", "N", "Controller force limit F_max (default 20 N).",
         robotNumber(&RobotParams::fMax)},
        {"wall", "M", "Wall position x_w (default 0.05 m).", robotNumber(&RobotParams::wall)},
        {"wall-stiffness", "N/M", "Wall stiffness k_w (default 200 N/m).",
         robotNumber(&RobotParams::wallStiffness)},
        {"wall-damping", "NS/M", "Wall damping b_w (default 5 N·s/m).",
         robotNumber(&RobotParams::wallDamping)},
        {"start", "M", "Position at the start (default 0 m).", robotNumber(&RobotParams::start)},
        {"delay", "S", "Added one-way latency, both directions (default 0 s).",
         faultNumber(&LinkFaults::delay)},
        {"jitter", "S", "Uniform extra latency, order kept (default 0 s).",
         faultNumber(&LinkFaults::jitter)},
        {"loss", "P", "Fraction of messages dropped, both directions (default 0).",
         faultNumber(&LinkFaults::loss)},
        {"seed", "N", "Seed of the faults' randomness (default 1).",
         [](RobotSimSettings &s, const QString &t) -> QString {
             bool ok = false;
             const qulonglong v = t.trimmed().toULongLong(&ok);
             if (!ok)
                 return QStringLiteral("needs a whole number ≥ 0");
             s.seed = v;
             return {};
         }},
    };
    return table;
}

QString quoted(const QString &value)
{
    constexpr qsizetype kMax = 40;
    return u'\'' + (value.size() > kMax ? value.left(kMax) + u'…' : value) + u'\'';
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
    for (const Option &o : optionTable()) {
        parser.addOption(QCommandLineOption(QString::fromLatin1(o.name), QString::fromUtf8(o.help),
                                            QString::fromLatin1(o.valueName)));
    }
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
    for (const Option &o : optionTable()) {
        const QString name = QString::fromLatin1(o.name);
        if (!parser.isSet(name))
            continue;
        if (const QString problem = o.apply(settings, parser.value(name)); !problem.isEmpty()) {
            *error = u"--" + name + u' ' + problem + u", got " + quoted(parser.value(name)) + u'.';
            return std::nullopt;
        }
    }
    if (const auto violations = validate(settings); !violations.empty()) {
        *error = u"--" + QString::fromStdString(violations.front().message()) + u'.';
        return std::nullopt;
    }
    return settings;
}

} // namespace hatpic::robot
