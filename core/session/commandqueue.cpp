#include "commandqueue.h"

#include "protocol/v2codec.h"

#include <QLoggingCategory>
#include <QStringBuilder>

#include <algorithm>

Q_LOGGING_CATEGORY(lcCommands, "hatpic.device.commands", QtWarningMsg)

namespace hatpic {

namespace {

// GCC 12 at -O3 warns that the byte of a disengaged optional<uint8_t> (the knob's `axis`) "may
// be used uninitialized" when the message is copied into its variant: a false positive (the
// copy of a trivially copyable optional copies its bytes; nothing reads the value).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

//! The frame of `cmd`'s step in flight.
QByteArray encode(const Command &cmd)
{
    const DeviceTuning *tuning = cmd.pushed();
    // Knob 1 goes without the field, so a single-knob device's frames are as they always were.
    const Knob knob = cmd.knob();
    const v2::AxisIndex axis = knob ? v2::AxisIndex(knob) : std::nullopt;
    switch (cmd.stepKind()) {
    case CommandKind::Hello:
        // Led by a delimiter, as in detection: junk already on the line cannot spoil it.
        return QByteArray(1, '\0') + v2::encodeFrame(cmd.seq, v2::Hello{});
    case CommandKind::GetParams:
        return v2::encodeFrame(cmd.seq, v2::GetParams{axis});
    case CommandKind::SetParams:
        return v2::encodeFrame(cmd.seq, v2::SetParams{*tuning->params, axis});
    case CommandKind::SetStream:
        return v2::encodeFrame(cmd.seq,
                               v2::SetStream{std::get<request::Stream>(*cmd.request).rateHz});
    case CommandKind::Zero:
        return v2::encodeFrame(cmd.seq, v2::Zero{axis});
    case CommandKind::SaveParams:
        return v2::encodeFrame(cmd.seq, v2::SaveParams{});
    case CommandKind::SetEffects:
        return v2::encodeFrame(cmd.seq, v2::SetEffects{*tuning->effects, axis});
    case CommandKind::GetEffects:
        return v2::encodeFrame(cmd.seq, v2::GetEffects{axis});
    case CommandKind::SetPassivity:
        return v2::encodeFrame(cmd.seq, v2::SetPassivity{*tuning->passivity, axis});
    case CommandKind::GetPassivity:
        return v2::encodeFrame(cmd.seq, v2::GetPassivity{axis});
    case CommandKind::Vibrate: {
        const Vibration &v = std::get<request::Vibrate>(*cmd.request).vibration;
        return v2::encodeFrame(cmd.seq, v2::Vibrate{static_cast<float>(v.amplitude),
                                                    static_cast<float>(v.frequency),
                                                    static_cast<float>(v.duration), axis});
    }
    default: // not a command
        return {};
    }
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

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

} // namespace

Knob Command::knob() const
{
    return request ? knobOf(*request) : 0;
}

const DeviceTuning *Command::pushed() const
{
    const auto *push = request ? std::get_if<request::Push>(&*request) : nullptr;
    return push ? &push->tuning : nullptr;
}

Outcome CommandQueue::outcomeOf(const Command &cmd, Outcome::Result result)
{
    return {cmd.request.value_or(Request{}), std::move(result), cmd.received};
}

outcome::Stopped CommandQueue::stoppedAt(const Command &cmd)
{
    outcome::Stopped stop{cmd.stepKind(), {}};
    const DeviceTuning *sent = cmd.pushed();
    if (!sent)
        return stop;
    // Each SET before the step in flight was acknowledged: its part is in force, as read back
    // where that came, else as sent.
    const auto take = [&](const auto &part, const auto &readBack, auto &out) {
        out = readBack ? readBack : part;
    };
    for (std::size_t i = 0; i < cmd.step; ++i) {
        switch (cmd.steps[i]) {
        case CommandKind::SetParams:
            take(sent->params, cmd.received.params, stop.applied.params);
            break;
        case CommandKind::SetEffects:
            take(sent->effects, cmd.received.effects, stop.applied.effects);
            break;
        case CommandKind::SetPassivity:
            take(sent->passivity, cmd.received.passivity, stop.applied.passivity);
            break;
        default:
            break;
        }
    }
    return stop;
}

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
        Q_EMIT finished(command, outcomeOf(command, outcome::QueueFull{kMaxQueuedCommands}));
        return;
    }
    m_queue.push_back(std::move(command));
    pump();
}

