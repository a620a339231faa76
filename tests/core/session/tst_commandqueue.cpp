// CommandQueue on its own, over a scripted link: a writer that keeps every frame, and ACKs and
// PARAMS handed in as a device would answer. One in flight, retries with the same bytes,
// late answers ignored, the read-back, the bound, and failing everything at once.
#include "protocol/v2codec.h"
#include "session/commandqueue.h"

#include <QTest>

#include <tuple>

using namespace Qt::StringLiterals;

namespace hatpic {

namespace {

//! The link side of the queue: what was written, decoded.
struct ScriptedLink
{
    QList<QByteArray> writes;
    QList<v2::Frame> frames() const
    {
        v2::FrameDecoder decoder(v2::Direction::FromHost);
        QList<v2::Frame> out;
        for (const QByteArray &w : writes)
            decoder.feed(w, out);
        return out;
    }
    v2::Frame last() const { return frames().constLast(); }
};

//! A queue writing to a ScriptedLink, with everything it emits collected.
struct Harness
{
    CommandQueue queue;
    ScriptedLink link;
    QList<QPair<Command, CommandResult>> finished;
    QList<Command> acknowledged;
    int retried = 0;
    int helloUnanswered = 0;

    Harness()
    {
        queue.setWriter([this](const QByteArray &bytes) { link.writes.append(bytes); });
        QObject::connect(&queue, &CommandQueue::finished,
                         [this](const Command &c, const CommandResult &r) {
                             finished.append({c, r});
                         });
        QObject::connect(&queue, &CommandQueue::acknowledged,
                         [this](const Command &c) { acknowledged.append(c); });
        QObject::connect(&queue, &CommandQueue::retried, [this] { ++retried; });
        QObject::connect(&queue, &CommandQueue::helloUnanswered, [this] { ++helloUnanswered; });
    }
    //! A push of `tuning` as request `id`; returns the command as queued.
    Command push(quint64 id, const DeviceTuning &tuning)
    {
        Command c;
        c.id = id;
        c.kind = tuning.params    ? CommandKind::SetParams
                 : tuning.effects ? CommandKind::SetEffects
                                  : CommandKind::SetPassivity; // as DeviceSession::pushTuning
        c.tuning = tuning;
        queue.enqueue(c);
        return c;
    }
    void enqueue(quint64 id, CommandKind kind, const DeviceParams &params = {})
    {
        Command c;
        c.id = id;
        c.kind = kind;
        if (kind == CommandKind::SetParams)
            c.tuning.params = params;
        if (kind == CommandKind::SetEffects)
            c.tuning.effects = EffectParams{};
        queue.enqueue(c);
    }
    void ack(quint8 seq, v2::AckStatus status = v2::AckStatus::Ok, quint8 field = v2::kNoField)
    {
        v2::Ack a;
        a.ackedSeq = seq;
        a.status = status;
        a.field = field;
        queue.onAck(a);
    }
    quint8 lastSeq() const { return link.last().seq; }
};

constexpr int kAllRetriesMs =
    CommandQueue::kCommandTimeoutMs * (CommandQueue::kCommandRetries + 1) + 500;

} // namespace

class TestCommandQueue : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void oneInFlightTheRestWait();
    void setEffectsIsReadBack();
    void aTuningIsOnePushWithOneResult();
    void aPassivityPushSaysWhatItSentAndWhatWasApplied();
    void aRefusedPartEndsThePush();
    void effectsReadBackThatDiffersIsReported();
    void vibrateFinishesOnItsAck();
    void effectRejectionsNameTheirField();
    void okAckDoesNotAnswerGetEffects();
    void retriesResendTheSameBytesThenTimeOut();
    void lateAnswerToARetryIsIgnored();
    void setParamsIsReadBack();
    void readBackThatDiffersIsReported();
    void zeroReadBackCarriesTheNewTheta0();
    void unansweredReadBackStillSucceeds();
    void rejectionNamesTheField();
    void okAckDoesNotAnswerGetParams();
    void fullQueueRefusesAtOnce();
    void failAllFinishesEverything();
    void withoutAWriterNothingIsSent();
    void unansweredHelloIsReported();
};

