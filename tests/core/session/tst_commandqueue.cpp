// CommandQueue on its own, over a scripted link: a writer that keeps every frame, and ACKs and
// PARAMS handed in as a device would answer. One in flight, retries with the same bytes,
// late answers ignored, the read-back, the bound, and failing everything at once.
#include "protocol/v2codec.h"
#include "session/commandqueue.h"

#include <QTest>

#include <tuple>
#include <variant>

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

//! A v2 device with `capabilities` (v2::kCapability* bits).
DeviceInfo v2Device(quint8 capabilities)
{
    DeviceInfo device;
    device.protocol = WireProtocol::V2;
    device.protocolVersion = 2;
    device.capabilities = capabilities;
    return device;
}
//! A v2 device with neither effects nor passivity: a read is GET_PARAMS alone.
const DeviceInfo kPlainDevice = v2Device(0);
//! A v2 device with effects (a read adds GET_EFFECTS; VIBRATE).
const DeviceInfo kEffectsDevice = v2Device(v2::kCapabilityEffects);
//! A v2 device with every block.
const DeviceInfo kFullDevice = v2Device(v2::kCapabilityEffects | v2::kCapabilityPassivity);

//! What the queue finished: the command, its outcome, and the id its `then` answers to.
struct Finished
{
    Command command;
    Outcome outcome;
    quint64 id = 0; //!< 0: the command had no `then`
};

//! A queue writing to a ScriptedLink, with everything it emits collected.
struct Harness
{
    CommandQueue queue;
    ScriptedLink link;
    QList<Finished> finished;
    QList<Command> acknowledged;
    int retried = 0;
    int helloUnanswered = 0;
    quint64 heard = 0; //!< the id of the last `then` called

    Harness()
    {
        queue.setWriter([this](const QByteArray &bytes) { link.writes.append(bytes); });
        QObject::connect(&queue, &CommandQueue::finished,
                         [this](const Command &c, const Outcome &o) {
                             // The listener calls `then`, as the session does: it names the
                             // request that finished.
                             heard = 0;
                             if (c.then)
                                 c.then(o);
                             finished.append({c, o, heard});
                         });
        QObject::connect(&queue, &CommandQueue::acknowledged,
                         [this](const Command &c) { acknowledged.append(c); });
        QObject::connect(&queue, &CommandQueue::retried, [this] { ++retried; });
        QObject::connect(&queue, &CommandQueue::helloUnanswered, [this] { ++helloUnanswered; });
    }
    //! Queues `request` as request `id`, with the steps it takes on `device`; returns the
    //! command as queued.
    Command enqueue(quint64 id, const Request &request, const DeviceInfo &device = kPlainDevice)
    {
        const Command c(request, wireSteps(request, device),
                        [this, id](const Outcome &) { heard = id; });
        queue.enqueue(c);
        return c;
    }
    //! A push of `tuning` as request `id`; returns the command as queued.
    Command push(quint64 id, const DeviceTuning &tuning)
    {
        return enqueue(id, request::Push{tuning}, kFullDevice);
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

//! The read-back of a finished outcome; nullopt when it did not finish as Done.
std::optional<outcome::ReadBack> readBackOf(const Outcome &o)
{
    const auto *done = std::get_if<outcome::Done>(&o.result);
    return done ? std::optional(done->readBack) : std::nullopt;
}

constexpr int kAllRetriesMs =
    CommandQueue::kCommandTimeoutMs * (CommandQueue::kCommandRetries + 1) + 500;

} // namespace

class TestCommandQueue : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void oneInFlightTheRestWait();
    void setEffectsIsReadBack();
    void aTuningIsOnePushWithOneOutcome();
    void aPassivityPushSaysWhatItSentAndWhatWasApplied();
    void aRefusedPartEndsThePush();
    void effectsReadBackThatDiffersIsReported();
    void vibrateFinishesOnItsAck();
    void effectRejectionsNameTheirField();
    void okAckDoesNotAnswerGetEffects();
    void retriesResendTheSameBytesThenTimeOut();
    void lateAnswerToARetryIsIgnored();
    void setParamsIsReadBack();
    void eachStepCarriesWhatItApplies();
    void aKnobsStepsNameItAndOnlyItsReplyAnswers();
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
    h.enqueue(1, request::Save{});
    h.enqueue(2, request::Read{});
    QCOMPARE(h.link.writes.size(), 1);
    QVERIFY(h.queue.busy());
    QVERIFY(std::holds_alternative<v2::SaveParams>(h.link.last().message));
    h.ack(h.lastSeq());
    QCOMPARE(h.finished.size(), 1);
    QCOMPARE(h.finished[0].id, quint64(1));
    QVERIFY(h.finished[0].outcome.ok());
    QVERIFY(std::holds_alternative<request::Save>(h.finished[0].outcome.request));
    // The next one goes out as soon as the first is answered, with the next seq.
    QCOMPARE(h.link.writes.size(), 2);
    QVERIFY(std::holds_alternative<v2::GetParams>(h.link.last().message));
    QCOMPARE(h.link.frames()[1].seq, quint8(h.link.frames()[0].seq + 1));
}

