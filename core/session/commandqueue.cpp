#include "commandqueue.h"

#include "protocol/v2codec.h"
#include "telemetry/numbertext.h"

#include <QLoggingCategory>
#include <QStringBuilder>

Q_LOGGING_CATEGORY(lcCommands, "hatpic.device.commands", QtWarningMsg)

namespace hatpic {

namespace {

CommandResult result(CommandResult::Status status, const QString &message)
{
    CommandResult r;
    r.status = status;
    r.message = message;
    return r;
}

QByteArray encode(const Command &cmd)
{
    switch (cmd.kind) {
    case CommandKind::Hello:
        // Led by a delimiter, as in detection: junk already on the line cannot spoil it.
        return QByteArray(1, '\0') + v2::encodeFrame(cmd.seq, v2::Hello{});
    case CommandKind::GetParams:
        return v2::encodeFrame(cmd.seq, v2::GetParams{});
    case CommandKind::SetParams:
        return v2::encodeFrame(cmd.seq, v2::SetParams{cmd.params});
    case CommandKind::SetStream:
        return v2::encodeFrame(cmd.seq, v2::SetStream{cmd.rate});
    case CommandKind::Zero:
        return v2::encodeFrame(cmd.seq, v2::Zero{});
    case CommandKind::SaveParams:
        return v2::encodeFrame(cmd.seq, v2::SaveParams{});
    }
    return {};
}

} // namespace

CommandQueue::CommandQueue(QObject *parent) : QObject(parent), m_timer(this)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(kCommandTimeoutMs);
    connect(&m_timer, &QTimer::timeout, this, &CommandQueue::onTimeout);
}

void CommandQueue::setWriter(Writer writer)
{
    m_write = std::move(writer);
    if (!m_write)
        m_timer.stop();
    pump();
}

void CommandQueue::enqueue(Command command)
{
    if (static_cast<int>(m_queue.size()) >= kMaxQueuedCommands) {
        Q_EMIT finished(command, result(CommandResult::Status::Invalid,
                                        u"Too many commands are waiting (" %
                                            QString::number(kMaxQueuedCommands) % u"); " %
                                            commandName(command.kind) % u" was not sent."));
        return;
    }
    m_queue.push_back(std::move(command));
    pump();
}

void CommandQueue::pump()
{
    if (m_inflight || m_queue.empty() || !m_write)
        return;
    m_inflight = std::move(m_queue.front());
    m_queue.pop_front();
    sendInflight();
}

void CommandQueue::sendInflight()
{
    Command &cmd = *m_inflight;
    cmd.seq = nextSeq();
    cmd.wire = encode(cmd);
    m_timer.start(); // before writing: a write may fail the link, which stops the timer
    m_write(cmd.wire);
}

void CommandQueue::onTimeout()
{
    if (!m_inflight || !m_write)
        return;
    Command &cmd = *m_inflight;
    if (cmd.retries < kCommandRetries) {
        // Same bytes, same seq: a device that did answer the first copy answers again
        // without applying it twice.
        ++cmd.retries;
        Q_EMIT retried();
        m_timer.start();
        m_write(cmd.wire);
        return;
    }
    const QString name = cmd.readBack ? commandName(cmd.origin) : commandName(cmd.kind);
    if (cmd.kind == CommandKind::Hello) {
        m_inflight.reset();
        Q_EMIT helloUnanswered();
        return;
    }
    if (cmd.readBack) {
        // The device acknowledged the command; only its read-back went unanswered.
        finishInflight(result(CommandResult::Status::Ok,
                              u"The device acknowledged " % name %
                                  u", but did not answer the GET_PARAMS read-back."));
        return;
    }
    finishInflight(result(CommandResult::Status::Timeout,
                          u"The device did not answer " % name % u" (sent " %
                              QString::number(kCommandRetries + 1) % u" times, " %
                              QString::number(kCommandTimeoutMs) % u" ms apart)."));
}