void TestCommandQueue::oneInFlightTheRestWait()
{
    Harness h;
    h.enqueue(1, CommandKind::SaveParams);
    h.enqueue(2, CommandKind::GetParams);
    QCOMPARE(h.link.writes.size(), 1);
    QVERIFY(h.queue.busy());
    QVERIFY(std::holds_alternative<v2::SaveParams>(h.link.last().message));
    h.ack(h.lastSeq());
    QCOMPARE(h.finished.size(), 1);
    QCOMPARE(h.finished[0].first.id, quint64(1));
    QVERIFY(h.finished[0].second.ok());
    QCOMPARE(h.finished[0].second.command, CommandKind::SaveParams);
    // The next one goes out as soon as the first is answered, with the next seq.
    QCOMPARE(h.link.writes.size(), 2);
    QVERIFY(std::holds_alternative<v2::GetParams>(h.link.last().message));
    QCOMPARE(h.link.frames()[1].seq, quint8(h.link.frames()[0].seq + 1));
}

void TestCommandQueue::retriesResendTheSameBytesThenTimeOut()
{
    Harness h;
    h.enqueue(5, CommandKind::Zero);
    QTRY_COMPARE_WITH_TIMEOUT(h.finished.size(), 1, kAllRetriesMs);
    QCOMPARE(h.link.writes.size(), CommandQueue::kCommandRetries + 1);
    for (const QByteArray &w : std::as_const(h.link.writes))
        QCOMPARE(w, h.link.writes.first()); // same seq, same bytes: the device dedupes
    QCOMPARE(h.retried, CommandQueue::kCommandRetries);
    const CommandResult r = h.finished[0].second;
    QCOMPARE(r.status, CommandResult::Status::Timeout);
    QCOMPARE(r.command, CommandKind::Zero);
    QCOMPARE(r.attempts, CommandQueue::kCommandRetries + 1);
    QCOMPARE(r.intervalMs, CommandQueue::kCommandTimeoutMs);
    QVERIFY(!h.queue.busy());
}

void TestCommandQueue::lateAnswerToARetryIsIgnored()
{
    Harness h;
    h.enqueue(1, CommandKind::SaveParams);
    const quint8 first = h.lastSeq();
    h.enqueue(2, CommandKind::SaveParams);
    h.ack(first);
    QCOMPARE(h.finished.size(), 1);
    // The device answered a retried copy too: that ACK names the old seq and is not the
    // second command's answer.
    h.ack(first);
    QCOMPARE(h.finished.size(), 1);
    QVERIFY(h.queue.busy());
    h.ack(quint8(first + 7)); // nothing of ours
    QCOMPARE(h.finished.size(), 1);
    h.ack(h.lastSeq());
    QCOMPARE(h.finished.size(), 2);
    QCOMPARE(h.finished[1].first.id, quint64(2));
}

void TestCommandQueue::setParamsIsReadBack()
{
    Harness h;
    DeviceParams p;
    p.K_max = 0.6;
    h.enqueue(3, CommandKind::SetParams, p);
    QVERIFY(std::holds_alternative<v2::SetParams>(h.link.last().message));
    h.ack(h.lastSeq());
    // Acknowledged (the session applies it from the next sample), then read back.
    QCOMPARE(h.acknowledged.size(), 1);
    QCOMPARE(h.acknowledged[0].kind, CommandKind::SetParams);
    QVERIFY(h.finished.isEmpty());
    QVERIFY(std::holds_alternative<v2::GetParams>(h.link.last().message));
    h.queue.onTuning({p, std::nullopt});
    QCOMPARE(h.finished.size(), 1);
    const CommandResult r = h.finished[0].second;
    QCOMPARE(h.finished[0].first.id, quint64(3));
    QVERIFY(r.ok());
    QCOMPARE(r.command, CommandKind::SetParams);
    QVERIFY(r.readBack);
    QVERIFY(r.readBackMatches);
    QCOMPARE(r.received.params.value(), p);
}