void TestCommandQueue::retriesResendTheSameBytesThenTimeOut()
{
    Harness h;
    h.enqueue(5, request::Zero{});
    QTRY_COMPARE_WITH_TIMEOUT(h.finished.size(), 1, kAllRetriesMs);
    QCOMPARE(h.link.writes.size(), CommandQueue::kCommandRetries + 1);
    for (const QByteArray &w : std::as_const(h.link.writes))
        QCOMPARE(w, h.link.writes.first()); // same seq, same bytes: the device dedupes
    QCOMPARE(h.retried, CommandQueue::kCommandRetries);
    const Outcome r = h.finished[0].outcome;
    const auto *timedOut = std::get_if<outcome::TimedOut>(&r.result);
    QVERIFY(timedOut);
    QCOMPARE(timedOut->step, CommandKind::Zero);
    QCOMPARE(timedOut->attempts, CommandQueue::kCommandRetries + 1);
    QCOMPARE(timedOut->intervalMs, CommandQueue::kCommandTimeoutMs);
    QVERIFY(!h.queue.busy());
}

void TestCommandQueue::lateAnswerToARetryIsIgnored()
{
    Harness h;
    h.enqueue(1, request::Save{});
    const quint8 first = h.lastSeq();
    h.enqueue(2, request::Save{});
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
    QCOMPARE(h.finished[1].id, quint64(2));
}

void TestCommandQueue::setParamsIsReadBack()
{
    Harness h;
    DeviceParams p;
    p.K_max = 0.6;
    h.push(3, {p, std::nullopt});
    QVERIFY(std::holds_alternative<v2::SetParams>(h.link.last().message));
    h.ack(h.lastSeq());
    // Acknowledged (the session applies it from the next sample), then read back.
    QCOMPARE(h.acknowledged.size(), 1);
    QCOMPARE(h.acknowledged[0].stepKind(), CommandKind::SetParams);
    QVERIFY(h.finished.isEmpty());
    QVERIFY(std::holds_alternative<v2::GetParams>(h.link.last().message));
    h.queue.onTuning({p, std::nullopt});
    QCOMPARE(h.finished.size(), 1);
    const Outcome r = h.finished[0].outcome;
    QCOMPARE(h.finished[0].id, quint64(3));
    QVERIFY(r.ok());
    QVERIFY(r.pushed() && r.pushed()->params && !r.pushed()->effects);
    QCOMPARE(readBackOf(r), std::optional(outcome::ReadBack::Matches));
    QCOMPARE(r.received.params.value(), p);
}

