#include "deviceinfo.h"

#include "model/printabletext.h"

#include <QStringBuilder>

#include <cmath>

namespace hatpic {

QString wireProtocolName(WireProtocol protocol)
{
    return protocol == WireProtocol::Legacy ? QStringLiteral("legacy") : QStringLiteral("v2");
}

QString printableDeviceText(const QString &text)
{
    return QString::fromStdString(printableText(text.toStdString()));
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
