#include "legacydriver.h"

namespace hatpic {

LegacyDriver::LegacyDriver(const ConnectOptions &options, qint32 baud, DriverWrite write)
    : m_write(std::move(write)), m_conversion(options.legacy),
      m_feedbackOn(options.feedbackRateHz > 0), m_field(options.legacy.feedbackToField(0))
{
    m_info.protocol = WireProtocol::Legacy;
    m_info.port = options.port;
    m_info.baud = baud;
    m_info.protocolVersion = 0;
    m_info.maxStreamHz = 5;
    m_info.deviceId = 0;
    m_info.tauLimit = options.legacy.tauLimit;
    m_info.firmware = QStringLiteral("published firmware (legacy)");
    m_info.simulated = options.link && options.link->simulated();
}

void LegacyDriver::feed(const QByteArray &bytes, std::vector<Received> &out)
{
    QList<legacy::Frame> frames;
    QStringList lines;
    m_decoder.feed(bytes, frames, &lines);
    for (QString &line : lines) {
        if (!line.isEmpty())
            out.push_back(received::Text{std::move(line)});
    }
    const double tauExt = m_feedbackOn ? m_conversion.fieldToFeedback(m_field) : 0.0;
    for (const legacy::Frame &frame : std::as_const(frames))
        out.push_back(received::LegacyFrame{frame, &m_conversion, tauExt});
}

void LegacyDriver::sendFeedback(double tauExt)
{
    // One whole frame per write: the published firmware busy-waits from 'i' to 'o'.
    m_field = m_conversion.feedbackToField(tauExt);
    m_write(legacy::encodeFrame(legacy::Frame{m_field, 0, 0, 0}));
}

std::optional<outcome::Unsupported::Why> LegacyDriver::refusal(CommandKind step) const
{
    // Host settings still apply; only the device side is fixed.
    using Why = outcome::Unsupported::Why;
    if (isEffectCommand(step))
        return Why::NoEffects;
    if (isPassivityCommand(step))
        return Why::NoPassivityCapability;
    return step == CommandKind::SetStream ? Why::FixedRate : Why::NoParameters;
}

} // namespace hatpic