void TestCommandQueue::eachStepCarriesWhatItApplies()
{
    // wireSteps(): the messages themselves, each with its part of the request.
    DeviceParams p;
    p.K_max = 0.6;
    EffectParams e;
    e.wall_stiffness = 2;
    PassivityParams pc;
    pc.pc_damping_max = 0.3;
    QCOMPARE(wireSteps(request::Push{{p, e, pc}}, kFullDevice),
             (std::vector<WireStep>{{v2::SetParams{p}},
                                    {v2::GetParams{}},
                                    {v2::SetEffects{e}},
                                    {v2::GetEffects{}},
                                    {v2::SetPassivity{pc}},
                                    {v2::GetPassivity{}}}));
    QCOMPARE(wireSteps(request::Read{}, kEffectsDevice),
             (std::vector<WireStep>{{v2::GetParams{}}, {v2::GetEffects{}}}));
    QCOMPARE(wireSteps(request::Zero{1}, kPlainDevice),
             (std::vector<WireStep>{{v2::Zero{1}}, {v2::GetParams{1}}}));
    QCOMPARE(wireSteps(request::Stream{250}, kPlainDevice),
             (std::vector<WireStep>{{v2::SetStream{250}}}));
    QCOMPARE(wireSteps(request::Vibrate{{0.1, 80, 0.5}}, kEffectsDevice),
             (std::vector<WireStep>{{v2::Vibrate{0.1f, 80.f, 0.5f}}}));
    QCOMPARE(stepKinds(wireSteps(request::Save{}, kPlainDevice)),
             std::vector{CommandKind::SaveParams});
    // The queue sends each step's message as it is.
    Harness h;
    h.enqueue(20, request::Vibrate{{0.1, 80, 0.5}, 2}, kEffectsDevice);
    QCOMPARE(h.link.writes.constLast(),
             v2::encodeFrame(h.lastSeq(), v2::Vibrate{0.1f, 80.f, 0.5f, 2}));
}

void TestCommandQueue::aKnobsStepsNameItAndOnlyItsReplyAnswers()
{
    Harness h;
    DeviceInfo fourKnobs = kFullDevice;
    fourKnobs.axes = 4;
    DeviceParams p;
    p.K_max = 0.6;
    EffectParams e;
    e.detent_strength = 0.04;
    h.enqueue(5, request::Push{{p, e}, 2}, fourKnobs); // knob 3
    QCOMPARE(std::get<v2::SetParams>(h.link.last().message).axis, v2::AxisIndex(2));
    h.ack(h.lastSeq());
    QCOMPARE(std::get<v2::GetParams>(h.link.last().message).axis, v2::AxisIndex(2));
    // Knob 1's PARAMS (another host's read, or telemetry's owner) does not answer knob 3's.
    DeviceParams other;
    h.queue.onTuning({other, std::nullopt}, 0);
    h.queue.onTuning({other, std::nullopt}, 1);
    QVERIFY(std::holds_alternative<v2::GetParams>(h.link.last().message));
    h.queue.onTuning({p, std::nullopt}, 2);
    QCOMPARE(std::get<v2::SetEffects>(h.link.last().message).axis, v2::AxisIndex(2));
    h.ack(h.lastSeq());
    QCOMPARE(std::get<v2::GetEffects>(h.link.last().message).axis, v2::AxisIndex(2));
    h.queue.onTuning({std::nullopt, e}, 2);
    QCOMPARE(h.finished.size(), 1);
    const Outcome r = h.finished[0].outcome;
    QVERIFY(r.ok());
    QCOMPARE(knobOf(r.request), Knob(2));
    QCOMPARE(readBackOf(r), std::optional(outcome::ReadBack::Matches));
    QCOMPARE(r.received.params.value(), p);

    // Knob 1's steps go without the field: a single-knob device's frames are unchanged.
    h.enqueue(6, request::Zero{}, fourKnobs);
    QCOMPARE(std::get<v2::Zero>(h.link.last().message).axis, v2::AxisIndex());
    QCOMPARE(h.link.writes.constLast(), v2::encodeFrame(h.lastSeq(), v2::Zero{}));
    // And every per-knob step carries it.
    h.ack(h.lastSeq());
    h.queue.onTuning({p, std::nullopt});
    h.enqueue(7, request::Vibrate{{0.05, 20, 0.2}, 3}, fourKnobs);
    QCOMPARE(std::get<v2::Vibrate>(h.link.last().message).axis, v2::AxisIndex(3));
    h.ack(h.lastSeq());
    h.enqueue(8, request::Read{1}, fourKnobs);
    QCOMPARE(std::get<v2::GetParams>(h.link.last().message).axis, v2::AxisIndex(1));
    h.queue.onTuning({p, std::nullopt}, 1);
    QCOMPARE(std::get<v2::GetEffects>(h.link.last().message).axis, v2::AxisIndex(1));
    h.queue.onTuning({std::nullopt, e}, 1);
    QCOMPARE(std::get<v2::GetPassivity>(h.link.last().message).axis, v2::AxisIndex(1));
    h.queue.onTuning({std::nullopt, std::nullopt, PassivityParams{}}, 1);
    QCOMPARE(h.finished.size(), 4);
    QVERIFY(h.finished[3].outcome.ok());
    QCOMPARE(h.finished[3].id, quint64(8));
}

