#include "samplepipeline.h"

#include <QDateTime>

#include <algorithm>

namespace hatpic {

SamplePipeline::SamplePipeline(QObject *parent)
    : QObject(parent), m_batchTimer(this), m_recording(this)
{
    m_batchTimer.setTimerType(Qt::PreciseTimer);
    m_batchTimer.setInterval(kBatchIntervalMs);
    connect(&m_batchTimer, &QTimer::timeout, this, &SamplePipeline::flush);
    connect(&m_recording, &RecordingSink::statusChanged, this, &SamplePipeline::recordingChanged);
    connect(&m_recording, &RecordingSink::aboutToFlush, this, &SamplePipeline::flush);
}

void SamplePipeline::connectionStarted(const DeviceInfo &device)
{
    m_device = {};
    m_builder.markDiscontinuity();
    m_batchTimer.start();
    if (!m_gap)
        return;
    if (!m_recording.isOpen()) {
        m_gap.reset();
        return;
    }
    // One file, one device: its metadata names the device and its tau_limit.
    if (const QStringList differences = describeDeviceChange(m_recordingDevice, device);
        !differences.isEmpty()) {
        m_gap.reset();
        m_stopAt.reset();
        m_pendingDuration_s = 0;
        m_recording.closeForOtherDevice(differences);
        Q_EMIT notice({SessionNotice::Kind::RecordingClosedOtherDevice, differences});
        return;
    }
    // Rows resume once the device has told what it holds, so the first row after the gap
    // carries every change against the parameters before it.
    m_gap->reconnected = true;
    m_gap->pending = {device.canSetParams() ? std::optional(DeviceParams{}) : std::nullopt,
                      device.hasEffects() ? std::optional(EffectParams{}) : std::nullopt,
                      device.hasPassivity() ? std::optional(PassivityParams{}) : std::nullopt};
    m_gap->resumeBy.reset();
    m_gap->changes.clear();
    resumeIfReady();
}

void SamplePipeline::connectionEnded(const StateDetail &lost, bool reconnecting)
{
    flush();
    m_builder.markDiscontinuity();
    if (m_armed) { // an armed recording waits for no lost device
        const QString path = m_armed->csvPath;
        m_armed.reset();
        m_recording.reportDisarmed(path);
    }
    if (!m_recording.isOpen())
        return;
    if (!reconnecting) {
        stopRecording();
        Q_EMIT notice({SessionNotice::Kind::RecordingClosedByLoss, {}});
        return;
    }
    if (m_gap) { // lost again before the rows resumed: the same gap goes on
        m_gap->reconnected = false;
        return;
    }
    Gap gap;
    gap.held = {m_builder.deviceParams(), m_device.effects, m_device.passivity};
    m_gap = gap;
    m_recording.suspend(m_recent.empty() ? 0.0 : m_recent.back().t_s, lost);
    Q_EMIT notice({SessionNotice::Kind::RecordingWaitsForDevice, {}});
}

void SamplePipeline::resumeIfReady()
{
    if (m_gap && m_gap->reconnected && m_gap->pending == DeviceTuning{})
        resume(false);
}

void SamplePipeline::resume(bool unread)
{
    flush(); // the samples waiting came before the device's state was known: not recorded
    const QStringList changes = m_gap->changes;
    m_gap.reset();
    m_recording.resume(changes, unread);
    Q_EMIT notice({SessionNotice::Kind::RecordingResumed, {}});
}

void SamplePipeline::stop()
{
    m_batchTimer.stop();
}

void SamplePipeline::push(const Sample &decoded)
{
    Sample sample = decoded;
    sample.arrival_ns = sampleClockNs();
    m_listeners.dispatch(sample);
    if (m_gap && m_gap->reconnected) {
        if (!m_gap->resumeBy)
            m_gap->resumeBy = sample.t_s + kResumeWait_s;
        else if (sample.t_s > *m_gap->resumeBy)
            resume(true); // the read-back never came: record without it, and say so
    }
    if (m_armed && m_armed->trigger.feed(sample))
        fire(sample.t_s);
    keepRecent(sample);
    m_batch.append(sample);
    if (m_batch.size() >= kBatchMaxSamples)
        flush();
}

void SamplePipeline::flush()
{
    if (m_batch.isEmpty())
        return;
    SampleBatch batch;
    batch.swap(m_batch);
    m_batch.reserve(kBatchMaxSamples);
    record(batch);
    Q_EMIT samplesReady(batch);
}

void SamplePipeline::keepRecent(const Sample &sample)
{
    m_recent.push_back(sample);
    const double oldest = sample.t_s - RecordingPlan::kMaxPreTrigger_s;
    while (!m_recent.empty() && (m_recent.front().t_s < oldest ||
                                 static_cast<qsizetype>(m_recent.size()) > kMaxRecentSamples))
        m_recent.pop_front();
}

void SamplePipeline::record(const SampleBatch &batch)
{
    if (!m_recording.isOpen() || m_gap || batch.isEmpty())
        return;
    if (m_pendingDuration_s > 0) {
        m_stopAt = batch.constFirst().t_s + m_pendingDuration_s;
        m_pendingDuration_s = 0;
    }
    if (!m_stopAt) {
        m_recording.append(batch);
        return;
    }
    const double stopAt = *m_stopAt;
    const auto end = std::find_if(batch.cbegin(), batch.cend(),
                                  [stopAt](const Sample &s) { return s.t_s > stopAt; });
    if (end == batch.cend()) {
        m_recording.append(batch);
        return;
    }
    m_recording.append(batch.first(end - batch.cbegin()));
    m_stopAt.reset();
    m_recording.close();
}

void SamplePipeline::tuningApplied(CommandKind kind, const DeviceTuning &applied)
{
    flush(); // the event belongs to the next sample, not to those already waiting
    if (kind == CommandKind::Zero) {
        m_recording.zeroed(m_builder.deviceParams().theta0);
        return;
    }
    if (m_armed && m_armed->trigger.plan().start == RecordingPlan::Start::NextPush)
        fire(m_recent.empty() ? std::nullopt : std::optional(m_recent.back().t_s));
    m_recording.tuningApplied({m_builder.deviceParams(), m_device.effects, m_device.passivity},
                              applied);
    if (applied.params)
        m_builder.setDeviceParams(*applied.params);
    if (applied.effects)
        m_device.effects = applied.effects;
    if (applied.passivity)
        m_device.passivity = applied.passivity;
}

void SamplePipeline::tuningReceived(const DeviceTuning &told)
{
    const DeviceTuning held{m_builder.deviceParams(), m_device.effects, m_device.passivity};
    // What this connection already knew and the device now tells differently.
    const DeviceTuning known{told.params && m_device.params ? told.params : std::nullopt,
                             told.effects && m_device.effects ? told.effects : std::nullopt,
                             told.passivity && m_device.passivity ? told.passivity : std::nullopt};
    if (!sameOnWire(held.updatedBy(known), held)) {
        flush();
        m_recording.tuningReadBack(held, known);
    }
    // The parts a device back after a loss had yet to tell, as told now.
    const DeviceTuning now =
        m_gap && m_gap->reconnected
            ? DeviceTuning{m_gap->pending.params ? told.params : std::nullopt,
                           m_gap->pending.effects ? told.effects : std::nullopt,
                           m_gap->pending.passivity ? told.passivity : std::nullopt}
            : DeviceTuning{};
    if (now != DeviceTuning{}) {
        DeviceTuning compared = now; // effects compared only when known at the loss
        if (!m_gap->held.effects)
            compared.effects.reset();
        if (!m_gap->held.passivity)
            compared.passivity.reset();
        flush();
        if (const QString change = describeTuningChange(m_gap->held, compared); !change.isEmpty())
            m_gap->changes << change;
        if (now.params)
            m_gap->pending.params.reset();
        if (now.effects)
            m_gap->pending.effects.reset();
        if (now.passivity)
            m_gap->pending.passivity.reset();
    }
    if (told.params)
        m_builder.setDeviceParams(*told.params);
    m_device = m_device.updatedBy(told);
    Q_EMIT deviceTuningChanged(m_device);
    resumeIfReady();
}

bool SamplePipeline::setHostParams(const HostParams &host)
{
    const HostParams old = m_builder.hostParams();
    if (old == host)
        return false;
    flush();
    m_builder.setHostParams(host);
    m_recording.hostChanged(old, host);
    return true;
}

void SamplePipeline::resetReference()
{
    flush();
    m_builder.resetReference();
    m_recording.referenceReset();
}

void SamplePipeline::startRecording(const QString &csvPath, const QString &source,
                                    const DeviceInfo &device, const RecordingPlan &plan)
{
    stopRecording();
    m_armed = Armed{csvPath, source, device, RecordingTrigger(plan)};
    if (plan.start == RecordingPlan::Start::Now)
        fire(m_recent.empty() ? std::nullopt : std::optional(m_recent.back().t_s));
    else
        m_recording.reportArmed(csvPath, triggerEventText(m_armed->trigger.plan()));
}

void SamplePipeline::fire(std::optional<double> anchor)
{
    const Armed armed = *m_armed;
    m_armed.reset();
    const RecordingPlan &plan = armed.trigger.plan();
    flush(); // samples that arrived before the start are only recorded as pre-trigger span
    RecordingMetadata meta;
    meta.start = QDateTime::currentDateTimeUtc();
    meta.device = armed.device;
    meta.params = m_builder.deviceParams();
    meta.effects = m_device.effects;
    meta.passivity = m_device.passivity;
    meta.host = m_builder.hostParams();
    meta.source = armed.source;
    m_gap.reset();
    if (!m_recording.open(armed.csvPath, meta))
        return;
    m_recordingDevice = armed.device;
    m_stopAt.reset();
    m_pendingDuration_s = 0;
    if (anchor && plan.preTrigger_s > 0) {
        SampleBatch before;
        for (const Sample &s : m_recent) {
            if (s.t_s > *anchor - plan.preTrigger_s)
                before.append(s);
        }
        m_recording.append(before);
    }
    if (plan.start != RecordingPlan::Start::Now || plan.preTrigger_s > 0)
        m_recording.addEvent(triggerEventText(plan));
    if (plan.duration_s > 0) {
        if (anchor)
            m_stopAt = *anchor + plan.duration_s;
        else
            m_pendingDuration_s = plan.duration_s;
    }
}

void SamplePipeline::stopRecording()
{
    if (m_armed) {
        const QString path = m_armed->csvPath;
        m_armed.reset();
        m_recording.reportDisarmed(path);
    }
    if (!m_recording.isOpen())
        return;
    flush();
    m_stopAt.reset();
    m_pendingDuration_s = 0;
    m_gap.reset();
    m_recording.close();
}

} // namespace hatpic