void TestCommandQueue::readBackThatDiffersIsReported()
{
    Harness h;
    DeviceParams sent;
    sent.K_max = 0.6;
    h.enqueue(3, CommandKind::SetParams, sent);
    h.ack(h.lastSeq());
    DeviceParams held = sent;
    held.K_max = 0.5;
    h.queue.onTuning({held, std::nullopt});
    const CommandResult r = h.finished.value(0).second;
    QVERIFY(r.ok());
    QVERIFY(r.readBack);
    QVERIFY(!r.readBackMatches);
    QCOMPARE(r.sent.params.value(), sent);
    QCOMPARE(r.received.params.value(), held);
}

void TestCommandQueue::zeroReadBackCarriesTheNewTheta0()
{
    Harness h;
    h.enqueue(4, CommandKind::Zero);
    h.ack(h.lastSeq());
    DeviceParams held;
    held.theta0 = 0.25;
    h.queue.onTuning({held, std::nullopt});
    const CommandResult r = h.finished.value(0).second;
    QVERIFY(r.ok());
    QCOMPARE(r.command, CommandKind::Zero);
    QVERIFY(r.readBack && r.readBackMatches);
    QCOMPARE(r.received.params.value().theta0, 0.25);
}

void TestCommandQueue::unansweredReadBackStillSucceeds()
{
    Harness h;
    h.enqueue(6, CommandKind::Zero);
    h.ack(h.lastSeq());
    QTRY_COMPARE_WITH_TIMEOUT(h.finished.size(), 1, kAllRetriesMs);
    const CommandResult r = h.finished[0].second;
    QVERIFY(r.ok()); // the device did acknowledge ZERO
    QCOMPARE(r.reason, CommandResult::Reason::ReadBackUnanswered);
    QCOMPARE(r.command, CommandKind::Zero);
}

void TestCommandQueue::rejectionNamesTheField()
{
    Harness h;
    h.enqueue(7, CommandKind::SetParams);
    h.ack(h.lastSeq(), v2::AckStatus::OutOfRange, 3);
    QCOMPARE(h.finished.size(), 1);
    const CommandResult r = h.finished[0].second;
    QCOMPARE(r.status, CommandResult::Status::Rejected);
    QCOMPARE(r.ackStatus, v2::AckStatus::OutOfRange);
    QCOMPARE(r.field, 3);
    QCOMPARE(r.command, CommandKind::SetParams);
    QVERIFY(h.acknowledged.isEmpty()); // nothing to apply, nothing read back
    QCOMPARE(h.link.writes.size(), 1);
}

void TestCommandQueue::setEffectsIsReadBack()
{
    Harness h;
    EffectParams fx;
    fx.detent_strength = 0.05;
    h.push(11, {std::nullopt, fx});
    const v2::Frame sent = h.link.last();
    const auto *set = std::get_if<v2::SetEffects>(&sent.message);
    QVERIFY(set && set->effects.detent_strength == double(0.05f));
    h.ack(h.lastSeq());
    QCOMPARE(h.acknowledged.size(), 1);
    QCOMPARE(h.acknowledged[0].kind, CommandKind::SetEffects);
    QVERIFY(h.finished.isEmpty());
    // Read back under the same request id with GET_EFFECTS; a PARAMS does not answer it.
    QVERIFY(std::holds_alternative<v2::GetEffects>(h.link.last().message));
    h.queue.onTuning({DeviceParams{}, std::nullopt});
    QVERIFY(h.finished.isEmpty());
    h.queue.onTuning({std::nullopt, set->effects});
    QCOMPARE(h.finished.size(), 1);
    QCOMPARE(h.finished[0].first.id, quint64(11));
    const CommandResult r = h.finished[0].second;
    QVERIFY(r.ok());
    QCOMPARE(r.command, CommandKind::SetEffects);
    QVERIFY(r.readBack && r.readBackMatches);
    QCOMPARE(r.received.effects.value().detent_strength, double(0.05f));
}