void TestCommandQueue::readBackThatDiffersIsReported()
{
    Harness h;
    DeviceParams sent;
    sent.K_max = 0.6;
    h.push(3, {sent, std::nullopt});
    h.ack(h.lastSeq());
    DeviceParams held = sent;
    held.K_max = 0.5;
    h.queue.onTuning({held, std::nullopt});
    const Outcome r = h.finished.value(0).outcome;
    QVERIFY(r.ok());
    QCOMPARE(readBackOf(r), std::optional(outcome::ReadBack::Differs));
    QVERIFY(r.pushed());
    QCOMPARE(r.pushed()->params.value(), sent);
    QCOMPARE(r.received.params.value(), held);
}

void TestCommandQueue::zeroReadBackCarriesTheNewTheta0()
{
    Harness h;
    h.enqueue(4, request::Zero{});
    h.ack(h.lastSeq());
    DeviceParams held;
    held.theta0 = 0.25;
    h.queue.onTuning({held, std::nullopt});
    const Outcome r = h.finished.value(0).outcome;
    QVERIFY(r.ok());
    QVERIFY(std::holds_alternative<request::Zero>(r.request));
    QCOMPARE(readBackOf(r), std::optional(outcome::ReadBack::Matches));
    QCOMPARE(r.received.params.value().theta0, 0.25);
}

void TestCommandQueue::unansweredReadBackStillSucceeds()
{
    Harness h;
    h.enqueue(6, request::Zero{});
    h.ack(h.lastSeq());
    QTRY_COMPARE_WITH_TIMEOUT(h.finished.size(), 1, kAllRetriesMs);
    const Outcome r = h.finished[0].outcome;
    QVERIFY(r.ok()); // the device did acknowledge ZERO
    QCOMPARE(readBackOf(r), std::optional(outcome::ReadBack::Unanswered));
    QVERIFY(std::holds_alternative<request::Zero>(r.request));
}

void TestCommandQueue::rejectionNamesTheField()
{
    Harness h;
    h.push(7, {DeviceParams{}, std::nullopt});
    h.ack(h.lastSeq(), v2::AckStatus::OutOfRange, 3);
    QCOMPARE(h.finished.size(), 1);
    const Outcome r = h.finished[0].outcome;
    const auto *refused = std::get_if<outcome::Refused>(&r.result);
    QVERIFY(refused);
    QCOMPARE(refused->status, v2::AckStatus::OutOfRange);
    QCOMPARE(refused->field, 3);
    QCOMPARE(refused->step, CommandKind::SetParams);
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
    QCOMPARE(h.acknowledged[0].stepKind(), CommandKind::SetEffects);
    QVERIFY(h.finished.isEmpty());
    // Read back under the same request with GET_EFFECTS; a PARAMS does not answer it.
    QVERIFY(std::holds_alternative<v2::GetEffects>(h.link.last().message));
    h.queue.onTuning({DeviceParams{}, std::nullopt});
    QVERIFY(h.finished.isEmpty());
    h.queue.onTuning({std::nullopt, set->effects});
    QCOMPARE(h.finished.size(), 1);
    QCOMPARE(h.finished[0].id, quint64(11));
    const Outcome r = h.finished[0].outcome;
    QVERIFY(r.ok());
    QVERIFY(r.pushed() && !r.pushed()->params && r.pushed()->effects);
    QCOMPARE(readBackOf(r), std::optional(outcome::ReadBack::Matches));
    QCOMPARE(r.received.effects.value().detent_strength, double(0.05f));
}

