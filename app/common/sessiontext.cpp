#include "common/sessiontext.h"

#include <QLoggingCategory>
#include <QStringBuilder>

namespace hatpic::cli {

namespace {

QString number(qint64 n)
{
    return QString::number(n);
}

} // namespace

QString portDescription(const StateDetail &detail)
{
    if (detail.simulated())
        return QStringLiteral("the simulated joystick");
    return detail.port % u" at " % number(detail.baud) % u" baud";
}

QString stateDetailText(const StateDetail &d)
{
    using Kind = StateDetail::Kind;
    const QString port = portDescription(d);
    switch (d.kind) {
    case Kind::None:
        return {};
    case Kind::Opening:
        return u"Opening " % port;
    case Kind::OpenFailed:
        return u"Cannot open " % port % u": " % d.error;
    case Kind::UsingLegacy:
        return u"Using the legacy protocol on " % port;
    case Kind::AskingHello:
        return u"Asking for HELLO on " % port;
    case Kind::Listening:
        return u"Listening for a legacy device on " % port;
    case Kind::SendingHello:
        return u"Sending HELLO on " % port;
    case Kind::BaudSwitchFailed:
        return u"Cannot switch " % d.port % u" to " % number(d.targetBaud) % u" baud: " % d.error;
    case Kind::NoAnswer: {
        const QString listenBaud =
            d.listenBaud > 0 ? u" at " % number(d.listenBaud) % u" baud" : QString();
        return u"No HATPIC answered on " % port % u": listened " % number(d.listenMs) % u" ms" %
               listenBaud % u" for legacy frames (got " % number(d.legacyFrames) % u" valid, " %
               number(d.legacyFramesNeeded) % u" needed), then sent HELLO and got no " %
               u"HELLO_REPLY within " % number(d.helloWaitMs) % u" ms.";
    }
    case Kind::NoHelloReply:
        return u"No HATPIC v2 device answered on " % port % u": HELLO sent " % number(d.attempts) %
               u" times, " % number(d.intervalMs) % u" ms apart, without a HELLO_REPLY.";
    case Kind::Refused:
        return u"Refused the device on " % port % u": " % d.error %
               u". It does not behave as a HATPIC joystick; nothing was sent to it.";
    case Kind::ConnectedV2:
        return u"HATPIC v2 \"" % d.firmware % u"\" on " % port;
    case Kind::ConnectedLegacy:
        return u"Legacy HATPIC on " % port;
    case Kind::LinkFailed:
        return u"Lost " % port % u": " % d.error;
    case Kind::Silent:
        return u"Lost " % port % u": no data from the device for " %
               QString::number(d.silenceMs / 1000.0) % u" s";
    }
    return {};
}

QString commandFailureText(const CommandResult &r)
{
    using Status = CommandResult::Status;
    using Reason = CommandResult::Reason;
    const QString name = commandName(r.command);
    switch (r.status) {
    case Status::Ok:
        return {};
    case Status::Rejected: {
        const QString status = v2::ackStatusName(r.ackStatus);
        if (r.field >= 0 && r.command == CommandKind::SetEffects) {
            return u"The device rejected " % QString::fromLatin1(effectFieldName(r.field)) %
                   u" (field " % number(r.field) % u"): " % status %
                   u"; its effects are unchanged.";
        }
        if (r.field >= 0 && r.command == CommandKind::Vibrate) {
            return u"The device rejected VIBRATE (field " % number(r.field) % u"): " % status %
                   u'.';
        }
        if (r.field >= 0) {
            return u"The device rejected " % QString::fromLatin1(deviceFieldName(r.field)) %
                   u" (field " % number(r.field) % u"): " % status %
                   u"; its parameters are unchanged.";
        }
        return u"The device rejected " % name % u": " % status % u'.';
    }
    case Status::Timeout:
        return u"The device did not answer " % name % u" (sent " % number(r.attempts) %
               u" times, " % number(r.intervalMs) % u" ms apart).";
    case Status::NotConnected:
        switch (r.reason) {
        case Reason::Disconnected:
            return QStringLiteral("The session was disconnected before the device answered.");
        case Reason::ConnectionLost:
            return QStringLiteral("The connection was lost before the device answered.");
        default:
            return QStringLiteral("Not connected to a device.");
        }
    case Status::Unsupported:
        if (r.reason == Reason::NoEffects)
            return name % u" is not available: the device runs the published firmware (legacy "
                          u"protocol), which cannot render effects.";
        if (r.reason == Reason::NoEffectsCapability)
            return name % u" is not available: this device's firmware does not announce the "
                          u"effects capability, so it cannot render effects.";
        return name %
               u" is not available: the device runs the published firmware (legacy protocol), " %
               (r.reason == Reason::FixedRate
                    ? QStringLiteral("which streams at its own fixed rate of about 5 Hz.")
                    : QStringLiteral("which cannot send or take parameters. Host settings still "
                                     "apply."));
    case Status::Invalid:
        if (r.reason == Reason::QueueFull)
            return u"Too many commands are waiting (" % number(r.limit) % u"); " % name %
                   u" was not sent.";
        if (r.command == CommandKind::Vibrate)
            return u"The vibration cue is not valid: " % r.problems.join(QStringLiteral("; ")) %
                   u"; nothing was sent.";
        if (r.command == CommandKind::SetEffects)
            return u"The effects are not valid: " % r.problems.join(QStringLiteral("; ")) %
                   u"; nothing was sent.";
        return u"The parameters are not valid: " % r.problems.join(QStringLiteral("; ")) % u'.';
    }
    return {};
}

QString noticeText(const SessionNotice &notice)
{
    switch (notice.kind) {
    case SessionNotice::Kind::RecordingNeedsDevice:
        return QStringLiteral("Not connected: a recording starts once a device is connected.");
    case SessionNotice::Kind::RecordingClosedByLoss:
        return QStringLiteral("Recording closed: the device was lost.");
    case SessionNotice::Kind::RecordingWaitsForDevice:
        return QStringLiteral("The device was lost while recording: the recording goes on in "
                              "the same file when the device is back.");
    case SessionNotice::Kind::RecordingResumed:
        return QStringLiteral("The device is back: recording resumed; the gap is marked in the "
                              "file.");
    case SessionNotice::Kind::RecordingClosedOtherDevice:
        return u"Recording ended at the link loss: a different device answered (" %
               notice.problems.join(QStringLiteral("; ")) % u").";
    case SessionNotice::Kind::HostParamsRefused:
        return u"Host parameters refused: " % notice.problems.join(QStringLiteral("; "));
    }
    return {};
}

void silenceLibraryLog()
{
    QLoggingCategory::setFilterRules(QStringLiteral("hatpic.*=false"));
}

} // namespace hatpic::cli