//! Parameters and effects travel as one push: SET_PARAMS, GET_PARAMS, SET_EFFECTS, GET_EFFECTS
//! under one request id, one result carrying both read-backs.
void TestCommandQueue::aTuningIsOnePushWithOneResult()
{
    Harness h;
    DeviceTuning tuning{DeviceParams{}, EffectParams{}};
    tuning.params->K_max = 0.6;
    tuning.effects->detent_strength = 0.05;
    const Command c = h.push(13, tuning);
    QVERIFY(std::holds_alternative<v2::SetParams>(h.link.last().message));
    h.ack(h.lastSeq());
    QVERIFY(std::holds_alternative<v2::GetParams>(h.link.last().message));
    h.queue.onTuning({std::nullopt, *c.tuning.effects}); // not what GET_PARAMS waits for
    QVERIFY(std::holds_alternative<v2::GetParams>(h.link.last().message));
    h.queue.onTuning({c.tuning.params, std::nullopt});
    QVERIFY(h.finished.isEmpty());
    QVERIFY(std::holds_alternative<v2::SetEffects>(h.link.last().message));
    h.ack(h.lastSeq());
    QVERIFY(std::holds_alternative<v2::GetEffects>(h.link.last().message));
    h.queue.onTuning({std::nullopt, c.tuning.effects});
    QCOMPARE(h.finished.size(), 1);
    QCOMPARE(h.finished[0].first.id, quint64(13));
    QCOMPARE(h.acknowledged.size(), 2);
    QCOMPARE(h.acknowledged[0].stepKind(), CommandKind::SetParams);
    QCOMPARE(h.acknowledged[1].stepKind(), CommandKind::SetEffects);
    const CommandResult r = h.finished[0].second;
    QVERIFY(r.ok() && r.readBack && r.readBackMatches);
    QCOMPARE(r.command, CommandKind::SetParams);
    QVERIFY(sameOnWire(r.received, c.tuning));
    QCOMPARE(h.link.writes.size(), 4);
}

void TestCommandQueue::aPassivityPushSaysWhatItSentAndWhatWasApplied()
{
    Harness h;
    // The passivity block alone: SET_PASSIVITY, GET_PASSIVITY; the result says what it sent
    // (the tuner's "Pushed: pc_damping_max 0.7 → 0" is made from it).
    const Command alone = h.push(15, {std::nullopt, std::nullopt, PassivityParams::off()});
    QVERIFY(std::holds_alternative<v2::SetPassivity>(h.link.last().message));
    h.ack(h.lastSeq());
    QVERIFY(std::holds_alternative<v2::GetPassivity>(h.link.last().message));
    h.queue.onTuning({std::nullopt, std::nullopt, alone.tuning.passivity});
    QCOMPARE(h.finished.size(), 1);
    const CommandResult r = h.finished[0].second;
    QVERIFY(r.ok() && r.readBackMatches);
    QVERIFY(r.sent.passivity && *r.sent.passivity == PassivityParams::off());
    QVERIFY(r.received.passivity.has_value());

    // All three blocks, SET_PASSIVITY unanswered: the parameters and effects are in force, the
    // passivity block unknown.
    const Command all = h.push(16, {DeviceParams{}, EffectParams{}, PassivityParams::off()});
    h.ack(h.lastSeq());
    h.queue.onTuning({all.tuning.params, std::nullopt});
    h.ack(h.lastSeq());
    h.queue.onTuning({std::nullopt, all.tuning.effects});
    QVERIFY(std::holds_alternative<v2::SetPassivity>(h.link.last().message));
    QTRY_COMPARE_WITH_TIMEOUT(h.finished.size(), 2, 10 * CommandQueue::kCommandTimeoutMs);
    const CommandResult timedOut = h.finished[1].second;
    QCOMPARE(timedOut.status, CommandResult::Status::Timeout);
    QCOMPARE(timedOut.command, CommandKind::SetPassivity);
    const DeviceTuning applied = appliedBeforeFailure(timedOut);
    QVERIFY(applied.params && applied.effects && !applied.passivity);
    QCOMPARE(unansweredBlockStep(timedOut), std::optional(CommandKind::SetPassivity));
}