//! Parameters and effects travel as one push: SET_PARAMS, GET_PARAMS, SET_EFFECTS, GET_EFFECTS
//! under one request, one outcome carrying both read-backs.
void TestCommandQueue::aTuningIsOnePushWithOneOutcome()
{
    Harness h;
    DeviceTuning tuning{DeviceParams{}, EffectParams{}};
    tuning.params->K_max = 0.6;
    tuning.effects->detent_strength = 0.05;
    const Command c = h.push(13, tuning);
    QVERIFY(c.pushed());
    const DeviceTuning &sent = *c.pushed();
    QVERIFY(std::holds_alternative<v2::SetParams>(h.link.last().message));
    h.ack(h.lastSeq());
    QVERIFY(std::holds_alternative<v2::GetParams>(h.link.last().message));
    h.queue.onTuning({std::nullopt, *sent.effects}); // not what GET_PARAMS waits for
    QVERIFY(std::holds_alternative<v2::GetParams>(h.link.last().message));
    h.queue.onTuning({sent.params, std::nullopt});
    QVERIFY(h.finished.isEmpty());
    QVERIFY(std::holds_alternative<v2::SetEffects>(h.link.last().message));
    h.ack(h.lastSeq());
    QVERIFY(std::holds_alternative<v2::GetEffects>(h.link.last().message));
    h.queue.onTuning({std::nullopt, sent.effects});
    QCOMPARE(h.finished.size(), 1);
    QCOMPARE(h.finished[0].id, quint64(13));
    QCOMPARE(h.acknowledged.size(), 2);
    QCOMPARE(h.acknowledged[0].stepKind(), CommandKind::SetParams);
    QCOMPARE(h.acknowledged[1].stepKind(), CommandKind::SetEffects);
    const Outcome r = h.finished[0].outcome;
    QVERIFY(r.ok());
    QCOMPARE(readBackOf(r), std::optional(outcome::ReadBack::Matches));
    QVERIFY(r.pushed() && r.pushed()->params && r.pushed()->effects);
    QVERIFY(sameOnWire(r.received, sent));
    QCOMPARE(h.link.writes.size(), 4);
}

void TestCommandQueue::aPassivityPushSaysWhatItSentAndWhatWasApplied()
{
    Harness h;
    // The passivity block alone: SET_PASSIVITY, GET_PASSIVITY; the outcome says what it sent
    // (the tuner's "Pushed: pc_damping_max 0.7 → 0" is made from it).
    const Command alone = h.push(15, {std::nullopt, std::nullopt, PassivityParams::off()});
    QVERIFY(std::holds_alternative<v2::SetPassivity>(h.link.last().message));
    h.ack(h.lastSeq());
    QVERIFY(std::holds_alternative<v2::GetPassivity>(h.link.last().message));
    QVERIFY(alone.pushed());
    h.queue.onTuning({std::nullopt, std::nullopt, alone.pushed()->passivity});
    QCOMPARE(h.finished.size(), 1);
    const Outcome r = h.finished[0].outcome;
    QVERIFY(r.ok());
    QCOMPARE(readBackOf(r), std::optional(outcome::ReadBack::Matches));
    QVERIFY(r.pushed() && r.pushed()->passivity &&
            *r.pushed()->passivity == PassivityParams::off());
    QVERIFY(r.received.passivity.has_value());

    // All three blocks, SET_PASSIVITY unanswered: the parameters and effects are in force, the
    // passivity block unknown.
    const Command all = h.push(16, {DeviceParams{}, EffectParams{}, PassivityParams::off()});
    QVERIFY(all.pushed());
    h.ack(h.lastSeq());
    h.queue.onTuning({all.pushed()->params, std::nullopt});
    h.ack(h.lastSeq());
    h.queue.onTuning({std::nullopt, all.pushed()->effects});
    QVERIFY(std::holds_alternative<v2::SetPassivity>(h.link.last().message));
    QTRY_COMPARE_WITH_TIMEOUT(h.finished.size(), 2, 10 * CommandQueue::kCommandTimeoutMs);
    const Outcome timedOut = h.finished[1].outcome;
    const auto *stop = std::get_if<outcome::TimedOut>(&timedOut.result);
    QVERIFY(stop);
    QCOMPARE(stop->step, CommandKind::SetPassivity);
    QVERIFY(timedOut.stopped());
    const DeviceTuning &applied = timedOut.stopped()->applied;
    QVERIFY(applied.params && applied.effects && !applied.passivity);
    QCOMPARE(timedOut.unknownStep(), std::optional(CommandKind::SetPassivity));
}

