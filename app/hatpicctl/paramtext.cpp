#include "paramtext.h"

#include "model/paramtable.h"
#include "profile/profile.h"
#include "telemetry/numbertext.h"

#include <cmath>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

QString text(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

//! One line per field of `fields`: name (padded to `nameWidth`), value, unit, meaning.
template<typename Block, std::size_t N>
QString blockTable(const std::array<FieldSpec<Block>, N> &fields, const Block &block, int nameWidth)
{
    QString out;
    for (const FieldSpec<Block> &spec : fields) {
        out += text(spec.name).leftJustified(nameWidth) +
               compactNumberText(block.*spec.member).leftJustified(14) + u' ' +
               text(spec.unit).leftJustified(11) + text(spec.meaning) + u'\n';
    }
    return out;
}

} // namespace

QString parameterTable(const DeviceParams &params)
{
    return blockTable(kDeviceFields, params, 8);
}

QByteArray tuningOutput(const DeviceTuning &tuning, const DeviceInfo &info, bool json)
{
    const DeviceParams params = tuning.params.value_or(DeviceParams{});
    if (!json) {
        QString table = parameterTable(params);
        if (tuning.effects)
            table += blockTable(kEffectFields, *tuning.effects, 16);
        if (tuning.passivity)
            table += blockTable(kPassivityFields, *tuning.passivity, 16);
        return table.toUtf8();
    }
    Profile profile;
    profile.name = u"Read from device"_s;
    profile.notes = u"Device parameters read from " + info.port + u" (device id 0x" +
                    QString::number(info.deviceId, 16).rightJustified(8, u'0') +
                    u"); host settings are defaults.";
    profile.device = tidyDeviceParams(params);
    if (std::isfinite(info.tauLimit) && info.tauLimit > 0 && info.tauLimit <= 10)
        profile.host.tau_limit = shortestFloatDecimal(info.tauLimit);
    if (tuning.effects)
        profile.effects = tidyEffectParams(*tuning.effects);
    if (tuning.passivity)
        profile.passivity = tidyPassivityParams(*tuning.passivity);
    // Every block the device has, defaults or not: a profile saved from it must not take
    // another version's defaults for what the device held.
    return serializeProfile(profile, {.effects = tuning.effects.has_value(),
                                      .passivity = tuning.passivity.has_value()});
}

QString problemText(const std::vector<Violation> &violations)
{
    QStringList problems;
    for (const Violation &v : violations)
        problems << QString::fromStdString(v.message());
    return problems.join(u"; "_s);
}

} // namespace hatpic::cli