void TestCommandQueue::aRefusedPartEndsThePush()
{
    Harness h;
    const Command c = h.push(14, {DeviceParams{}, EffectParams{}});
    h.ack(h.lastSeq());
    h.queue.onTuning({c.tuning.params, std::nullopt});
    h.ack(h.lastSeq(), v2::AckStatus::OutOfRange, 5); // SET_EFFECTS refused: wall_stiffness
    QCOMPARE(h.finished.size(), 1);
    const CommandResult r = h.finished[0].second;
    QCOMPARE(r.status, CommandResult::Status::Rejected);
    QCOMPARE(r.command, CommandKind::SetEffects); // the frame refused
    QCOMPARE(r.field, 5);
    QVERIFY(r.received.params.has_value()); // the parameters were taken and read back
    QVERIFY(!r.received.effects.has_value());
    QCOMPARE(h.link.writes.size(), 3);
}

void TestCommandQueue::effectsReadBackThatDiffersIsReported()
{
    Harness h;
    EffectParams fx;
    fx.wall_max = 0.5;
    const Command c = h.push(12, {std::nullopt, fx});
    h.ack(h.lastSeq());
    EffectParams held = *c.tuning.effects;
    held.wall_max = 0.25;
    h.queue.onTuning({std::nullopt, held});
    const CommandResult r = h.finished.value(0).second;
    QVERIFY(r.ok() && r.readBack && !r.readBackMatches);
    QCOMPARE(r.sent.effects.value().wall_max, 0.5);
    QCOMPARE(r.received.effects.value().wall_max, 0.25);
}

void TestCommandQueue::vibrateFinishesOnItsAck()
{
    Harness h;
    Command c;
    c.id = 13;
    c.kind = CommandKind::Vibrate;
    c.vibration = {0.1, 80, 0.5};
    h.queue.enqueue(c);
    const v2::Frame sent = h.link.last();
    const auto *cue = std::get_if<v2::Vibrate>(&sent.message);
    QVERIFY(cue);
    QCOMPARE(*cue, (v2::Vibrate{0.1f, 80.0f, 0.5f}));
    h.ack(h.lastSeq());
    QCOMPARE(h.finished.size(), 1); // no read-back: fire and forget
    QCOMPARE(h.link.writes.size(), 1);
    const CommandResult r = h.finished[0].second;
    QVERIFY(r.ok());
    QCOMPARE(r.command, CommandKind::Vibrate);
    QCOMPARE(r.vibration, (Vibration{0.1, 80, 0.5}));
}

void TestCommandQueue::effectRejectionsNameTheirField()
{
    // A field the block has is named; one beyond it (VIBRATE has three) names nothing.
    for (const auto &[kind, field, named] : {std::tuple{CommandKind::SetEffects, quint8(6), 6},
                                             std::tuple{CommandKind::Vibrate, quint8(1), 1},
                                             std::tuple{CommandKind::Vibrate, quint8(5), -1}}) {
        Harness h;
        h.enqueue(14, kind);
        h.ack(h.lastSeq(), v2::AckStatus::OutOfRange, field);
        const CommandResult r = h.finished.value(0).second;
        QCOMPARE(r.status, CommandResult::Status::Rejected);
        QCOMPARE(r.command, kind);
        QCOMPARE(r.field, named);
        QVERIFY(h.acknowledged.isEmpty());
    }
}

void TestCommandQueue::okAckDoesNotAnswerGetEffects()
{
    Harness h;
    h.enqueue(15, CommandKind::GetEffects);
    h.ack(h.lastSeq());
    QVERIFY(h.finished.isEmpty()); // only EFFECTS answers it
    h.ack(h.lastSeq(), v2::AckStatus::UnknownType);
    QCOMPARE(h.finished.value(0).second.status, CommandResult::Status::Rejected);
}

