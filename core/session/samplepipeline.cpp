#include "samplepipeline.h"

namespace hatpic {

SamplePipeline::SamplePipeline(QObject *parent)
    : QObject(parent), m_batchTimer(this),
      m_recording({[this] { flush(); }, [this] { return held(); },
                   [this] { return m_builder.hostParams(); }},
                  this)
{
    m_batchTimer.setTimerType(Qt::PreciseTimer);
    m_batchTimer.setInterval(kBatchIntervalMs);
    connect(&m_batchTimer, &QTimer::timeout, this, &SamplePipeline::flush);
    connect(&m_recording, &RecordingController::statusChanged, this,
            &SamplePipeline::recordingChanged);
    connect(&m_recording, &RecordingController::notice, this, &SamplePipeline::notice);
}

DeviceTuning SamplePipeline::held() const
{
    return {m_builder.deviceParams(), m_device.effects, m_device.passivity};
}

void SamplePipeline::connectionStarted(const DeviceInfo &device)
{
    m_device = {};
    m_builder.markDiscontinuity();
    m_batchTimer.start();
    m_recording.connectionStarted(device);
}

void SamplePipeline::connectionEnded(const StateDetail &lost, bool reconnecting)
{
    flush();
    m_builder.markDiscontinuity();
    m_recording.connectionEnded(lost, reconnecting);
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
    m_recording.sample(sample);
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
    m_recording.record(batch);
    Q_EMIT samplesReady(batch);
}

void SamplePipeline::tuningApplied(CommandKind kind, const DeviceTuning &applied)
{
    flush(); // the event belongs to the next sample, not to those already waiting
    if (kind == CommandKind::Zero) {
        m_recording.zeroed(m_builder.deviceParams().theta0);
        return;
    }
    m_recording.tuningApplied(applied);
    if (applied.params)
        m_builder.setDeviceParams(*applied.params);
    if (applied.effects)
        m_device.effects = applied.effects;
    if (applied.passivity)
        m_device.passivity = applied.passivity;
}

void SamplePipeline::tuningReceived(const DeviceTuning &told)
{
    // What this connection already knew and the device now tells differently.
    const DeviceTuning known{told.params && m_device.params ? told.params : std::nullopt,
                             told.effects && m_device.effects ? told.effects : std::nullopt,
                             told.passivity && m_device.passivity ? told.passivity : std::nullopt};
    m_recording.tuningReceived(known, told);
    if (told.params)
        m_builder.setDeviceParams(*told.params);
    m_device = m_device.updatedBy(told);
    Q_EMIT deviceTuningChanged(m_device);
    m_recording.resumeIfReady();
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

} // namespace hatpic
