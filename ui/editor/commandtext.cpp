#include "editor/commandtext.h"

namespace hatpic {

QString CommandText::rejection(const CommandResult &r)
{
    const QString status = v2::ackStatusName(r.ackStatus);
    if (r.field < 0)
        return tr("The device rejected %1: %2.").arg(commandName(r.command), status);
    if (r.command == CommandKind::SetEffects) {
        return tr("The device rejected %1 (field %2): %3; its effects are unchanged.")
            .arg(QString::fromLatin1(effectFieldName(r.field)), QString::number(r.field), status);
    }
    if (r.command == CommandKind::Vibrate) {
        return tr("The device rejected VIBRATE (field %1): %2.")
            .arg(QString::number(r.field), status);
    }
    return tr("The device rejected %1 (field %2): %3; its parameters are unchanged.")
        .arg(QString::fromLatin1(deviceFieldName(r.field)), QString::number(r.field), status);
}

QString CommandText::noEffectsReason(bool legacy)
{
    return legacy ? tr("it runs the published firmware, legacy protocol")
                  : tr("its firmware does not announce the effects capability");
}

QString CommandText::commandFailure(const CommandResult &r)
{
    using Status = CommandResult::Status;
    using Reason = CommandResult::Reason;
    const QString name = commandName(r.command);
    if (r.ok())
        return {};
    if (r.status == Status::Rejected)
        return rejection(r);
    if (r.status == Status::Timeout) {
        return tr("The device did not answer %1 (sent %2 times, %3 ms apart).")
            .arg(name, QString::number(r.attempts), QString::number(r.intervalMs));
    }
    if (r.status == Status::Unsupported &&
        (r.reason == Reason::NoEffects || r.reason == Reason::NoEffectsCapability)) {
        return tr("%1 is not available: this device cannot render effects (%2).")
            .arg(name, noEffectsReason(r.reason == Reason::NoEffects));
    }
    if (r.status == Status::Unsupported) {
        const QString why = r.reason == Reason::FixedRate
                                ? tr("which streams at its own fixed rate of about 5 Hz")
                                : tr("which cannot send or take parameters; host settings "
                                     "still apply");
        return tr("%1 is not available: the device runs the published firmware (legacy "
                  "protocol), %2.")
            .arg(name, why);
    }
    if (r.reason == Reason::QueueFull) {
        return tr("Too many commands are waiting (%1); %2 was not sent.")
            .arg(QString::number(r.limit), name);
    }
    if (r.reason == Reason::InvalidParams && r.command == CommandKind::Vibrate)
        return tr("The vibration cue is not valid: %1.").arg(r.problems.join(u"; "));
    if (r.reason == Reason::InvalidParams && r.command == CommandKind::SetEffects)
        return tr("The effects are not valid: %1.").arg(r.problems.join(u"; "));
    if (r.reason == Reason::InvalidParams)
        return tr("The parameters are not valid: %1.").arg(r.problems.join(u"; "));
    if (r.reason == Reason::Disconnected)
        return tr("The session was disconnected before the device answered.");
    if (r.reason == Reason::ConnectionLost)
        return tr("The connection was lost before the device answered.");
    return tr("Not connected to a device.");
}

} // namespace hatpic
