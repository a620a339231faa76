// The v2 command channel: one command in flight, a bounded queue behind it, resends on a
// timeout (same bytes, same seq, so the device answers a retry without applying it twice), and
// the answers matched to the command in flight. A command is the wire steps it takes, in order:
// a push of a tuning is SET_PARAMS, GET_PARAMS (the read-back), then SET_EFFECTS, GET_EFFECTS
// for its effect part, then SET_PASSIVITY, GET_PASSIVITY for its passivity part; a read is
// GET_PARAMS (and GET_EFFECTS, GET_PASSIVITY); ZERO is ZERO, GET_PARAMS. It
// finishes once, with what it sent and what it read.
//
// Writes through a function it is given; knows nothing of links, drivers or the session.
#pragma once

#include "model/params.h"
#include "protocol/messages.h"
#include "session/sessiontypes.h"

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
    quint64 id = 0; //!< 0 = the session's own (connect sequence), not reported
    CommandKind kind = CommandKind::GetParams; //!< what was asked for (its first step)
    //! A push: what is sent (float32-rounded). A read: effects present to read them too.
    DeviceTuning tuning;
    Vibration vibration; //!< VIBRATE
    quint16 rate = 0;    //!< SET_STREAM

    // Set by the queue as the command goes.
    std::vector<CommandKind> steps; //!< the wire steps, in order
    std::size_t step = 0;           //!< the one in flight
    DeviceTuning received;          //!< what the GET steps read so far
    bool readBackMatches = true;    //!< every read-back so far equals what its step sent
    bool readBackUnanswered = false;
    quint8 seq = 0;
    int retries = 0;
    QByteArray wire;

    CommandKind stepKind() const { return steps.empty() ? kind : steps[step]; }
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
    //! Queues `command`; a full queue finishes it at once (Invalid, QueueFull).
    void enqueue(Command command);
    //! A command waits for its answer (no PING may go out in between).
    bool busy() const { return m_inflight.has_value(); }

    //! The seq of the next frame sent; shared by commands, PINGs and detection's HELLO.
    quint8 nextSeq() { return m_seq++; }
    quint8 peekSeq() const { return m_seq; }
    void setNextSeq(quint8 seq) { m_seq = seq; }

    //! An ACK arrived: finishes, reads back or ignores (late answers) the command in flight.
    void onAck(const v2::Ack &ack);
    //! A PARAMS or EFFECTS arrived (`told` has the part it carried): answers the GET_PARAMS or
    //! GET_EFFECTS step in flight.
    void onTuning(const DeviceTuning &told);
    //! HELLO_REPLY arrived: a HELLO in flight is answered (detection handles the reply).
    void onHelloReply();
    //! Finishes every command (in flight and queued) as NotConnected for `reason`.
    void failAll(CommandResult::Reason reason);

Q_SIGNALS:
    //! A command ended; `command.id == 0` for the session's own.
    void finished(const hatpic::Command &command, const hatpic::CommandResult &result);
    //! The device acknowledged `command`'s step in flight (stepKind(): SET_PARAMS, ZERO,
    //! SET_EFFECTS before their read-back, SET_STREAM and VIBRATE before finished()).
    void acknowledged(const hatpic::Command &command);
    //! A command frame was sent again.
    void retried();
    //! HELLO went unanswered after every resend.
    void helloUnanswered();

private:
    void pump();
    void sendInflight();
    void onTimeout();
    void finishInflight(const CommandResult &result);
    //! The step in flight is done: the next one goes out, or the command finishes.
    void nextStep();

    Writer m_write;
    QTimer m_timer;
    std::optional<Command> m_inflight;
    std::deque<Command> m_queue;
    quint8 m_seq = 0;
};

} // namespace hatpic
