// The v2 command channel: one command in flight, a bounded queue behind it, resends on a
// timeout (same bytes, same seq, so the device answers a retry without applying it twice), and
// the answers matched to the command in flight. A command is a request and the wire steps it
// takes (wireSteps()). It finishes once, with its Outcome: what it sent and what it read.
//
// Writes through a function it is given; knows nothing of links, drivers or the session.
#pragma once

#include "model/params.h"
#include "protocol/messages.h"
#include "session/request.h"

#include <QByteArray>
#include <QObject>
#include <QTimer>

#include <deque>
#include <functional>
#include <optional>
#include <vector>

namespace hatpic {

struct Command
{
    Command() = default;
    Command(std::optional<Request> request, std::vector<WireStep> steps, OutcomeHandler then)
        : request(std::move(request)), steps(std::move(steps)), then(std::move(then))
    {}

    //! What was asked; none for detection's HELLO, which ends in helloUnanswered() or nothing.
    std::optional<Request> request;
    std::vector<WireStep> steps; //!< the wire steps, in order (wireSteps())
    OutcomeHandler then; //!< hears the outcome; empty: the session's own (the connect sequence)

    // Set by the queue as the command goes.
    std::size_t step = 0;         //!< the one in flight
    DeviceTuning received;        //!< what the GET steps read so far
    bool readBackDiffers = false; //!< a read-back so far differs from what its step sent
    bool readBackUnanswered = false;
    quint8 seq = 0;
    int retries = 0;
    QByteArray wire;

    CommandKind stepKind() const { return steps.at(step).kind(); }
    //! The message of the step in flight, which carries what it applies.
    const v2::Message &stepMessage() const { return steps.at(step).message; }
    //! The knob the request is about (knobOf()); 0 for detection's HELLO.
    Knob knob() const;
    //! The push's tuning (float32-rounded), or null.
    const DeviceTuning *pushed() const;
};

class CommandQueue : public QObject
{
    Q_OBJECT
public:
    static constexpr int kCommandTimeoutMs = 250; //!< resend a command after this [ms]
    static constexpr int kCommandRetries = 3;     //!< resends before Timeout
    static constexpr int kMaxQueuedCommands = 16; //!< commands waiting behind the one in flight

    using Writer = std::function<void(const QByteArray &bytes)>;

    explicit CommandQueue(QObject *parent = nullptr);

    //! Where frames go; an empty writer means no link (commands wait in the queue).
    void setWriter(Writer writer);
    //! Queues `command`; a full queue finishes it at once (QueueFull).
    void enqueue(Command command);
    //! Queues detection's HELLO.
    void enqueueHello();
    //! A command waits for its answer (no PING may go out in between).
    bool busy() const { return m_inflight.has_value(); }

    //! The seq of the next frame sent; shared by commands, PINGs and detection's HELLO.
    quint8 nextSeq() { return m_seq++; }
    quint8 peekSeq() const { return m_seq; }
    void setNextSeq(quint8 seq) { m_seq = seq; }

    //! An ACK arrived: finishes, reads back or ignores (late answers) the command in flight.
    void onAck(const v2::Ack &ack);
    //! A PARAMS, EFFECTS or PASSIVITY of `knob` arrived (`told` has the part it carried):
    //! answers the GET_PARAMS, GET_EFFECTS or GET_PASSIVITY step in flight for that knob.
    void onTuning(const DeviceTuning &told, Knob knob = 0);
    //! HELLO_REPLY arrived: a HELLO in flight is answered (detection handles the reply).
    void onHelloReply();
    //! Finishes every command (in flight and queued) as cut short, for `why`.
    void failAll(outcome::Cut::Why why);

Q_SIGNALS:
    //! A command ended (its `then` is the listener's to call).
    void finished(const hatpic::Command &command, const hatpic::Outcome &outcome);
    //! The device acknowledged `command`'s step in flight (stepKind(): SET_PARAMS, ZERO,
    //! SET_EFFECTS, SET_PASSIVITY before their read-back, SET_STREAM and VIBRATE before
    //! finished()).
    void acknowledged(const hatpic::Command &command);
    //! A command frame was sent again.
    void retried();
    //! HELLO went unanswered after every resend.
    void helloUnanswered();

private:
    void pump();
    void sendInflight();
    void onTimeout();
    void finishInflight(Outcome::Result result);
    //! `cmd`'s outcome: `result`, its request and what it read.
    static Outcome outcomeOf(const Command &cmd, Outcome::Result result);
    //! A failure at `cmd`'s step in flight: what it had applied before it.
    static outcome::Stopped stoppedAt(const Command &cmd);
    //! The step in flight is done: the next one goes out, or the command finishes.
    void nextStep();

    Writer m_write;
    QTimer m_timer;
    std::optional<Command> m_inflight;
    std::deque<Command> m_queue;
    quint8 m_seq = 0;
};

} // namespace hatpic
