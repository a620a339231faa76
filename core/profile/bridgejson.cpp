#include "bridgejson.h"

#include "paramsjson.h"

#include <QJsonArray>

#include <cmath>
#include <functional>
#include <variant>

namespace hatpic {

using bridge::BridgeSettings;
using bridge::Component;

namespace {

// How a setting is held: text, a number, a whole number, or one of the special kinds below.
struct AxisTag
{}; // referenceAxis: "auto" or a twist component
struct ComponentTag
{}; // feedback.component: a wrench component
struct QosTag
{};
struct OriginTag
{}; // poseOrigin: [x, y, z]

using Place =
    std::variant<std::string BridgeSettings::*, double BridgeSettings::*, int BridgeSettings::*,
                 std::string bridge::Topics::*, double bridge::FeedbackSettings::*, AxisTag,
                 ComponentTag, QosTag, OriginTag>;

struct Key
{
    const char *name;
    Place place;
};

// The keys of the bridge object, in the order they are written (profile.md).
const Key kKeys[] = {
    {"joint_states_topic", &bridge::Topics::jointStates},
    {"twist_topic", &bridge::Topics::twist},
    {"twist_unstamped_topic", &bridge::Topics::twistUnstamped},
    {"pose_topic", &bridge::Topics::pose},
    {"feedback_topic", &bridge::Topics::feedback},
    {"wrench_topic", &bridge::Topics::wrench},
    {"wrench_unstamped_topic", &bridge::Topics::wrenchUnstamped},
    {"rate", &BridgeSettings::publishRateHz},
    {"frame_id", &BridgeSettings::frameId},
    {"joint_name", &BridgeSettings::jointName},
    {"axis", AxisTag{}},
    {"origin", OriginTag{}},
    {"component", ComponentTag{}},
    {"gain", &bridge::FeedbackSettings::gain},
    {"limit", &bridge::FeedbackSettings::limit},
    {"stale", &bridge::FeedbackSettings::staleAfter},
    {"qos", QosTag{}},
    {"depth", &BridgeSettings::depth},
};

constexpr char kAuto[] = "auto";

QByteArray text(const std::string &s)
{
    return jsonString(QString::fromStdString(s));
}

QByteArray valueJson(const BridgeSettings &s, const Place &place)
{
    struct Visitor
    {
        const BridgeSettings &s;
        QByteArray operator()(std::string BridgeSettings::*m) const { return text(s.*m); }
        QByteArray operator()(double BridgeSettings::*m) const { return jsonNumber(s.*m); }
        QByteArray operator()(int BridgeSettings::*m) const { return QByteArray::number(s.*m); }
        QByteArray operator()(std::string bridge::Topics::*m) const { return text(s.topics.*m); }
        QByteArray operator()(double bridge::FeedbackSettings::*m) const
        {
            return jsonNumber(s.feedback.*m);
        }
        QByteArray operator()(AxisTag) const
        {
            return text(s.referenceAxis ? s.referenceAxis->twistName() : kAuto);
        }
        QByteArray operator()(ComponentTag) const
        {
            return text(s.feedback.component.wrenchName());
        }
        QByteArray operator()(QosTag) const { return text(bridge::qosProfileName(s.qos)); }
        QByteArray operator()(OriginTag) const
        {
            return '[' + jsonNumber(s.poseOrigin[0]) + ", " + jsonNumber(s.poseOrigin[1]) + ", " +
                   jsonNumber(s.poseOrigin[2]) + ']';
        }
    };
    return std::visit(Visitor{s}, place);
}

// Reads one value; returns what is wrong with it ("must be a number"), or an empty string.
QString readValue(const QJsonValue &v, const Place &place, BridgeSettings &s)
{
    struct Visitor
    {
        const QJsonValue &v;
        BridgeSettings &s;
        QString string(std::string &target) const
        {
            if (!v.isString())
                return QStringLiteral("must be a string");
            target = v.toString().toStdString();
            return {};
        }
        QString number(double &target) const
        {
            if (!v.isDouble())
                return QStringLiteral("must be a number");
            target = v.toDouble();
            return {};
        }
        QString operator()(std::string BridgeSettings::*m) const { return string(s.*m); }
        QString operator()(std::string bridge::Topics::*m) const { return string(s.topics.*m); }
        QString operator()(double BridgeSettings::*m) const { return number(s.*m); }
        QString operator()(double bridge::FeedbackSettings::*m) const
        {
            return number(s.feedback.*m);
        }
        QString operator()(int BridgeSettings::*m) const
        {
            const double d = v.toDouble(std::nan(""));
            if (!v.isDouble() || d != std::floor(d) || std::abs(d) > 1e9)
                return QStringLiteral("must be a whole number");
            s.*m = int(d);
            return {};
        }
        QString operator()(AxisTag) const
        {
            const std::string t = v.toString().toStdString();
            const auto c = Component::parse(t);
            if (!v.isString() || (t != kAuto && !c))
                return QStringLiteral("must be \"auto\" or one of \"linear.x\" … \"angular.z\"");
            s.referenceAxis = c;
            return {};
        }
        QString operator()(ComponentTag) const
        {
            const auto c = Component::parse(v.toString().toStdString());
            if (!v.isString() || !c)
                return QStringLiteral("must be one of \"force.x\" … \"torque.z\"");
            s.feedback.component = *c;
            return {};
        }
        QString operator()(QosTag) const
        {
            const auto q = bridge::parseQosProfile(v.toString().toStdString());
            if (!v.isString() || !q)
                return QStringLiteral("must be \"reliable\" or \"best-effort\"");
            s.qos = *q;
            return {};
        }
        QString operator()(OriginTag) const
        {
            const QJsonArray a = v.toArray();
            if (!v.isArray() || a.size() != 3 || !a[0].isDouble() || !a[1].isDouble() ||
                !a[2].isDouble())
                return QStringLiteral("must be an array of three numbers [x, y, z] in metres");
            for (int i = 0; i < 3; ++i)
                s.poseOrigin[std::size_t(i)] = a[i].toDouble();
            return {};
        }
    };
    return std::visit(Visitor{v, s}, place);
}

} // namespace

QByteArray bridgeSettingsJson(const BridgeSettings &settings, int indent)
{
    JsonObjectWriter writer(indent);
    for (const Key &key : kKeys)
        writer.add(key.name, valueJson(settings, key.place));
    return writer.text();
}

void readBridgeSettings(const QJsonObject &object, const QString &prefix, BridgeSettings &settings,
                        QStringList &errors, QStringList &warnings)
{
    QStringList known;
    for (const Key &key : kKeys) {
        const QString name = QString::fromLatin1(key.name);
        known.append(name);
        const QJsonValue value = object.value(name);
        if (value.isUndefined())
            continue;
        if (const QString problem = readValue(value, key.place, settings); !problem.isEmpty())
            errors.append(prefix + name + u": " + problem + u", got " + jsonValueText(value));
    }
    warnUnknownKeys(object, known, prefix, warnings);
    // The rules themselves, in validate()'s words, after the block's name.
    QString block = prefix;
    if (block.endsWith(u'.'))
        block.chop(1);
    for (const std::string &problem : bridge::validate(settings))
        errors.append(block + u": " + QString::fromStdString(problem));
}

} // namespace hatpic
