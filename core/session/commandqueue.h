// The v2 command channel: one command in flight, a bounded queue behind it, resends on a
// timeout (same bytes, same seq, so the device answers a retry without applying it twice),
// matching of ACKs, PARAMS and EFFECTS to the command in flight, and the read-back that follows
// SET_PARAMS and ZERO (GET_PARAMS) and SET_EFFECTS (GET_EFFECTS) under the same request id.
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

namespace hatpic {

struct Command
{
    quint64 id = 0; //!< 0 = the session's own (connect sequence), not reported
    CommandKind kind = CommandKind::GetParams;
    DeviceParams params;  //!< SET_PARAMS: what was sent (float32-rounded)
    EffectParams effects; //!< SET_EFFECTS: what was sent (float32-rounded)
    Vibration vibration;  //!< VIBRATE
    quint16 rate = 0;     //!< SET_STREAM
    bool readBack =
        false; //!< the GET_PARAMS (GET_EFFECTS) stage after SET_PARAMS, ZERO (SET_EFFECTS)
    CommandKind origin = CommandKind::GetParams; //!< the command a read-back belongs to
    quint8 seq = 0;
    int retries = 0;
    QByteArray wire;
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
    //! A PARAMS arrived: answers a GET_PARAMS (or a read-back) in flight.
    void onParams(const DeviceParams &params);
    //! An EFFECTS arrived: answers a GET_EFFECTS (or SET_EFFECTS' read-back) in flight.
    void onEffects(const EffectParams &effects);
    //! HELLO_REPLY arrived: a HELLO in flight is answered (detection handles the reply).
    void onHelloReply();
    //! Finishes every command (in flight and queued) as NotConnected for `reason`.
    void failAll(CommandResult::Reason reason);

Q_SIGNALS:
    //! A command ended; `command.id == 0` for the session's own.
    void finished(const hatpic::Command &command, const hatpic::CommandResult &result);
    //! The device acknowledged `command` (OK): SET_PARAMS, ZERO and SET_EFFECTS before their
    //! read-back, SET_STREAM and VIBRATE before finished().
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

    Writer m_write;
    QTimer m_timer;
    std::optional<Command> m_inflight;
    std::deque<Command> m_queue;
    quint8 m_seq = 0;
};

} // namespace hatpic
