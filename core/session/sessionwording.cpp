#include "session/sessionwording.h"

namespace hatpic {

namespace {

QString number(qint64 n)
{
    return QString::number(n);
}

QString joined(const QStringList &problems)
{
    return problems.join(u"; ");
}

} // namespace

QString SessionWording::port(const StateDetail &detail)
{
    if (detail.simulated)
        return tr("the simulated joystick");
    return tr("%1 at %2 baud").arg(detail.port, number(detail.baud));
}

QString SessionWording::stateDetail(const StateDetail &d)
{
    using Kind = StateDetail::Kind;
    switch (d.kind) {
    case Kind::None:
        return {};
    case Kind::Opening:
        return tr("Opening %1").arg(port(d));
    case Kind::OpenFailed:
        return tr("Cannot open %1: %2").arg(port(d), d.error);
    case Kind::UsingLegacy:
        return tr("Using the legacy protocol on %1").arg(port(d));
    case Kind::AskingHello:
        return tr("Asking for HELLO on %1").arg(port(d));
    case Kind::Listening:
        return tr("Listening for a legacy device on %1").arg(port(d));
    case Kind::SendingHello:
        return tr("Sending HELLO on %1").arg(port(d));
    case Kind::BaudSwitchFailed:
        return tr("Cannot switch %1 to %2 baud: %3").arg(d.port, number(d.targetBaud), d.error);
    case Kind::NoAnswer: {
        const QString heard =
            tr("got %1 valid, %2 needed").arg(number(d.legacyFrames), number(d.legacyFramesNeeded));
        if (d.listenBaud > 0) {
            return tr("No HATPIC answered on %1: listened %2 ms at %3 baud for legacy frames (%4), "
                      "then sent HELLO and got no HELLO_REPLY within %5 ms.")
                .arg(port(d), number(d.listenMs), number(d.listenBaud), heard,
                     number(d.helloWaitMs));
        }
        return tr("No HATPIC answered on %1: listened %2 ms for legacy frames (%3), then sent "
                  "HELLO and got no HELLO_REPLY within %4 ms.")
            .arg(port(d), number(d.listenMs), heard, number(d.helloWaitMs));
    }
    case Kind::NoHelloReply:
        return tr("No HATPIC v2 device answered on %1: HELLO sent %2 times, %3 ms apart, without "
                  "a HELLO_REPLY.")
            .arg(port(d), number(d.attempts), number(d.intervalMs));
    case Kind::Refused:
        return tr("Refused the device on %1: %2. It does not behave as a HATPIC joystick; nothing "
                  "was sent to it.")
            .arg(port(d), d.error);
    case Kind::ConnectedV2:
        return tr("HATPIC v2 \"%1\" on %2").arg(d.firmware, port(d));
    case Kind::ConnectedLegacy:
        return tr("Legacy HATPIC on %1").arg(port(d));
    case Kind::LinkFailed:
        return tr("Lost %1: %2").arg(port(d), d.error);
    case Kind::Silent:
        return tr("Lost %1: no data from the device for %2 s")
            .arg(port(d), QString::number(d.silenceMs / 1000.0));
    }
    return {};
}

QString SessionWording::notice(const SessionNotice &notice)
{
    switch (notice.kind) {
    case SessionNotice::Kind::RecordingNeedsDevice:
        return tr("Not connected: a recording starts once a device is connected.");
    case SessionNotice::Kind::RecordingClosedByLoss:
        return tr("Recording closed: the device was lost.");
    case SessionNotice::Kind::RecordingWaitsForDevice:
        return tr("The device was lost while recording: the recording stays open and goes on "
                  "in the same file when the device is back.");
    case SessionNotice::Kind::RecordingResumed:
        return tr("The device is back: recording resumed in the same file; the gap is marked "
                  "in it.");
    case SessionNotice::Kind::RecordingClosedOtherDevice:
        return tr("Recording ended at the link loss: a different device answered (%1). Start a "
                  "new recording to record it.")
            .arg(joined(notice.problems));
    case SessionNotice::Kind::HostParamsRefused:
        return tr("Host parameters refused: %1").arg(joined(notice.problems));
    }
    return {};
}

QString SessionWording::rejection(const CommandResult &r)
{
    const QString status = v2::ackStatusName(r.ackStatus);
    if (r.field < 0)
        return tr("The device rejected %1: %2.").arg(commandName(r.command), status);
    if (r.command == CommandKind::SetEffects) {
        return tr("The device rejected %1 (field %2): %3; its effects are unchanged.")
            .arg(QString::fromLatin1(effectFieldName(r.field)), number(r.field), status);
    }
    if (r.command == CommandKind::SetPassivity) {
        return tr("The device rejected %1 (field %2): %3; its passivity controller is unchanged.")
            .arg(QString::fromLatin1(passivityFieldName(r.field)), number(r.field), status);
    }
    if (r.command == CommandKind::Vibrate)
        return tr("The device rejected VIBRATE (field %1): %2.").arg(number(r.field), status);
    return tr("The device rejected %1 (field %2): %3; its parameters are unchanged.")
        .arg(QString::fromLatin1(deviceFieldName(r.field)), number(r.field), status);
}

// Cause, then consequence: the same shape for every command a device cannot carry.
QString SessionWording::unsupported(const CommandResult &r)
{
    using Reason = CommandResult::Reason;
    const QString name = commandName(r.command);
    switch (r.reason) {
    case Reason::NoEffects:
        return tr("%1 is not available: the device runs the published firmware (legacy "
                  "protocol), which cannot render effects.")
            .arg(name);
    case Reason::NoEffectsCapability:
        return tr("%1 is not available: this device's firmware does not announce the effects "
                  "capability, so it cannot render effects.")
            .arg(name);
    case Reason::NoPassivityCapability:
        return tr("%1 is not available: this device's firmware does not announce the passivity "
                  "capability, so it has no passivity controller.")
            .arg(name);
    case Reason::FixedRate:
        return tr("%1 is not available: the device runs the published firmware (legacy "
                  "protocol), which streams at its own fixed rate of about 5 Hz.")
            .arg(name);
    default:
        return tr("%1 is not available: the device runs the published firmware (legacy "
                  "protocol), which cannot send or take parameters.")
            .arg(name);
    }
}

// Refused on the host, before anything went on the wire: each sentence says so.
QString SessionWording::invalid(const CommandResult &r)
{
    if (r.reason == CommandResult::Reason::QueueFull) {
        return tr("Too many commands are waiting (%1); %2 was not sent.")
            .arg(number(r.limit), commandName(r.command));
    }
    if (r.command == CommandKind::Vibrate)
        return tr("The vibration cue is not valid: %1; nothing was sent.").arg(joined(r.problems));
    if (r.command == CommandKind::SetEffects)
        return tr("The effects are not valid: %1; nothing was sent.").arg(joined(r.problems));
    if (r.command == CommandKind::SetPassivity)
        return tr("The passivity settings are not valid: %1; nothing was sent.")
            .arg(joined(r.problems));
    return tr("The parameters are not valid: %1; nothing was sent.").arg(joined(r.problems));
}

QString SessionWording::appliedBeforeFailure(const CommandResult &r)
{
    const DeviceTuning applied = hatpic::appliedBeforeFailure(r);
    if (!applied.params && !applied.effects && !applied.passivity)
        return {};
    const bool lost = r.status == CommandResult::Status::NotConnected;
    QStringList parts;
    if (applied.params) {
        parts << (r.received.params ? tr("the parameters (SET_PARAMS, read back)")
                                    : tr("the parameters (SET_PARAMS, not read back)"));
    }
    if (applied.effects) {
        parts << (r.received.effects ? tr("the effects (SET_EFFECTS, read back)")
                                     : tr("the effects (SET_EFFECTS, not read back)"));
    }
    if (applied.passivity) {
        parts << (r.received.passivity
                      ? tr("the passivity settings (SET_PASSIVITY, read back)")
                      : tr("the passivity settings (SET_PASSIVITY, not read back)"));
    }
    QString text = lost
                       ? tr("It had accepted %1: those were in force when the link went.")
                             .arg(parts.join(tr(" and ")))
                       : tr("It had accepted %1: those are in force.").arg(parts.join(tr(" and ")));
    // A SET_EFFECTS or SET_PASSIVITY sent but never answered may or may not have taken effect.
    if (const auto step = unansweredBlockStep(r); step == CommandKind::SetEffects)
        text += u' ' + tr("Whether the effects changed is unknown until they are read back.");
    else if (step == CommandKind::SetPassivity)
        text += u' ' + tr("Whether the passivity settings changed is unknown until they are "
                          "read back.");
    return text;
}

QString SessionWording::commandFailure(const CommandResult &r)
{
    const QString failure = commandFailureAlone(r);
    const QString applied = appliedBeforeFailure(r);
    return applied.isEmpty() ? failure : failure + u' ' + applied;
}

QString SessionWording::commandFailureAlone(const CommandResult &r)
{
    using Status = CommandResult::Status;
    using Reason = CommandResult::Reason;
    switch (r.status) {
    case Status::Ok:
        return {};
    case Status::Rejected:
        return rejection(r);
    case Status::Timeout:
        return tr("The device did not answer %1 (sent %2 times, %3 ms apart).")
            .arg(commandName(r.command), number(r.attempts), number(r.intervalMs));
    case Status::NotConnected:
        if (r.reason == Reason::Disconnected)
            return tr("The session was disconnected before the device answered.");
        if (r.reason == Reason::ConnectionLost)
            return tr("The connection was lost before the device answered.");
        return tr("Not connected to a device.");
    case Status::Unsupported:
        return unsupported(r);
    case Status::Invalid:
        return invalid(r);
    }
    return {};
}

QString SessionWording::commandFailureBrief(const CommandResult &r)
{
    QString brief = commandFailureBriefAlone(r);
    const DeviceTuning applied = hatpic::appliedBeforeFailure(r);
    QStringList parts;
    if (applied.params)
        parts << tr("parameters");
    if (applied.effects)
        parts << tr("effects");
    if (applied.passivity)
        parts << tr("passivity settings");
    if (!parts.isEmpty())
        brief += tr("; %1 applied").arg(parts.join(tr(" and ")));
    return brief;
}

QString SessionWording::commandFailureBriefAlone(const CommandResult &r)
{
    using Status = CommandResult::Status;
    const bool effects = isEffectCommand(r.command);
    const bool passivity = isPassivityCommand(r.command);
    switch (r.status) {
    case Status::Ok:
        return {};
    case Status::Rejected: {
        QString reason = v2::ackStatusName(r.ackStatus);
        const QString name = QString::fromLatin1(effects     ? effectFieldName(r.field)
                                                 : passivity ? passivityFieldName(r.field)
                                                             : deviceFieldName(r.field));
        if (!name.isEmpty() && !reason.contains(name))
            reason += u" (" + name + u')';
        if (passivity)
            return tr("device rejected the passivity settings: %1").arg(reason);
        return effects ? tr("device rejected the effects: %1").arg(reason)
                       : tr("device rejected: %1").arg(reason);
    }
    case Status::Timeout:
        return tr("timeout: the device did not answer");
    case Status::NotConnected:
        return tr("push failed: not connected to the device");
    case Status::Unsupported:
        if (passivity)
            return tr("push failed: this device has no passivity controller");
        return effects ? tr("push failed: this device cannot render effects")
                       : tr("push failed: the device's protocol cannot carry parameters");
    case Status::Invalid:
        return r.problems.isEmpty() ? tr("push failed: the command was not sent")
                                    : tr("push failed: %1").arg(joined(r.problems));
    }
    return {};
}

QString SessionWording::noEffectsReason(bool legacy)
{
    return legacy ? tr("it runs the published firmware, legacy protocol")
                  : tr("its firmware does not announce the effects capability");
}

QString SessionWording::noPassivityReason(bool legacy)
{
    return legacy ? tr("it runs the published firmware, legacy protocol")
                  : tr("its firmware does not announce the passivity capability");
}

QString SessionWording::deviceLinesHeldBack(quint64 lines, int perInterval, int intervalMs)
{
    return tr("(%1 more lines from the device not shown: at most %2 every %3 s are)")
        .arg(QString::number(lines), number(perInterval), QString::number(intervalMs / 1000.0));
}

} // namespace hatpic
