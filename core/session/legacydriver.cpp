#include "legacydriver.h"

#include "session/linkstatistics.h"
#include "session/samplebuilder.h"

namespace hatpic {

LegacyDriver::LegacyDriver(DriverHost &host, const ConnectOptions &options, qint32 baud)
    : m_host(host), m_conversion(options.legacy), m_feedbackOn(options.feedbackRateHz > 0),
      m_field(options.legacy.feedbackToField(0))
{
    m_info.protocol = WireProtocol::Legacy;
    m_info.port = options.port;
    m_info.baud = baud;
    m_info.protocolVersion = 0;
    m_info.maxStreamHz = 5;
    m_info.deviceId = 0;
    m_info.tauLimit = options.legacy.tauLimit;
    m_info.firmware = QStringLiteral("published firmware (legacy)");
    m_info.simulated = options.port == QStringView(kSimPortName);
}

void LegacyDriver::start()
{
    // The published firmware renders its own fixed spring; the host estimates τ_rec from its
    // copy of the parameters, which stays at the defaults (θ0 = 0).
    m_host.builder().setTauLimit(m_host.builder().hostParams().tau_limit);
}

void LegacyDriver::feed(const QByteArray &bytes)
{
    QList<legacy::Frame> frames;
    QStringList lines;
    m_decoder.feed(bytes, frames, &lines);
    for (const QString &line : std::as_const(lines)) {
        if (!line.isEmpty())
            m_host.deviceText(line);
    }
    for (const legacy::Frame &frame : std::as_const(frames)) {
        if (m_closed || !m_host.linkOpen())
            break;
        m_host.statistics().countFrame();
        const double tauExt = m_feedbackOn ? m_conversion.fieldToFeedback(m_field) : 0.0;
        m_host.pushSample(
            m_host.builder().fromLegacy(frame, m_conversion, tauExt, m_host.hostUs()));
    }
}

void LegacyDriver::sendFeedback(double tauExt)
{
    // One whole frame per write: the published firmware busy-waits from 'i' to 'o'.
    m_field = m_conversion.feedbackToField(tauExt);
    m_host.write(legacy::encodeFrame(legacy::Frame{m_field, 0, 0, 0}));
}

CommandResult::Reason LegacyDriver::refusal(CommandKind kind) const
{
    // Host settings still apply; only the device side is fixed.
    if (isEffectCommand(kind))
        return CommandResult::Reason::NoEffects;
    return kind == CommandKind::SetStream ? CommandResult::Reason::FixedRate
                                          : CommandResult::Reason::NoParameters;
}

void LegacyDriver::hostParamsChanged(const HostParams &host)
{
    m_host.builder().setTauLimit(host.tau_limit);
}

void LegacyDriver::close()
{
    if (m_closed)
        return;
    m_closed = true;
    m_host.statistics().absorb(m_decoder.stats());
    m_decoder.resetStats();
}

} // namespace hatpic
