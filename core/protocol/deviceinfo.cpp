#include "deviceinfo.h"

#include <QStringBuilder>

#include <cmath>

namespace hatpic {

QString wireProtocolName(WireProtocol protocol)
{
    return protocol == WireProtocol::Legacy ? QStringLiteral("legacy") : QStringLiteral("v2");
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

} // namespace hatpic
