#include "sessiontypes.h"

#include "telemetry/numbertext.h"
#include "telemetry/sample.h"

#include <QStringBuilder>
#include <QStringList>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace hatpic {

QString sessionStateName(SessionState state)
{
    switch (state) {
    case SessionState::Disconnected:
        return QStringLiteral("disconnected");
    case SessionState::Opening:
        return QStringLiteral("opening");
    case SessionState::Detecting:
        return QStringLiteral("detecting");
    case SessionState::Connected:
        return QStringLiteral("connected");
    case SessionState::Lost:
        return QStringLiteral("lost");
    }
    return QStringLiteral("unknown");
}

quint64 LinkStats::totalDecoderDrops() const
{
    return std::accumulate(decoderDrops.begin(), decoderDrops.end(), quint64(0));
}

namespace {

//! "name a → b" for each field of a block that differs as the wire carries it (`onWire`: the
//! device's fields rounded by their own rule, the blocks' to float32).
template<typename Block>
QString describeBlockChange(const Block &from, const Block &to, std::string_view (*fieldName)(int),
                            double (*onWire)(int, double))
{
    QStringList parts;
    for (int i = 0; i < Block::kFieldCount; ++i) {
        const double a = onWire(i, from.field(i));
        const double b = onWire(i, to.field(i));
        if (a != b) {
            const std::string_view name = fieldName(i);
            parts << QString::fromLatin1(name.data(), qsizetype(name.size())) % u' ' %
                         compactNumberText(a) % u" → " % compactNumberText(b);
        }
    }
    return parts.join(QStringLiteral("; "));
}

double asFloat(int, double value)
{
    return static_cast<float>(value);
}

} // namespace

QString describeTuningChange(const DeviceTuning &from, const DeviceTuning &to)
{
    QStringList parts;
    const auto describe = [&parts](const auto &was, const auto &now, std::string_view (*name)(int),
                                   double (*onWire)(int, double)) {
        if (!now)
            return;
        using Block = std::decay_t<decltype(*now)>;
        if (const QString p = describeBlockChange(was.value_or(Block{}), *now, name, onWire);
            !p.isEmpty())
            parts << p;
    };
    describe(from.params, to.params, &deviceFieldName, &roundedForWire);
    describe(from.effects, to.effects, &effectFieldName, &asFloat);
    describe(from.passivity, to.passivity, &passivityFieldName, &asFloat);
    return parts.join(QStringLiteral("; "));
}

QStringList describeDeviceChange(const DeviceInfo &from, const DeviceInfo &to)
{
    QStringList parts;
    auto differ = [&parts](QStringView name, const QString &a, const QString &b) {
        if (a != b)
            parts << name % u' ' % a % u" → " % b;
    };
    differ(u"protocol", wireProtocolName(from.protocol), wireProtocolName(to.protocol));
    differ(u"protocol_version", QString::number(from.protocolVersion),
           QString::number(to.protocolVersion));
    differ(u"device_id", QString::number(from.deviceId), QString::number(to.deviceId));
    differ(u"firmware", u'"' % from.firmware % u'"', u'"' % to.firmware % u'"');
    differ(u"tau_limit", compactNumberText(from.tauLimit), compactNumberText(to.tauLimit));
    differ(u"max_stream_hz", QString::number(from.maxStreamHz), QString::number(to.maxStreamHz));
    differ(u"capabilities", QString::number(from.capabilities), QString::number(to.capabilities));
    differ(u"baud", QString::number(from.baud), QString::number(to.baud));
    return parts;
}

void registerSessionMetaTypes()
{
    qRegisterMetaType<hatpic::Sample>();
    qRegisterMetaType<hatpic::SampleBatch>();
    qRegisterMetaType<hatpic::ConnectOptions>();
    qRegisterMetaType<hatpic::SessionState>();
    qRegisterMetaType<hatpic::StateDetail>();
    qRegisterMetaType<hatpic::SessionNotice>();
    qRegisterMetaType<hatpic::DeviceInfo>();
    qRegisterMetaType<hatpic::Request>();
    qRegisterMetaType<hatpic::Outcome>();
    qRegisterMetaType<hatpic::LinkStats>();
    qRegisterMetaType<hatpic::RecordingStatus>();
    qRegisterMetaType<hatpic::DeviceParams>();
    qRegisterMetaType<hatpic::DeviceTuning>();
    qRegisterMetaType<hatpic::HostParams>();
    qRegisterMetaType<hatpic::EffectParams>();
    qRegisterMetaType<hatpic::PassivityParams>();
    qRegisterMetaType<hatpic::Vibration>();
}

} // namespace hatpic
