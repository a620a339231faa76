#include "legacydriver.h"

#include "session/linkstatistics.h"
#include "session/samplepipeline.h"

namespace hatpic {

LegacyDriver::LegacyDriver(DriverLinks links, const ConnectOptions &options, qint32 baud)
    : m_links(std::move(links)), m_conversion(options.legacy),
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

void LegacyDriver::start()
{
    // The published firmware renders its own fixed spring; the host estimates τ_rec from its
    // copy of the parameters, which stays at the defaults (θ0 = 0).
    SampleBuilder &builder = m_links.samples.builder();
    builder.setTauLimit(builder.hostParams().tau_limit);
}

void LegacyDriver::feed(const QByteArray &bytes)
{
    QList<legacy::Frame> frames;
    QStringList lines;
    m_decoder.feed(bytes, frames, &lines);
    for (const QString &line : std::as_const(lines)) {
        if (!line.isEmpty())
            m_links.deviceText(line);
    }
    for (const legacy::Frame &frame : std::as_const(frames)) {
        if (m_closed)
            break;
        m_links.statistics.countFrame();
        const double tauExt = m_feedbackOn ? m_conversion.fieldToFeedback(m_field) : 0.0;
        m_links.samples.push(m_links.samples.builder().fromLegacy(
            frame, m_conversion, tauExt, m_links.clock.nsecsElapsed() / 1000));
    }
}

void LegacyDriver::sendFeedback(double tauExt)
{
    // One whole frame per write: the published firmware busy-waits from 'i' to 'o'.
    m_field = m_conversion.feedbackToField(tauExt);
    m_links.write(legacy::encodeFrame(legacy::Frame{m_field, 0, 0, 0}));
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

void LegacyDriver::hostParamsChanged(const HostParams &host)
{
    m_links.samples.builder().setTauLimit(host.tau_limit);
}

void LegacyDriver::close()
{
    if (m_closed)
        return;
    m_closed = true;
    m_links.statistics.absorb(m_decoder.stats());
    m_decoder.resetStats();
}

} // namespace hatpic
