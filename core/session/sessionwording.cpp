#include "session/sessionwording.h"

#include "model/overloaded.h"

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
    const QString where = port(d);
    return std::visit(
        Overloaded{
            [](const state::None &) { return QString(); },
            [&](const state::Opening &) { return tr("Opening %1").arg(where); },
            [&](const state::OpenFailed &w) {
                return tr("Cannot open %1: %2").arg(where, w.error);
            },
            [&](const state::UsingLegacy &) {
                return tr("Using the legacy protocol on %1").arg(where);
            },
            [&](const state::AskingHello &) { return tr("Asking for HELLO on %1").arg(where); },
            [&](const state::Listening &) {
                return tr("Listening for a legacy device on %1").arg(where);
            },
            [&](const state::SendingHello &) { return tr("Sending HELLO on %1").arg(where); },
            [&](const state::BaudSwitchFailed &w) {
                return tr("Cannot switch %1 to %2 baud: %3")
                    .arg(d.port, number(w.targetBaud), w.error);
            },
            [&](const state::NoAnswer &w) {
                const QString heard =
                    tr("got %1 valid, %2 needed")
                        .arg(number(w.legacyFrames), number(w.legacyFramesNeeded));
                if (w.listenBaud > 0) {
                    return tr("No HATPIC answered on %1: listened %2 ms at %3 baud for legacy "
                              "frames (%4), then sent HELLO and got no HELLO_REPLY within %5 ms.")
                        .arg(where, number(w.listenMs), number(w.listenBaud), heard,
                             number(w.helloWaitMs));
                }
                return tr("No HATPIC answered on %1: listened %2 ms for legacy frames (%3), then "
                          "sent HELLO and got no HELLO_REPLY within %4 ms.")
                    .arg(where, number(w.listenMs), heard, number(w.helloWaitMs));
            },
            [&](const state::NoHelloReply &w) {
                return tr("No HATPIC v2 device answered on %1: HELLO sent %2 times, %3 ms apart, "
                          "without a HELLO_REPLY.")
                    .arg(where, number(w.attempts), number(w.intervalMs));
            },
            [&](const state::Refused &w) {
                return tr("Refused the device on %1: %2. It does not behave as a HATPIC "
                          "joystick; nothing was sent to it.")
                    .arg(where, w.error);
            },
            [&](const state::ConnectedV2 &w) {
                return tr("HATPIC v2 \"%1\" on %2").arg(w.firmware, where);
            },
            [&](const state::ConnectedLegacy &) { return tr("Legacy HATPIC on %1").arg(where); },
            [&](const state::LinkFailed &w) { return tr("Lost %1: %2").arg(where, w.error); },
            [&](const state::Silent &w) {
                return tr("Lost %1: no data from the device for %2 s")
                    .arg(where, QString::number(w.silenceMs / 1000.0));
            },
        },
        d.why);
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

QString SessionWording::rejection(const outcome::Refused &r)
{
    const QString status = v2::ackStatusName(r.status);
    if (r.field < 0)
        return tr("The device rejected %1: %2.").arg(commandName(r.step), status);
    const QString name = QString::fromLatin1(r.fieldName());
    if (r.step == CommandKind::SetEffects) {
        return tr("The device rejected %1 (field %2): %3; its effects are unchanged.")
            .arg(name, number(r.field), status);
    }
    if (r.step == CommandKind::SetPassivity) {
        return tr("The device rejected %1 (field %2): %3; its passivity controller is unchanged.")
            .arg(name, number(r.field), status);
    }
    if (r.step == CommandKind::Vibrate)
        return tr("The device rejected VIBRATE (field %1): %2.").arg(number(r.field), status);
    return tr("The device rejected %1 (field %2): %3; its parameters are unchanged.")
        .arg(name, number(r.field), status);
}

// Cause, then consequence: the same shape for every step a device cannot carry.
QString SessionWording::unsupported(const outcome::Unsupported &u)
{
    using Why = outcome::Unsupported::Why;
    const QString name = commandName(u.step);
    switch (u.why) {
    case Why::NoEffects:
        return tr("%1 is not available: the device runs the published firmware (legacy "
                  "protocol), which cannot render effects.")
            .arg(name);
    case Why::NoEffectsCapability:
        return tr("%1 is not available: this device's firmware does not announce the effects "
                  "capability, so it cannot render effects.")
            .arg(name);
    case Why::NoPassivityCapability:
        return tr("%1 is not available: this device's firmware does not announce the passivity "
                  "capability, so it has no passivity controller.")
            .arg(name);
    case Why::FixedRate:
        return tr("%1 is not available: the device runs the published firmware (legacy "
                  "protocol), which streams at its own fixed rate of about 5 Hz.")
            .arg(name);
    case Why::NoSuchKnob:
        if (u.axes == 1)
            return tr("%1 is not available for knob %2: the device has one knob.")
                .arg(name, number(int(u.knob) + 1));
        return tr("%1 is not available for knob %2: the device has %3 knobs.")
            .arg(name, number(int(u.knob) + 1), number(u.axes));
    case Why::NoParameters:
        break;
    }
    return tr("%1 is not available: the device runs the published firmware (legacy "
              "protocol), which cannot send or take parameters.")
        .arg(name);
}