void TestCommandQueue::aRefusedPartEndsThePush()
{
    Harness h;
    const Command c = h.push(14, {DeviceParams{}, EffectParams{}});
    QVERIFY(c.pushed());
    h.ack(h.lastSeq());
    h.queue.onTuning({c.pushed()->params, std::nullopt});
    h.ack(h.lastSeq(), v2::AckStatus::OutOfRange, 5); // SET_EFFECTS refused: wall_stiffness
    QCOMPARE(h.finished.size(), 1);
    const Outcome r = h.finished[0].outcome;
    const auto *refused = std::get_if<outcome::Refused>(&r.result);
    QVERIFY(refused);
    QCOMPARE(refused->step, CommandKind::SetEffects); // the frame refused
    QCOMPARE(refused->field, 5);
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
    QVERIFY(c.pushed());
    h.ack(h.lastSeq());
    EffectParams held = *c.pushed()->effects;
    held.wall_max = 0.25;
    h.queue.onTuning({std::nullopt, held});
    const Outcome r = h.finished.value(0).outcome;
    QVERIFY(r.ok());
    QCOMPARE(readBackOf(r), std::optional(outcome::ReadBack::Differs));
    QVERIFY(r.pushed());
    QCOMPARE(r.pushed()->effects.value().wall_max, 0.5);
    QCOMPARE(r.received.effects.value().wall_max, 0.25);
}

void TestCommandQueue::vibrateFinishesOnItsAck()
{
    Harness h;
    h.enqueue(13, request::Vibrate{{0.1, 80, 0.5}}, kEffectsDevice);
    const v2::Frame sent = h.link.last();
    const auto *cue = std::get_if<v2::Vibrate>(&sent.message);
    QVERIFY(cue);
    QCOMPARE(*cue, (v2::Vibrate{0.1f, 80.0f, 0.5f}));
    h.ack(h.lastSeq());
    QCOMPARE(h.finished.size(), 1); // no read-back: fire and forget
    QCOMPARE(h.link.writes.size(), 1);
    const Outcome r = h.finished[0].outcome;
    QVERIFY(r.ok());
    const auto *vibrate = std::get_if<request::Vibrate>(&r.request);
    QVERIFY(vibrate);
    QCOMPARE(vibrate->vibration, (Vibration{0.1, 80, 0.5}));
}

void TestCommandQueue::effectRejectionsNameTheirField()
{
    // A field the block has is named, by index and name; one beyond it (VIBRATE has three,
    // 0xFE is a knob the device lacks) names nothing.
    const Request params{request::Push{{DeviceParams{}, std::nullopt}}};
    const Request effects{request::Push{{std::nullopt, EffectParams{}}}};
    const Request passivity{request::Push{{std::nullopt, std::nullopt, PassivityParams{}}}};
    for (const auto &[request, step, field, named, name] :
         {std::tuple{params, CommandKind::SetParams, quint8(3), 3, "K_max"},
          std::tuple{params, CommandKind::SetParams, v2::kAxisField, -1, ""},
          std::tuple{effects, CommandKind::SetEffects, quint8(6), 6, "wall_damping"},
          std::tuple{passivity, CommandKind::SetPassivity, quint8(0), 0, "pc_damping_max"},
          std::tuple{Request{request::Vibrate{}}, CommandKind::Vibrate, quint8(1), 1, "frequency"},
          std::tuple{Request{request::Vibrate{}}, CommandKind::Vibrate, quint8(5), -1, ""}}) {
        Harness h;
        h.enqueue(14, request, kFullDevice);
        h.ack(h.lastSeq(), v2::AckStatus::OutOfRange, field);
        const Outcome r = h.finished.value(0).outcome;
        const auto *refused = std::get_if<outcome::Refused>(&r.result);
        QVERIFY(refused);
        QCOMPARE(refused->step, step);
        QCOMPARE(refused->field, named);
        QCOMPARE(refused->fieldName(), std::string_view(name));
        QVERIFY(h.acknowledged.isEmpty());
    }
}

void TestCommandQueue::okAckDoesNotAnswerGetEffects()
{
    Harness h;
    h.enqueue(15, request::Read{}, kEffectsDevice); // GET_PARAMS, GET_EFFECTS
    h.queue.onTuning({DeviceParams{}, std::nullopt});
    QVERIFY(std::holds_alternative<v2::GetEffects>(h.link.last().message));
    h.ack(h.lastSeq());
    QVERIFY(h.finished.isEmpty()); // only EFFECTS answers it
    h.ack(h.lastSeq(), v2::AckStatus::UnknownType);
    const Outcome r = h.finished.value(0).outcome;
    const auto *refused = std::get_if<outcome::Refused>(&r.result);
    QVERIFY(refused);
    QCOMPARE(refused->step, CommandKind::GetEffects);
}

