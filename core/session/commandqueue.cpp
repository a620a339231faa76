#include "commandqueue.h"

#include "protocol/v2codec.h"

#include <QLoggingCategory>
#include <QStringBuilder>

Q_LOGGING_CATEGORY(lcCommands, "hatpic.device.commands", QtWarningMsg)

namespace hatpic {

namespace {

using Status = CommandResult::Status;
using Reason = CommandResult::Reason;

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
    case CommandKind::SetEffects:
        return v2::encodeFrame(cmd.seq, v2::SetEffects{cmd.effects});
    case CommandKind::GetEffects:
        return v2::encodeFrame(cmd.seq, v2::GetEffects{});
    case CommandKind::Vibrate:
        return v2::encodeFrame(cmd.seq, v2::Vibrate{static_cast<float>(cmd.vibration.amplitude),
                                                    static_cast<float>(cmd.vibration.frequency),
                                                    static_cast<float>(cmd.vibration.duration)});
    }
    return {};
}

//! Fields of the block a command carries: an ACK's `field` beyond them names nothing.
int fieldCount(CommandKind kind)
{
    switch (kind) {
    case CommandKind::SetParams:
        return DeviceParams::kFieldCount;
    case CommandKind::SetEffects:
        return EffectParams::kFieldCount;
    case CommandKind::Vibrate:
        return 3; // a, f, d
    default:
        return 0;
    }
}

//! The read-back that follows an acknowledged `kind`, if any.
std::optional<CommandKind> readBackOf(CommandKind kind)
{
    switch (kind) {
    case CommandKind::SetParams:
    case CommandKind::Zero:
        return CommandKind::GetParams;
    case CommandKind::SetEffects:
        return CommandKind::GetEffects;
    default:
        return std::nullopt;
    }
}

//! A result for `cmd` carrying what it sent.
CommandResult resultFor(const Command &cmd, CommandKind kind, Status status,
                        Reason reason = Reason::None)
{
    CommandResult r = commandResult(kind, status, reason);
    r.sent = cmd.params;
    r.effectsSent = cmd.effects;
    r.vibration = cmd.vibration;
    r.rate = cmd.rate;
    return r;
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
        CommandResult r = commandResult(command.kind, Status::Invalid, Reason::QueueFull);
        r.limit = kMaxQueuedCommands;
        Q_EMIT finished(command, r);
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
    if (cmd.kind == CommandKind::Hello) {
        m_inflight.reset();
        Q_EMIT helloUnanswered();
        return;
    }
    if (cmd.readBack) {
        // The device acknowledged the command; only its read-back went unanswered.
        finishInflight(resultFor(cmd, cmd.origin, Status::Ok, Reason::ReadBackUnanswered));
        return;
    }
    CommandResult r = resultFor(cmd, cmd.kind, Status::Timeout);
    r.attempts = kCommandRetries + 1;
    r.intervalMs = kCommandTimeoutMs;
    finishInflight(r);
}

void CommandQueue::onAck(const v2::Ack &ack)
{
    if (!m_inflight || m_inflight->wire.isEmpty() || ack.ackedSeq != m_inflight->seq)
        return; // a late answer to a retry, or to nothing of ours
    switch (m_inflight->kind) {
    case CommandKind::Hello:
    case CommandKind::GetParams:
    case CommandKind::GetEffects:
        // HELLO, GET_PARAMS and GET_EFFECTS are answered by their reply, not an ACK; an ACK
        // here is a refusal (UNKNOWN_TYPE, BAD_LENGTH, …).
        if (ack.status == v2::AckStatus::Ok)
            return;
        break;
    default:
        break;
    }
    m_timer.stop();

    if (ack.status != v2::AckStatus::Ok) {
        CommandResult r = resultFor(*m_inflight, m_inflight->kind, Status::Rejected);
        r.ackStatus = ack.status;
        if (ack.field != v2::kNoField && ack.field < fieldCount(m_inflight->kind))
            r.field = ack.field;
        finishInflight(r);
        return;
    }

    Command &cmd = *m_inflight;
    if (const auto readBack = readBackOf(cmd.kind)) {
        Q_EMIT acknowledged(cmd);
        // Read back what the device now holds, under the same request id.
        cmd.origin = cmd.kind;
        cmd.kind = *readBack;
        cmd.readBack = true;
        cmd.retries = 0;
        sendInflight();
        return;
    }
    switch (cmd.kind) {
    case CommandKind::SetStream:
    case CommandKind::Vibrate: {
        Q_EMIT acknowledged(cmd);
        finishInflight(resultFor(cmd, cmd.kind, Status::Ok));
        return;
    }
    case CommandKind::SaveParams:
        finishInflight(commandResult(CommandKind::SaveParams, Status::Ok));
        return;
    default: // HELLO, GET_PARAMS, GET_EFFECTS: answered above
        return;
    }
}

void CommandQueue::onParams(const DeviceParams &params)
{
    if (!m_inflight || m_inflight->kind != CommandKind::GetParams)
        return;
    m_timer.stop();
    const Command &cmd = *m_inflight;
    CommandResult r = commandResult(cmd.readBack ? cmd.origin : cmd.kind, Status::Ok);
    r.received = params;
    if (cmd.readBack) {
        r.readBack = true;
        r.sent = cmd.params;
        // ZERO changes θ0 by design: its read-back is the new value, not a comparison.
        r.readBackMatches = cmd.origin == CommandKind::Zero || sameOnWire(cmd.params, params);
    }
    finishInflight(r);
}

void CommandQueue::onEffects(const EffectParams &effects)
{
    if (!m_inflight || m_inflight->kind != CommandKind::GetEffects)
        return;
    m_timer.stop();
    const Command &cmd = *m_inflight;
    CommandResult r = commandResult(cmd.readBack ? cmd.origin : cmd.kind, Status::Ok);
    r.effectsReceived = effects;
    if (cmd.readBack) {
        r.readBack = true;
        r.effectsSent = cmd.effects;
        r.readBackMatches = sameOnWire(cmd.effects, effects);
    }
    finishInflight(r);
}

void CommandQueue::onHelloReply()
{
    if (m_inflight && m_inflight->kind == CommandKind::Hello) {
        m_timer.stop();
        m_inflight.reset();
        pump();
    }
}

void CommandQueue::finishInflight(const CommandResult &r)
{
    m_timer.stop();
    const Command done = std::move(*m_inflight);
    m_inflight.reset();
    if (!done.id && !r.ok())
        qCWarning(lcCommands) << commandName(done.kind) << "during connect failed, status"
                              << static_cast<int>(r.status);
    Q_EMIT finished(done, r);
    pump();
}

void CommandQueue::failAll(CommandResult::Reason reason)
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
        Q_EMIT finished(
            c, commandResult(c.readBack ? c.origin : c.kind, Status::NotConnected, reason));
}

} // namespace hatpic
