#include "session/recordingcontroller.h"

#include <QDateTime>

#include <algorithm>

namespace hatpic {

using namespace recording;

RecordingController::RecordingController(Session session, QObject *parent)
    : QObject(parent), m_session(std::move(session)), m_sink(this)
{
    connect(&m_sink, &RecordingSink::statusChanged, this, [this](const RecordingStatus &status) {
        // A file that closed itself (a write error) records nothing more.
        if (!m_sink.isOpen() && isRecording())
            m_state = Idle{};
        Q_EMIT statusChanged(status);
    });
    connect(&m_sink, &RecordingSink::aboutToFlush, this, [this] { m_session.flush(); });
}

bool RecordingController::isRecording() const
{
    return std::holds_alternative<Open>(m_state) || std::holds_alternative<Waiting>(m_state);
}

std::optional<double> RecordingController::lastTime() const
{
    return m_recent.empty() ? std::nullopt : std::optional(m_recent.back().t_s);
}

void RecordingController::start(const QString &csvPath, const QString &source,
                                const DeviceInfo &device, const RecordingPlan &plan)
{
    stop();
    m_state = Armed{csvPath, source, device, RecordingTrigger(plan)};
    if (plan.start == RecordingPlan::Start::Now)
        fire(lastTime());
    else
        m_sink.reportArmed(csvPath, triggerEventText(plan));
}

void RecordingController::disarm()
{
    if (const auto *armed = std::get_if<Armed>(&m_state)) {
        const QString path = armed->csvPath;
        m_state = Idle{};
        m_sink.reportDisarmed(path);
    }
}

void RecordingController::stop()
{
    disarm();
    if (!isRecording())
        return;
    m_session.flush(); // what came before the stop is recorded (unless the link is lost)
    m_state = Idle{};
    m_sink.close();
}

void RecordingController::fire(std::optional<double> anchor)
{
    const Armed armed = std::get<Armed>(m_state);
    m_state = Idle{};
    const RecordingPlan &plan = armed.trigger.plan();
    m_session.flush(); // samples that arrived before the start are only its pre-trigger span
    const DeviceTuning held = m_session.tuning();
    RecordingMetadata meta;
    meta.start = QDateTime::currentDateTimeUtc();
    meta.device = armed.device;
    meta.params = held.params.value_or(DeviceParams{});
    meta.effects = held.effects;
    meta.passivity = held.passivity;
    meta.host = m_session.host();
    meta.source = armed.source;
    if (!m_sink.open(armed.csvPath, meta))
        return;
    m_state = Open{armed.device, std::nullopt, 0};
    if (anchor && plan.preTrigger_s > 0) {
        SampleBatch before;
        for (const Sample &s : m_recent) {
            if (s.t_s > *anchor - plan.preTrigger_s)
                before.append(s);
        }
        m_sink.append(before);
    }
    if (plan.start != RecordingPlan::Start::Now || plan.preTrigger_s > 0)
        m_sink.addEvent(triggerEventText(plan));
    auto *open = std::get_if<Open>(&m_state); // none when the pre-trigger span failed to write
    if (open && plan.duration_s > 0) {
        if (anchor)
            open->stopAt = *anchor + plan.duration_s;
        else
            open->pendingDuration_s = plan.duration_s;
    }
}

void RecordingController::sample(const Sample &sample)
{
    if (auto *waiting = std::get_if<Waiting>(&m_state); waiting && waiting->reconnected) {
        if (!waiting->resumeBy)
            waiting->resumeBy = sample.t_s + kResumeWait_s;
        else if (sample.t_s > *waiting->resumeBy)
            resume(true); // the read-back never came: record without it, and say so
    }
    if (auto *armed = std::get_if<Armed>(&m_state); armed && armed->trigger.feed(sample))
        fire(sample.t_s);
    keepRecent(sample);
}

void RecordingController::keepRecent(const Sample &sample)
{
    m_recent.push_back(sample);
    const double oldest = sample.t_s - RecordingPlan::kMaxPreTrigger_s;
    while (!m_recent.empty() && (m_recent.front().t_s < oldest ||
                                 static_cast<qsizetype>(m_recent.size()) > kMaxRecentSamples))
        m_recent.pop_front();
}

void RecordingController::record(const SampleBatch &batch)
{
    auto *open = std::get_if<Open>(&m_state);
    if (!open || batch.isEmpty())
        return;
    if (open->pendingDuration_s > 0) {
        open->stopAt = batch.constFirst().t_s + open->pendingDuration_s;
        open->pendingDuration_s = 0;
    }
    if (!open->stopAt) {
        m_sink.append(batch);
        return;
    }
    const double stopAt = *open->stopAt;
    const auto end = std::find_if(batch.cbegin(), batch.cend(),
                                  [stopAt](const Sample &s) { return s.t_s > stopAt; });
    if (end == batch.cend()) {
        m_sink.append(batch);
        return;
    }
    m_sink.append(batch.first(end - batch.cbegin()));
    m_state = Idle{};
    m_sink.close();
}

void RecordingController::connectionStarted(const DeviceInfo &device)
{
    auto *waiting = std::get_if<Waiting>(&m_state);
    if (!waiting)
        return;
    // One file, one device: its metadata names the device and its tau_limit.
    if (const QStringList differences = describeDeviceChange(waiting->open.device, device);
        !differences.isEmpty()) {
        m_state = Idle{};
        m_sink.closeForOtherDevice(differences);
        Q_EMIT notice({SessionNotice::Kind::RecordingClosedOtherDevice, differences});
        return;
    }
    // Rows resume once the device has told what it holds, so the first row after the gap
    // carries every change against the parameters before it.
    waiting->reconnected = true;
    waiting->pending = {device.canSetParams() ? std::optional(DeviceParams{}) : std::nullopt,
                        device.hasEffects() ? std::optional(EffectParams{}) : std::nullopt,
                        device.hasPassivity() ? std::optional(PassivityParams{}) : std::nullopt};
    waiting->resumeBy.reset();
    waiting->changes.clear();
    resumeIfReady();
}

void RecordingController::connectionEnded(const StateDetail &lost, bool reconnecting)
{
    disarm(); // an armed recording waits for no lost device
    if (!isRecording())
        return;
    if (!reconnecting) {
        stop();
        Q_EMIT notice({SessionNotice::Kind::RecordingClosedByLoss, {}});
        return;
    }
    if (auto *waiting = std::get_if<Waiting>(&m_state)) { // lost again before rows resumed
        waiting->reconnected = false;
        return;
    }
    Waiting waiting;
    waiting.open = std::get<Open>(m_state);
    waiting.held = m_session.tuning();
    m_state = waiting;
    m_sink.suspend(lastTime().value_or(0.0), lost);
    Q_EMIT notice({SessionNotice::Kind::RecordingWaitsForDevice, {}});
}

void RecordingController::resumeIfReady()
{
    const auto *waiting = std::get_if<Waiting>(&m_state);
    if (waiting && waiting->reconnected && waiting->pending == DeviceTuning{})
        resume(false);
}

void RecordingController::resume(bool unread)
{
    m_session.flush(); // the samples waiting came before the device's state was known: not recorded
    const Waiting waiting = std::get<Waiting>(m_state);
    m_state = waiting.open;
    m_sink.resume(waiting.changes, unread);
    Q_EMIT notice({SessionNotice::Kind::RecordingResumed, {}});
}

void RecordingController::tuningApplied(const DeviceTuning &applied)
{
    if (const auto *armed = std::get_if<Armed>(&m_state);
        armed && armed->trigger.plan().start == RecordingPlan::Start::NextPush)
        fire(lastTime());
    m_sink.tuningApplied(m_session.tuning(), applied);
}

void RecordingController::zeroed(double theta0Before)
{
    m_sink.zeroed(theta0Before);
}

void RecordingController::tuningReceived(const DeviceTuning &known, const DeviceTuning &told)
{
    const DeviceTuning held = m_session.tuning();
    if (!sameOnWire(held.updatedBy(known), held)) {
        m_session.flush();
        m_sink.tuningReadBack(held, known);
    }
    auto *waiting = std::get_if<Waiting>(&m_state);
    if (!waiting || !waiting->reconnected)
        return;
    // The parts a device back after a loss had yet to tell, as told now.
    const DeviceTuning now{waiting->pending.params ? told.params : std::nullopt,
                           waiting->pending.effects ? told.effects : std::nullopt,
                           waiting->pending.passivity ? told.passivity : std::nullopt};
    if (now == DeviceTuning{})
        return;
    DeviceTuning compared = now; // blocks compared only when known at the loss
    if (!waiting->held.effects)
        compared.effects.reset();
    if (!waiting->held.passivity)
        compared.passivity.reset();
    m_session.flush(); // a waiting recording takes no rows: the state stays as it is
    if (const QString change = describeTuningChange(waiting->held, compared); !change.isEmpty())
        waiting->changes << change;
    if (now.params)
        waiting->pending.params.reset();
    if (now.effects)
        waiting->pending.effects.reset();
    if (now.passivity)
        waiting->pending.passivity.reset();
}

void RecordingController::hostChanged(const HostParams &from, const HostParams &to)
{
    m_sink.hostChanged(from, to);
}

void RecordingController::referenceReset()
{
    m_sink.referenceReset();
}

} // namespace hatpic