// Refused on the host, before anything went on the wire: each sentence says so. A push is named
// by its first part.
QString SessionWording::invalid(const Request &request, const outcome::Invalid &i)
{
    const QString problems = joined(i.problems);
    if (std::holds_alternative<request::Vibrate>(request))
        return tr("The vibration cue is not valid: %1; nothing was sent.").arg(problems);
    const auto *push = std::get_if<request::Push>(&request);
    if (push && !push->tuning.params && push->tuning.effects)
        return tr("The effects are not valid: %1; nothing was sent.").arg(problems);
    if (push && !push->tuning.params && !push->tuning.effects)
        return tr("The passivity settings are not valid: %1; nothing was sent.").arg(problems);
    return tr("The parameters are not valid: %1; nothing was sent.").arg(problems);
}

QString SessionWording::appliedBeforeFailure(const Outcome &o)
{
    const outcome::Stopped *stop = o.stopped();
    if (!stop)
        return {};
    const DeviceTuning &applied = stop->applied;
    QStringList parts;
    if (applied.params) {
        parts << (o.received.params ? tr("the parameters (SET_PARAMS, read back)")
                                    : tr("the parameters (SET_PARAMS, not read back)"));
    }
    if (applied.effects) {
        parts << (o.received.effects ? tr("the effects (SET_EFFECTS, read back)")
                                     : tr("the effects (SET_EFFECTS, not read back)"));
    }
    if (applied.passivity) {
        parts << (o.received.passivity
                      ? tr("the passivity settings (SET_PASSIVITY, read back)")
                      : tr("the passivity settings (SET_PASSIVITY, not read back)"));
    }
    if (parts.isEmpty())
        return {};
    QString text = std::holds_alternative<outcome::Cut>(o.result)
                       ? tr("It had accepted %1: those were in force when the link went.")
                             .arg(parts.join(tr(" and ")))
                       : tr("It had accepted %1: those are in force.").arg(parts.join(tr(" and ")));
    // A SET_EFFECTS or SET_PASSIVITY sent but never answered may or may not have taken effect.
    if (const auto step = o.unknownStep(); step == CommandKind::SetEffects)
        text += u' ' + tr("Whether the effects changed is unknown until they are read back.");
    else if (step == CommandKind::SetPassivity)
        text += u' ' + tr("Whether the passivity settings changed is unknown until they are "
                          "read back.");
    return text;
}

QString SessionWording::commandFailure(const Outcome &o)
{
    const QString failure = std::visit(
        Overloaded{
            [](const outcome::Done &) { return QString(); },
            [](const outcome::Refused &r) { return rejection(r); },
            [](const outcome::TimedOut &t) {
                return tr("The device did not answer %1 (sent %2 times, %3 ms apart).")
                    .arg(commandName(t.step), number(t.attempts), number(t.intervalMs));
            },
            [](const outcome::Cut &c) {
                switch (c.why) {
                case outcome::Cut::Why::Disconnected:
                    return tr("The session was disconnected before the device answered.");
                case outcome::Cut::Why::ConnectionLost:
                    return tr("The connection was lost before the device answered.");
                case outcome::Cut::Why::DetectionFailed:
                    break;
                }
                return tr("Not connected to a device.");
            },
            [](const outcome::NotConnected &) { return tr("Not connected to a device."); },
            [](const outcome::Unsupported &u) { return unsupported(u); },
            [&o](const outcome::Invalid &i) { return invalid(o.request, i); },
            [](const outcome::QueueFull &q) {
                return tr("Too many commands are waiting (%1); this one was not sent.")
                    .arg(number(q.limit));
            },
        },
        o.result);
    const QString applied = appliedBeforeFailure(o);
    return applied.isEmpty() ? failure : failure + u' ' + applied;
}

QString SessionWording::commandFailureBrief(const Outcome &o)
{
    QString brief = std::visit(
        Overloaded{
            [](const outcome::Done &) { return QString(); },
            [](const outcome::Refused &r) {
                const bool effects = isEffectCommand(r.step);
                const bool passivity = isPassivityCommand(r.step);
                QString reason = v2::ackStatusName(r.status);
                const QString name = QString::fromLatin1(r.fieldName());
                if (!name.isEmpty() && !reason.contains(name))
                    reason += u" (" + name + u')';
                if (passivity)
                    return tr("device rejected the passivity settings: %1").arg(reason);
                return effects ? tr("device rejected the effects: %1").arg(reason)
                               : tr("device rejected: %1").arg(reason);
            },
            [](const outcome::TimedOut &) { return tr("timeout: the device did not answer"); },
            [](const outcome::Cut &) { return tr("push failed: not connected to the device"); },
            [](const outcome::NotConnected &) {
                return tr("push failed: not connected to the device");
            },
            [](const outcome::Unsupported &u) {
                if (isPassivityCommand(u.step))
                    return tr("push failed: this device has no passivity controller");
                return isEffectCommand(u.step)
                           ? tr("push failed: this device cannot render effects")
                           : tr("push failed: the device's protocol cannot carry parameters");
            },
            [](const outcome::Invalid &i) {
                return i.problems.isEmpty() ? tr("push failed: the command was not sent")
                                            : tr("push failed: %1").arg(joined(i.problems));
            },
            [](const outcome::QueueFull &) { return tr("push failed: the command was not sent"); },
        },
        o.result);
    if (const outcome::Stopped *stop = o.stopped()) {
        QStringList parts;
        if (stop->applied.params)
            parts << tr("parameters");
        if (stop->applied.effects)
            parts << tr("effects");
        if (stop->applied.passivity)
            parts << tr("passivity settings");
        if (!parts.isEmpty())
            brief += tr("; %1 applied").arg(parts.join(tr(" and ")));
    }
    return brief;
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
