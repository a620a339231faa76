#include "connection/sessiontext.h"

namespace hatpic {

QString SessionText::port(const StateDetail &detail)
{
    if (detail.simulated())
        return tr("the simulated joystick");
    return tr("%1 at %2 baud").arg(detail.port, QString::number(detail.baud));
}

QString SessionText::stateDetail(const StateDetail &d)
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
        return tr("Cannot switch %1 to %2 baud: %3")
            .arg(d.port, QString::number(d.targetBaud), d.error);
    case Kind::NoAnswer: {
        const QString heard =
            tr("got %1 valid, %2 needed")
                .arg(QString::number(d.legacyFrames), QString::number(d.legacyFramesNeeded));
        if (d.listenBaud > 0) {
            return tr("No HATPIC answered on %1: listened %2 ms at %3 baud for legacy frames (%4), "
                      "then sent HELLO and got no HELLO_REPLY within %5 ms.")
                .arg(port(d), QString::number(d.listenMs), QString::number(d.listenBaud), heard,
                     QString::number(d.helloWaitMs));
        }
        return tr("No HATPIC answered on %1: listened %2 ms for legacy frames (%3), then sent "
                  "HELLO and got no HELLO_REPLY within %4 ms.")
            .arg(port(d), QString::number(d.listenMs), heard, QString::number(d.helloWaitMs));
    }
    case Kind::NoHelloReply:
        return tr("No HATPIC v2 device answered on %1: HELLO sent %2 times, %3 ms apart, without "
                  "a HELLO_REPLY.")
            .arg(port(d), QString::number(d.attempts), QString::number(d.intervalMs));
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

QString SessionText::notice(const SessionNotice &notice)
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
            .arg(notice.problems.join(u"; "));
    case SessionNotice::Kind::HostParamsRefused:
        return tr("Host parameters refused: %1").arg(notice.problems.join(u"; "));
    }
    return {};
}

} // namespace hatpic
