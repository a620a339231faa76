#include "legacydriver.h"

namespace hatpic {

LegacyDriver::LegacyDriver(const ConnectOptions &options, qint32 baud, DriverWrite write)
    : m_write(std::move(write)), m_conversion(options.legacy),
      m_feedbackOn(options.feedbackRateHz > 0)
{
    m_fields.fill(m_conversion.feedbackToField(0));
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
    AxisTorques tauExt{};
    for (std::size_t n = 0; m_feedbackOn && n < tauExt.size(); ++n)
        tauExt[n] = m_conversion.fieldToFeedback(m_fields[n]);
    for (const legacy::Frame &frame : std::as_const(frames)) {
        if (frame.tilt) // what the board is shows in its frames only
            noteImuBranch();
        out.push_back(received::LegacyFrame{frame, &m_conversion, tauExt});
    }
}

void LegacyDriver::noteImuBranch()
{
    m_info.axes = legacy::kImuBranchServos;
    m_info.tilt = true;
    m_info.firmware = QStringLiteral("published IMU branch (legacy)");
}

void LegacyDriver::sendFeedback(const AxisTorques &tauExt)
{
    // One whole frame per write: the published firmware busy-waits from 'i' to 'o'. Field n is
    // knob n's, on the same scale as A (the IMU branch adds each − 1000 to its servo's torque);
    // the master firmware ignores B, C and D. No force is 1000 in every field, never the 0 the
    // published driver sends: the IMU branch would render that as −100 % on servos 2, 3, 4.
    for (std::size_t n = 0; n < tauExt.size(); ++n)
        m_fields[n] = m_conversion.feedbackToField(tauExt[n]);
    m_write(legacy::encodeFrame(legacy::Frame{m_fields[0], m_fields[1], m_fields[2], m_fields[3]}));
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
