#include "sessiontypes.h"

#include "device/numbertext.h"
#include "device/sample.h"

#include <QStringBuilder>
#include <QStringList>

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

QString printableDeviceText(const QString &text)
{
    QString out;
    out.reserve(text.size());
    for (const QChar c : text) {
        const char16_t u = c.unicode();
        if (u < 0x20 || (u >= 0x7F && u < 0xA0))
            out += u"\\x" % QString::number(u, 16).rightJustified(2, u'0');
        else
            out += c;
    }
    return out;
}

QString helloReplyProblem(const v2::HelloReply &reply)
{
    const double tauLimit = reply.tauLimit;
    if (!std::isfinite(tauLimit) || tauLimit <= 0 || tauLimit > 10) {
        return u"its tau_limit is " % QString::number(tauLimit) %
               u" N·m, and must be a finite number above 0 and at most 10";
    }
    if (reply.maxStreamHz == 0)
        return QStringLiteral("its max_stream_hz is 0, and must be above 0");
    return {};
}

QString describeParamChange(const DeviceParams &from, const DeviceParams &to)
{
    QStringList parts;
    const DeviceParams a = roundedForWire(from);
    const DeviceParams b = roundedForWire(to);
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        if (a.field(i) != b.field(i)) {
            const std::string_view name = deviceFieldName(i);
            parts << QString::fromLatin1(name.data(), qsizetype(name.size())) % u' ' %
                         compactNumberText(a.field(i)) % u" → " % compactNumberText(b.field(i));
        }
    }
    return parts.join(QStringLiteral("; "));
}

void registerSessionMetaTypes()
{
    qRegisterMetaType<hatpic::Sample>();
    qRegisterMetaType<hatpic::SampleBatch>();
    qRegisterMetaType<hatpic::HandInput>();
    qRegisterMetaType<hatpic::ConnectOptions>();
    qRegisterMetaType<hatpic::SessionState>();
    qRegisterMetaType<hatpic::DeviceInfo>();
    qRegisterMetaType<hatpic::CommandResult>();
    qRegisterMetaType<hatpic::LinkStats>();
    qRegisterMetaType<hatpic::RecordingStatus>();
    qRegisterMetaType<hatpic::DeviceParams>();
    qRegisterMetaType<hatpic::HostParams>();
}

} // namespace hatpic