void CommandQueue::onAck(const v2::Ack &ack)
{
    if (!m_inflight || m_inflight->wire.isEmpty() || ack.ackedSeq != m_inflight->seq)
        return; // a late answer to a retry, or to nothing of ours
    switch (m_inflight->kind) {
    case CommandKind::Hello:
    case CommandKind::GetParams:
        // HELLO and GET_PARAMS are answered by their reply, not an ACK; an ACK here is a
        // refusal (UNKNOWN_TYPE, BAD_LENGTH, …).
        if (ack.status == v2::AckStatus::Ok)
            return;
        break;
    default:
        break;
    }
    m_timer.stop();

    if (ack.status != v2::AckStatus::Ok) {
        CommandResult r;
        r.status = CommandResult::Status::Rejected;
        r.ackStatus = ack.status;
        const QString status = v2::ackStatusName(ack.status);
        if (ack.field != v2::kNoField && ack.field < DeviceParams::kFieldCount) {
            r.field = ack.field;
            r.message = u"The device rejected " % QString::fromLatin1(deviceFieldName(ack.field)) %
                        u" (field " % QString::number(ack.field) % u"): " % status %
                        u"; its parameters are unchanged.";
        } else {
            r.message =
                u"The device rejected " % commandName(m_inflight->kind) % u": " % status % u'.';
        }
        finishInflight(r);
        return;
    }

    Command &cmd = *m_inflight;
    switch (cmd.kind) {
    case CommandKind::SetParams:
    case CommandKind::Zero:
        Q_EMIT acknowledged(cmd);
        // Read back what the device now holds, under the same request id.
        cmd.origin = cmd.kind;
        cmd.kind = CommandKind::GetParams;
        cmd.readBack = true;
        cmd.retries = 0;
        sendInflight();
        return;
    case CommandKind::SetStream:
        Q_EMIT acknowledged(cmd);
        finishInflight(result(CommandResult::Status::Ok,
                              cmd.rate ? u"Telemetry requested at " % QString::number(cmd.rate) %
                                             u" Hz (the device may clamp it)."
                                       : QStringLiteral("Telemetry stopped.")));
        return;
    case CommandKind::SaveParams:
        finishInflight(
            result(CommandResult::Status::Ok, QStringLiteral("The device saved its parameters.")));
        return;
    case CommandKind::Hello:
    case CommandKind::GetParams:
        return;
    }
}

void CommandQueue::onParams(const DeviceParams &params)
{
    if (!m_inflight || m_inflight->kind != CommandKind::GetParams)
        return;
    m_timer.stop();
    CommandResult r;
    if (!m_inflight->readBack) {
        r.message = QStringLiteral("Parameters read from the device.");
    } else if (m_inflight->origin == CommandKind::Zero) {
        r.readBack = true;
        r.readBackMatches = true;
        r.message =
            u"The device zeroed: theta0 is now " % compactNumberText(params.theta0) % u" rad.";
    } else {
        r.readBack = true;
        r.readBackMatches = sameOnWire(m_inflight->params, params);
        if (r.readBackMatches) {
            r.message = QStringLiteral("The device applied the parameters; the read-back matches.");
        } else {
            r.message = u"The device acknowledged the parameters, but the read-back differs: " %
                        describeParamChange(m_inflight->params, params) % u" (sent → read).";
        }
    }
    finishInflight(r);
}

void CommandQueue::onHelloReply()
{
    if (m_inflight && m_inflight->kind == CommandKind::Hello) {
        m_timer.stop();
        m_inflight.reset();
    }
}

void CommandQueue::finishInflight(const CommandResult &r)
{
    m_timer.stop();
    const Command done = std::move(*m_inflight);
    m_inflight.reset();
    if (!done.id && !r.ok())
        qCWarning(lcCommands) << commandName(done.kind) << "during connect:" << r.message;
    Q_EMIT finished(done, r);
    pump();
}

void CommandQueue::failAll(const QString &message)
{
    m_timer.stop();
    std::deque<Command> failing;
    if (m_inflight)
        failing.push_back(std::move(*m_inflight));
    m_inflight.reset();
    for (Command &c : m_queue)
        failing.push_back(std::move(c));
    m_queue.clear();
    for (const Command &c : failing)
        Q_EMIT finished(c, result(CommandResult::Status::NotConnected, message));
}

} // namespace hatpic
