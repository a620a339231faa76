#include "commandqueue.h"

#include "protocol/v2codec.h"

#include <QLoggingCategory>
#include <QStringBuilder>

#include <algorithm>

Q_LOGGING_CATEGORY(lcCommands, "hatpic.device.commands", QtWarningMsg)

namespace hatpic {

namespace {

using Status = CommandResult::Status;
using Reason = CommandResult::Reason;

//! The frame of `cmd`'s step in flight.
QByteArray encode(const Command &cmd)
{
    switch (cmd.stepKind()) {
    case CommandKind::Hello:
        // Led by a delimiter, as in detection: junk already on the line cannot spoil it.
        return QByteArray(1, '\0') + v2::encodeFrame(cmd.seq, v2::Hello{});
    case CommandKind::GetParams:
        return v2::encodeFrame(cmd.seq, v2::GetParams{});
    case CommandKind::SetParams:
        return v2::encodeFrame(cmd.seq, v2::SetParams{cmd.tuning.params.value_or(DeviceParams{})});
    case CommandKind::SetStream:
        return v2::encodeFrame(cmd.seq, v2::SetStream{cmd.rate});
    case CommandKind::Zero:
        return v2::encodeFrame(cmd.seq, v2::Zero{});
    case CommandKind::SaveParams:
        return v2::encodeFrame(cmd.seq, v2::SaveParams{});
    case CommandKind::SetEffects:
        return v2::encodeFrame(cmd.seq,
                               v2::SetEffects{cmd.tuning.effects.value_or(EffectParams{})});
    case CommandKind::GetEffects:
        return v2::encodeFrame(cmd.seq, v2::GetEffects{});
    case CommandKind::SetPassivity:
        return v2::encodeFrame(cmd.seq,
                               v2::SetPassivity{cmd.tuning.passivity.value_or(PassivityParams{})});
    case CommandKind::GetPassivity:
        return v2::encodeFrame(cmd.seq, v2::GetPassivity{});
    case CommandKind::Vibrate:
        return v2::encodeFrame(cmd.seq, v2::Vibrate{static_cast<float>(cmd.vibration.amplitude),
                                                    static_cast<float>(cmd.vibration.frequency),
                                                    static_cast<float>(cmd.vibration.duration)});
    default: // not a command
        return {};
    }
}

//! The wire steps of `cmd`: a push sends each part it carries and reads it back, a read reads
//! the parameters and the effects when it names them, ZERO reads the new θ0 back.
std::vector<CommandKind> stepsOf(const Command &cmd)
{
    const bool params = cmd.tuning.params.has_value();
    const bool effects = cmd.tuning.effects.has_value();
    const bool passivity = cmd.tuning.passivity.has_value();
    switch (cmd.kind) {
    case CommandKind::SetParams:
    case CommandKind::SetEffects:
    case CommandKind::SetPassivity: {
        std::vector<CommandKind> steps;
        if (params)
            steps.insert(steps.end(), {CommandKind::SetParams, CommandKind::GetParams});
        if (effects)
            steps.insert(steps.end(), {CommandKind::SetEffects, CommandKind::GetEffects});
        if (passivity)
            steps.insert(steps.end(), {CommandKind::SetPassivity, CommandKind::GetPassivity});
        return steps;
    }
    case CommandKind::GetParams: { // the parameters, and the other blocks it names
        std::vector<CommandKind> steps{CommandKind::GetParams};
        if (effects)
            steps.push_back(CommandKind::GetEffects);
        if (passivity)
            steps.push_back(CommandKind::GetPassivity);
        return steps;
    }
    case CommandKind::Zero:
        return {CommandKind::Zero, CommandKind::GetParams};
    default:
        return {cmd.kind};
    }
}

//! True for the steps that change what the device holds (a read-back follows them).
bool changes(CommandKind step)
{
    return step == CommandKind::SetParams || step == CommandKind::SetEffects ||
           step == CommandKind::SetPassivity || step == CommandKind::Zero;
}

//! Fields of the block a step carries: an ACK's `field` beyond them names nothing.
int fieldCount(CommandKind kind)
{
    switch (kind) {
    case CommandKind::SetParams:
        return DeviceParams::kFieldCount;
    case CommandKind::SetEffects:
        return EffectParams::kFieldCount;
    case CommandKind::SetPassivity:
        return PassivityParams::kFieldCount;
    case CommandKind::Vibrate:
        return 3; // a, f, d
    default:
        return 0;
    }
}

//! A result of `status` for `cmd` (its step `kind`) carrying what it sent and read.
CommandResult resultFor(const Command &cmd, CommandKind kind, Status status,
                        Reason reason = Reason::None)
{
    CommandResult r = commandResult(kind, status, reason);
    // Only a push sends a tuning; a read's `tuning` merely names the parts it reads.
    if (cmd.kind == CommandKind::SetParams || cmd.kind == CommandKind::SetEffects ||
        cmd.kind == CommandKind::SetPassivity)
        r.sent = cmd.tuning;
    r.received = cmd.received;
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
    command.steps = stepsOf(command);
    m_queue.push_back(std::move(command));
    pump();
}

void CommandQueue::pump()
{
    if (m_inflight || m_queue.empty() || !m_write)
        return;
    m_inflight = std::move(m_queue.front());
    m_queue.pop_front();
    if (m_inflight->steps.empty())
        finishInflight(resultFor(*m_inflight, m_inflight->kind, Status::Ok)); // nothing to do
    else
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
    if (cmd.stepKind() == CommandKind::Hello) {
        m_inflight.reset();
        Q_EMIT helloUnanswered();
        return;
    }
    if (cmd.step > 0 && changes(cmd.steps[cmd.step - 1])) {
        // The device acknowledged the change; only its read-back went unanswered.
        cmd.readBackUnanswered = true;
        nextStep();
        return;
    }
    CommandResult r = resultFor(cmd, cmd.stepKind(), Status::Timeout);
    r.attempts = kCommandRetries + 1;
    r.intervalMs = kCommandTimeoutMs;
    finishInflight(r);
}

void CommandQueue::onAck(const v2::Ack &ack)
{
    if (!m_inflight || m_inflight->wire.isEmpty() || ack.ackedSeq != m_inflight->seq)
        return; // a late answer to a retry, or to nothing of ours
    const CommandKind step = m_inflight->stepKind();
    switch (step) {
    case CommandKind::Hello:
    case CommandKind::GetParams:
    case CommandKind::GetEffects:
    case CommandKind::GetPassivity:
        // HELLO, GET_PARAMS, GET_EFFECTS and GET_PASSIVITY are answered by their reply, not an ACK;
        // an ACK here is a refusal (UNKNOWN_TYPE, BAD_LENGTH, …).
        if (ack.status == v2::AckStatus::Ok)
            return;
        break;
    default:
        break;
    }
    m_timer.stop();

    if (ack.status != v2::AckStatus::Ok) {
        CommandResult r = resultFor(*m_inflight, step, Status::Rejected);
        r.ackStatus = ack.status;
        if (ack.field != v2::kNoField && ack.field < fieldCount(step))
            r.field = ack.field;
        finishInflight(r);
        return;
    }
    if (step != CommandKind::SaveParams)
        Q_EMIT acknowledged(*m_inflight);
    nextStep();
}

void CommandQueue::onTuning(const DeviceTuning &told)
{
    if (!m_inflight)
        return;
    Command &cmd = *m_inflight;
    const CommandKind step = cmd.stepKind();
    const bool afterChange = cmd.step > 0 && changes(cmd.steps[cmd.step - 1]);
    if (step == CommandKind::GetParams && told.params) {
        cmd.received.params = told.params;
        // ZERO changes θ0 by design: its read-back is the new value, not a comparison.
        if (afterChange && cmd.steps[cmd.step - 1] == CommandKind::SetParams)
            cmd.readBackMatches &= sameOnWire(*cmd.tuning.params, *told.params);
    } else if (step == CommandKind::GetEffects && told.effects) {
        cmd.received.effects = told.effects;
        if (afterChange)
            cmd.readBackMatches &= sameOnWire(*cmd.tuning.effects, *told.effects);
    } else if (step == CommandKind::GetPassivity && told.passivity) {
        cmd.received.passivity = told.passivity;
        if (afterChange)
            cmd.readBackMatches &= sameOnWire(*cmd.tuning.passivity, *told.passivity);
    } else {
        return;
    }
    m_timer.stop();
    nextStep();
}

void CommandQueue::nextStep()
{
    Command &cmd = *m_inflight;
    if (++cmd.step < cmd.steps.size()) {
        cmd.retries = 0;
        sendInflight();
        return;
    }
    CommandResult r = resultFor(cmd, cmd.kind, Status::Ok,
                                cmd.readBackUnanswered ? Reason::ReadBackUnanswered : Reason::None);
    r.readBack =
        !cmd.readBackUnanswered && std::any_of(cmd.steps.begin(), cmd.steps.end(), changes);
    r.readBackMatches = r.readBack && cmd.readBackMatches;
    finishInflight(r);
}

void CommandQueue::onHelloReply()
{
    if (m_inflight && m_inflight->stepKind() == CommandKind::Hello) {
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
    // Each result names the step it stopped at and carries what was sent and read, so a push
    // that the loss cut after SET_PARAMS says what it had changed (appliedBeforeFailure()).
    for (const Command &c : failing)
        Q_EMIT finished(c, resultFor(c, c.stepKind(), Status::NotConnected, reason));
}

} // namespace hatpic
