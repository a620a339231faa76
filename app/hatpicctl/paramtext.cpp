#include "paramtext.h"

#include "model/paramtable.h"
#include "profile/profile.h"
#include "telemetry/numbertext.h"

#include <cmath>

namespace hatpic::cli {

namespace {

QString text(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QString fieldName(int index)
{
    return text(deviceFieldName(index));
}

} // namespace

QString fieldUnit(int index)
{
    if (index < 0 || index >= DeviceParams::kFieldCount)
        return {};
    return text(kDeviceFields[static_cast<std::size_t>(index)].unit);
}

QString fieldMeaning(int index)
{
    if (index < 0 || index >= DeviceParams::kFieldCount)
        return {};
    return text(kDeviceFields[static_cast<std::size_t>(index)].meaning);
}

QString parameterTable(const DeviceParams &params)
{
    QString text;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        text += fieldName(i).leftJustified(8) +
                compactNumberText(params.field(i)).leftJustified(14) + u' ' +
                fieldUnit(i).leftJustified(11) + fieldMeaning(i) + u'\n';
    }
    return text;
}

QString effectTable(const EffectParams &effects)
{
    QString out;
    for (int i = 0; i < EffectParams::kFieldCount; ++i) {
        const EffectFieldSpec &spec = kEffectFields[static_cast<std::size_t>(i)];
        out += text(spec.name).leftJustified(16) +
               compactNumberText(effects.field(i)).leftJustified(14) + u' ' +
               text(spec.unit).leftJustified(11) + text(spec.meaning) + u'\n';
    }
    return out;
}

QString deviceEffectsProblem(const EffectParams &effects, double tauLimit)
{
    QStringList problems;
    for (const Violation &v : validate(effects, tauLimit))
        problems << QString::fromStdString(v.message());
    return problems.join(QStringLiteral("; "));
}

namespace {

Profile profileFromDevice(const DeviceParams &params, const DeviceInfo &info)
{
    Profile profile;
    profile.name = QStringLiteral("Read from device");
    profile.notes = u"Device parameters read from " + info.port + u" (device id 0x" +
                    QString::number(info.deviceId, 16).rightJustified(8, u'0') +
                    u"); host settings are defaults.";
    profile.device = tidyDeviceParams(params);
    if (std::isfinite(info.tauLimit) && info.tauLimit > 0 && info.tauLimit <= 10)
        profile.host.tau_limit = shortestFloatDecimal(info.tauLimit);
    return profile;
}

} // namespace

QByteArray parameterProfile(const DeviceParams &params, const DeviceInfo &info)
{
    return serializeProfile(profileFromDevice(params, info));
}

QString deviceParamsProblem(const DeviceParams &params)
{
    QStringList problems;
    for (const Violation &v : validate(params))
        problems << QString::fromStdString(v.message());
    return problems.join(QStringLiteral("; "));
}

QByteArray parameterOutput(const DeviceParams &params, const DeviceInfo &info, bool json)
{
    return json ? parameterProfile(params, info) : parameterTable(params).toUtf8();
}

QByteArray parameterOutput(const DeviceParams &params, const std::optional<EffectParams> &effects,
                           const DeviceInfo &info, bool json)
{
    if (!effects)
        return parameterOutput(params, info, json);
    if (!json)
        return (parameterTable(params) + effectTable(*effects)).toUtf8();
    Profile profile = profileFromDevice(params, info);
    profile.effects = tidyEffectParams(*effects);
    return serializeProfile(profile);
}

} // namespace hatpic::cli