void TestCommandQueue::okAckDoesNotAnswerGetParams()
{
    Harness h;
    h.enqueue(8, request::Read{});
    h.ack(h.lastSeq()); // GET_PARAMS is answered by PARAMS, not by an ACK
    QVERIFY(h.finished.isEmpty());
    h.ack(h.lastSeq(), v2::AckStatus::UnknownType); // …but a refusal ends it
    QCOMPARE(h.finished.size(), 1);
    const auto *refused = std::get_if<outcome::Refused>(&h.finished[0].outcome.result);
    QVERIFY(refused);
    QCOMPARE(refused->field, -1);
}

void TestCommandQueue::fullQueueRefusesAtOnce()
{
    Harness h;
    h.enqueue(1, request::Save{}); // in flight
    for (int i = 0; i < CommandQueue::kMaxQueuedCommands; ++i)
        h.enqueue(quint64(10 + i), request::Save{});
    QVERIFY(h.finished.isEmpty());
    h.enqueue(99, request::Read{});
    QCOMPARE(h.finished.size(), 1);
    QCOMPARE(h.finished[0].id, quint64(99));
    const Outcome r = h.finished[0].outcome;
    const auto *full = std::get_if<outcome::QueueFull>(&r.result);
    QVERIFY(full);
    QCOMPARE(full->limit, CommandQueue::kMaxQueuedCommands);
    QVERIFY(std::holds_alternative<request::Read>(r.request));
    QCOMPARE(h.link.writes.size(), 1);
}

void TestCommandQueue::failAllFinishesEverything()
{
    Harness h;
    h.push(1, {DeviceParams{}, std::nullopt});
    h.ack(h.lastSeq()); // now in its read-back stage
    h.enqueue(2, request::Save{});
    h.queue.failAll(outcome::Cut::Why::ConnectionLost);
    QCOMPARE(h.finished.size(), 2);
    for (const Finished &f : std::as_const(h.finished)) {
        const auto *cut = std::get_if<outcome::Cut>(&f.outcome.result);
        QVERIFY(cut);
        QCOMPARE(cut->why, outcome::Cut::Why::ConnectionLost);
    }
    // The step in flight (issue 27): a push cut in its read-back had its SET_PARAMS accepted,
    // and its outcome says so.
    const outcome::Stopped *cutPush = h.finished[0].outcome.stopped();
    const outcome::Stopped *cutSave = h.finished[1].outcome.stopped();
    QVERIFY(cutPush && cutSave);
    QCOMPARE(cutPush->step, CommandKind::GetParams);
    QVERIFY(cutPush->applied.params.has_value());
    QVERIFY(!cutSave->applied.params.has_value());
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
    h.enqueue(1, request::Read{});
    QVERIFY(h.link.writes.isEmpty());
    QVERIFY(!h.queue.busy());
    h.queue.setWriter([&h](const QByteArray &bytes) { h.link.writes.append(bytes); });
    QCOMPARE(h.link.writes.size(), 1);
    QVERIFY(h.queue.busy());
}

void TestCommandQueue::unansweredHelloIsReported()
{
    Harness h;
    h.queue.enqueueHello();
    QCOMPARE(h.link.writes.first().front(), '\0'); // led by a delimiter
    QTRY_COMPARE_WITH_TIMEOUT(h.helloUnanswered, 1, kAllRetriesMs);
    QVERIFY(h.finished.isEmpty()); // detection reports it, not an outcome
    QVERIFY(!h.queue.busy());

    // Answered: HELLO_REPLY clears it, and the next command goes out.
    h.queue.enqueueHello();
    h.enqueue(1, request::Read{});
    h.queue.onHelloReply();
    QVERIFY(std::holds_alternative<v2::GetParams>(h.link.last().message));
}

} // namespace hatpic

QTEST_GUILESS_MAIN(hatpic::TestCommandQueue)
#include "tst_commandqueue.moc"