void CommandQueue::enqueueHello()
{
    Command hello;
    hello.steps = {CommandKind::Hello};
    enqueue(std::move(hello));
}

void CommandQueue::pump()
{
    if (m_inflight || m_queue.empty() || !m_write)
        return;
    m_inflight = std::move(m_queue.front());
    m_queue.pop_front();
    if (m_inflight->steps.empty())
        finishInflight(outcome::Done{}); // nothing to do
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
    finishInflight(outcome::TimedOut{stoppedAt(cmd), kCommandRetries + 1, kCommandTimeoutMs});
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
        const bool named = ack.field != v2::kNoField && ack.field < fieldCount(step);
        finishInflight(
            outcome::Refused{stoppedAt(*m_inflight), ack.status, named ? int(ack.field) : -1});
        return;
    }
    if (step != CommandKind::SaveParams)
        Q_EMIT acknowledged(*m_inflight);
    nextStep();
}

void CommandQueue::onTuning(const DeviceTuning &told, Knob knob)
{
    if (!m_inflight || knob != m_inflight->knob())
        return; // not the answer to the step in flight (another host's, or a stale one)
    Command &cmd = *m_inflight;
    const CommandKind step = cmd.stepKind();
    // ZERO changes θ0 by design: its read-back is the new value, not a comparison; a read
    // compares nothing.
    const DeviceTuning *sent = cmd.pushed();
    const auto readBack = [&cmd, sent](const auto &toldPart, auto &received, auto sentPart) {
        received = toldPart;
        if (sent && sent->*sentPart)
            cmd.readBackDiffers |= !sameOnWire(*(sent->*sentPart), *toldPart);
    };
    if (step == CommandKind::GetParams && told.params)
        readBack(told.params, cmd.received.params, &DeviceTuning::params);
    else if (step == CommandKind::GetEffects && told.effects)
        readBack(told.effects, cmd.received.effects, &DeviceTuning::effects);
    else if (step == CommandKind::GetPassivity && told.passivity)
        readBack(told.passivity, cmd.received.passivity, &DeviceTuning::passivity);
    else
        return;
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
    using outcome::ReadBack;
    const bool changed = std::any_of(cmd.steps.begin(), cmd.steps.end(), changes);
    finishInflight(outcome::Done{!changed                 ? ReadBack::None
                                 : cmd.readBackUnanswered ? ReadBack::Unanswered
                                 : cmd.readBackDiffers    ? ReadBack::Differs
                                                          : ReadBack::Matches});
}

void CommandQueue::onHelloReply()
{
    if (m_inflight && m_inflight->stepKind() == CommandKind::Hello) {
        m_timer.stop();
        m_inflight.reset();
        pump();
    }
}

void CommandQueue::finishInflight(Outcome::Result result)
{
    m_timer.stop();
    const Command done = std::move(*m_inflight);
    m_inflight.reset();
    const Outcome outcome = outcomeOf(done, std::move(result));
    if (!done.then && !outcome.ok())
        qCWarning(lcCommands) << commandName(done.stepKind()) << "during connect failed, outcome"
                              << outcome.result.index();
    Q_EMIT finished(done, outcome);
    pump();
}

void CommandQueue::failAll(outcome::Cut::Why why)
{
    m_timer.stop();
    std::deque<Command> failing;
    if (m_inflight)
        failing.push_back(std::move(*m_inflight));
    m_inflight.reset();
    for (Command &c : m_queue)
        failing.push_back(std::move(c));
    m_queue.clear();
    // Each outcome names the step it stopped at and what it had applied, so a push that the loss
    // cut after SET_PARAMS says what it had changed.
    for (const Command &c : failing) {
        if (c.request && !c.steps.empty())
            Q_EMIT finished(c, outcomeOf(c, outcome::Cut{stoppedAt(c), why}));
    }
}

} // namespace hatpic
