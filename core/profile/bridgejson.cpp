#include "bridgejson.h"

#include "paramsjson.h"

#include <QJsonArray>

#include <cmath>
#include <variant>

namespace hatpic {

using bridge::BridgeSettings;
using bridge::Component;

namespace {

constexpr char kAuto[] = "auto";

QByteArray text(const std::string &s)
{
    return jsonString(QString::fromStdString(s));
}

QByteArray valueJson(const BridgeSettings &s, const bridge::SettingPlace &place)
{
    return std::visit(
        Overloaded{
            [&](std::string bridge::Topics::*m) { return text(s.topics.*m); },
            [&](std::string BridgeSettings::*m) { return text(s.*m); },
            [&](double BridgeSettings::*m) { return jsonNumber(s.*m); },
            [&](double bridge::FeedbackSettings::*m) { return jsonNumber(s.feedback.*m); },
            [&](int BridgeSettings::*m) { return QByteArray::number(s.*m); },
            [&](bridge::AxisPlace) {
                return text(s.referenceAxis ? s.referenceAxis->twistName() : kAuto);
            },
            [&](bridge::ComponentPlace) { return text(s.feedback.component.wrenchName()); },
            [&](bridge::QosPlace) { return text(bridge::qosProfileName(s.qos)); },
            [&](bridge::OriginPlace) -> QByteArray {
                return '[' + jsonNumber(s.poseOrigin[0]) + ", " + jsonNumber(s.poseOrigin[1]) +
                       ", " + jsonNumber(s.poseOrigin[2]) + ']';
            },
        },
        place);
}

// `value` into `target` when `ok`; else `problem`, what is wrong with it.
template<typename T> QString take(T &target, bool ok, const T &value, const char *problem)
{
    if (!ok)
        return QString::fromUtf8(problem);
    target = value;
    return {};
}

// Reads one value; returns what is wrong with it ("must be a number"), or an empty string.
QString readValue(const QJsonValue &v, const bridge::SettingPlace &place, BridgeSettings &s)
{
    const std::string t = v.toString().toStdString();
    const double d = v.toDouble(std::nan(""));
    const auto c = Component::parse(t);
    return std::visit(
        Overloaded{
            [&](std::string bridge::Topics::*m) {
                return take(s.topics.*m, v.isString(), t, "must be a string");
            },
            [&](std::string BridgeSettings::*m) {
                return take(s.*m, v.isString(), t, "must be a string");
            },
            [&](double BridgeSettings::*m) {
                return take(s.*m, v.isDouble(), d, "must be a number");
            },
            [&](double bridge::FeedbackSettings::*m) {
                return take(s.feedback.*m, v.isDouble(), d, "must be a number");
            },
            [&](int BridgeSettings::*m) {
                return take(s.*m, v.isDouble() && d == std::floor(d) && std::abs(d) <= 1e9, int(d),
                            "must be a whole number");
            },
            [&](bridge::AxisPlace) {
                return take(s.referenceAxis, v.isString() && (t == kAuto || c), c,
                            "must be \"auto\" or one of \"linear.x\" … \"angular.z\"");
            },
            [&](bridge::ComponentPlace) {
                return take(s.feedback.component, v.isString() && c, c.value_or(Component{}),
                            "must be one of \"force.x\" … \"torque.z\"");
            },
            [&](bridge::QosPlace) {
                const auto q = bridge::parseQosProfile(t);
                return take(s.qos, v.isString() && q, q.value_or(s.qos),
                            "must be \"reliable\" or \"best-effort\"");
            },
            [&](bridge::OriginPlace) {
                const QJsonArray a = v.toArray();
                const bool ok = v.isArray() && a.size() == 3 && a[0].isDouble() &&
                                a[1].isDouble() && a[2].isDouble();
                return take(s.poseOrigin, ok, {a[0].toDouble(), a[1].toDouble(), a[2].toDouble()},
                            "must be an array of three numbers [x, y, z] in metres");
            },
        },
        place);
}

} // namespace

QByteArray bridgeSettingsJson(const BridgeSettings &settings, int indent)
{
    JsonObjectWriter writer(indent);
    for (const bridge::SettingSpec &spec : bridge::kSettings) {
        if (spec.inProfile)
            writer.add(spec.key.data(), valueJson(settings, spec.place));
    }
    return writer.text();
}

void readBridgeSettings(const QJsonObject &object, const QString &prefix, BridgeSettings &settings,
                        QStringList &errors, QStringList &warnings)
{
    QStringList known;
    for (const bridge::SettingSpec &spec : bridge::kSettings) {
        if (!spec.inProfile)
            continue;
        const QString name = QString::fromLatin1(spec.key.data(), qsizetype(spec.key.size()));
        known.append(name);
        const QJsonValue value = object.value(name);
        if (value.isUndefined())
            continue;
        if (const QString problem = readValue(value, spec.place, settings); !problem.isEmpty())
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
