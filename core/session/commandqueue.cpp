#include "commandqueue.h"

#include "model/overloaded.h"
#include "protocol/v2codec.h"

#include <QLoggingCategory>
#include <QStringBuilder>

#include <algorithm>

Q_LOGGING_CATEGORY(lcCommands, "hatpic.device.commands", QtWarningMsg)

namespace hatpic {

namespace {

//! The frame of `cmd`'s step in flight.
QByteArray encode(const Command &cmd)
{
    const WireStep &step = cmd.steps.at(cmd.step);
    // HELLO is led by a delimiter, as in detection: junk already on the line cannot spoil it.
    const QByteArray lead = step.kind() == CommandKind::Hello ? QByteArray(1, '\0') : QByteArray();
    return lead + v2::encodeFrame(cmd.seq, step.message);
}

//! True for the steps that change what the device holds (a read-back follows them).
bool changes(CommandKind step)
{
    return step == CommandKind::SetParams || step == CommandKind::SetEffects ||
           step == CommandKind::SetPassivity || step == CommandKind::Zero;
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
    // Each SET before the step in flight was acknowledged: its part is in force, as read back
    // where that came, else as its message carried it.
    const DeviceTuning &back = cmd.received;
    DeviceTuning &applied = stop.applied;
    for (std::size_t i = 0; i < cmd.step; ++i) {
        std::visit(Overloaded{
                       [&](const v2::SetParams &m) {
                           applied.params = back.params ? back.params : m.params;
                       },
                       [&](const v2::SetEffects &m) {
                           applied.effects = back.effects ? back.effects : m.effects;
                       },
                       [&](const v2::SetPassivity &m) {
                           applied.passivity = back.passivity ? back.passivity : m.passivity;
                       },
                       [](const auto &) {},
                   },
                   cmd.steps[i].message);
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
    hello.steps = {WireStep{v2::Hello{}}};
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
    if (cmd.step > 0 && changes(cmd.steps[cmd.step - 1].kind())) {
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
        // A field past the step's block (0xFE: a knob the device lacks) names nothing.
        outcome::Refused refused{stoppedAt(*m_inflight), ack.status, int(ack.field)};
        if (ack.field == v2::kNoField || refused.fieldName().empty())
            refused.field = -1;
        finishInflight(std::move(refused));
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
    const bool changed = std::any_of(cmd.steps.begin(), cmd.steps.end(),
                                     [](const WireStep &s) { return changes(s.kind()); });
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