void TestCommandQueue::okAckDoesNotAnswerGetParams()
{
    Harness h;
    h.enqueue(8, CommandKind::GetParams);
    h.ack(h.lastSeq()); // GET_PARAMS is answered by PARAMS, not by an ACK
    QVERIFY(h.finished.isEmpty());
    h.ack(h.lastSeq(), v2::AckStatus::UnknownType); // …but a refusal ends it
    QCOMPARE(h.finished.size(), 1);
    QCOMPARE(h.finished[0].second.status, CommandResult::Status::Rejected);
    QCOMPARE(h.finished[0].second.field, -1);
}

void TestCommandQueue::fullQueueRefusesAtOnce()
{
    Harness h;
    h.enqueue(1, CommandKind::SaveParams); // in flight
    for (int i = 0; i < CommandQueue::kMaxQueuedCommands; ++i)
        h.enqueue(quint64(10 + i), CommandKind::SaveParams);
    QVERIFY(h.finished.isEmpty());
    h.enqueue(99, CommandKind::GetParams);
    QCOMPARE(h.finished.size(), 1);
    QCOMPARE(h.finished[0].first.id, quint64(99));
    const CommandResult r = h.finished[0].second;
    QCOMPARE(r.status, CommandResult::Status::Invalid);
    QCOMPARE(r.reason, CommandResult::Reason::QueueFull);
    QCOMPARE(r.limit, CommandQueue::kMaxQueuedCommands);
    QCOMPARE(r.command, CommandKind::GetParams);
    QCOMPARE(h.link.writes.size(), 1);
}

void TestCommandQueue::failAllFinishesEverything()
{
    Harness h;
    h.enqueue(1, CommandKind::SetParams);
    h.ack(h.lastSeq()); // now in its read-back stage
    h.enqueue(2, CommandKind::SaveParams);
    h.queue.failAll(CommandResult::Reason::ConnectionLost);
    QCOMPARE(h.finished.size(), 2);
    for (const auto &[command, result] : std::as_const(h.finished)) {
        QCOMPARE(result.status, CommandResult::Status::NotConnected);
        QCOMPARE(result.reason, CommandResult::Reason::ConnectionLost);
    }
    // The step in flight (issue 27): a push cut in its read-back had its SET_PARAMS accepted,
    // and its result says so.
    QCOMPARE(h.finished[0].second.command, CommandKind::GetParams);
    QVERIFY(appliedBeforeFailure(h.finished[0].second).params.has_value());
    QVERIFY(!appliedBeforeFailure(h.finished[1].second).params.has_value());
    QVERIFY(!h.queue.busy());
    // Nothing is resent afterwards.
    const qsizetype writes = h.link.writes.size();
    QTest::qWait(CommandQueue::kCommandTimeoutMs * 2);
    QCOMPARE(h.link.writes.size(), writes);
}

void TestCommandQueue::withoutAWriterNothingIsSent()
{
    Harness h;
    h.queue.setWriter({});
    h.enqueue(1, CommandKind::GetParams);
    QVERIFY(h.link.writes.isEmpty());
    QVERIFY(!h.queue.busy());
    h.queue.setWriter([&h](const QByteArray &bytes) { h.link.writes.append(bytes); });
    QCOMPARE(h.link.writes.size(), 1);
    QVERIFY(h.queue.busy());
}

void TestCommandQueue::unansweredHelloIsReported()
{
    Harness h;
    h.enqueue(0, CommandKind::Hello);
    QCOMPARE(h.link.writes.first().front(), '\0'); // led by a delimiter
    QTRY_COMPARE_WITH_TIMEOUT(h.helloUnanswered, 1, kAllRetriesMs);
    QVERIFY(h.finished.isEmpty()); // detection reports it, not a command result
    QVERIFY(!h.queue.busy());

    // Answered: HELLO_REPLY clears it, and the next command goes out.
    h.enqueue(0, CommandKind::Hello);
    h.enqueue(1, CommandKind::GetParams);
    h.queue.onHelloReply();
    QVERIFY(std::holds_alternative<v2::GetParams>(h.link.last().message));
}

} // namespace hatpic

QTEST_GUILESS_MAIN(hatpic::TestCommandQueue)
#include "tst_commandqueue.moc"
