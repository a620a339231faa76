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

constexpr char kAuto[] = "auto";

QByteArray text(const std::string &s)
{
    return jsonString(QString::fromStdString(s));
}

QByteArray valueJson(const BridgeSettings &s, const bridge::SettingPlace &place)
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
        QByteArray operator()(bridge::AxisPlace) const
        {
            return text(s.referenceAxis ? s.referenceAxis->twistName() : kAuto);
        }
        QByteArray operator()(bridge::ComponentPlace) const
        {
            return text(s.feedback.component.wrenchName());
        }
        QByteArray operator()(bridge::QosPlace) const
        {
            return text(bridge::qosProfileName(s.qos));
        }
        QByteArray operator()(bridge::OriginPlace) const
        {
            return '[' + jsonNumber(s.poseOrigin[0]) + ", " + jsonNumber(s.poseOrigin[1]) + ", " +
                   jsonNumber(s.poseOrigin[2]) + ']';
        }
    };
    return std::visit(Visitor{s}, place);
}

// Reads one value; returns what is wrong with it ("must be a number"), or an empty string.
QString readValue(const QJsonValue &v, const bridge::SettingPlace &place, BridgeSettings &s)
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
        QString operator()(bridge::AxisPlace) const
        {
            const std::string t = v.toString().toStdString();
            const auto c = Component::parse(t);
            if (!v.isString() || (t != kAuto && !c))
                return QStringLiteral("must be \"auto\" or one of \"linear.x\" … \"angular.z\"");
            s.referenceAxis = c;
            return {};
        }
        QString operator()(bridge::ComponentPlace) const
        {
            const auto c = Component::parse(v.toString().toStdString());
            if (!v.isString() || !c)
                return QStringLiteral("must be one of \"force.x\" … \"torque.z\"");
            s.feedback.component = *c;
            return {};
        }
        QString operator()(bridge::QosPlace) const
        {
            const auto q = bridge::parseQosProfile(v.toString().toStdString());
            if (!v.isString() || !q)
                return QStringLiteral("must be \"reliable\" or \"best-effort\"");
            s.qos = *q;
            return {};
        }
        QString operator()(bridge::OriginPlace) const
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
