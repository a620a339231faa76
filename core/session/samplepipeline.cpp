#include "samplepipeline.h"

#include <QDateTime>

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

void SamplePipeline::connectionStarted()
{
    m_paramsKnown = false;
    m_effectsKnown = false;
    m_effects = {};
    m_builder.markDiscontinuity();
    m_batchTimer.start();
}

void SamplePipeline::connectionEnded()
{
    flush();
    m_builder.markDiscontinuity();
}

void SamplePipeline::stop()
{
    m_batchTimer.stop();
}

void SamplePipeline::push(const Sample &sample)
{
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
    m_recording.append(batch);
    Q_EMIT samplesReady(batch);
}

void SamplePipeline::applyEffect(CommandKind kind, const DeviceParams &params)
{
    flush(); // the event belongs to the next sample, not to those already waiting
    if (kind == CommandKind::Zero) {
        m_recording.zeroed(m_builder.deviceParams().theta0);
        return;
    }
    m_recording.paramsApplied(m_builder.deviceParams(), params);
    m_builder.setDeviceParams(params);
}

void SamplePipeline::paramsReceived(const DeviceParams &params)
{
    const DeviceParams held = m_builder.deviceParams();
    if (m_paramsKnown && !sameOnWire(held, params)) {
        flush();
        m_recording.paramsReadBack(held, params);
    }
    m_builder.setDeviceParams(params);
    m_paramsKnown = true;
    Q_EMIT deviceParamsChanged(params);
}

void SamplePipeline::effectsApplied(const EffectParams &effects)
{
    flush(); // the event belongs to the next sample, not to those already waiting
    m_recording.effectsApplied(m_effects, effects);
    m_effects = effects;
}

void SamplePipeline::effectsReceived(const EffectParams &effects)
{
    if (m_effectsKnown && !sameOnWire(m_effects, effects)) {
        flush();
        m_recording.effectsReadBack(m_effects, effects);
    }
    m_effects = effects;
    m_effectsKnown = true;
    Q_EMIT deviceEffectsChanged(effects);
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
                                    const DeviceInfo &device)
{
    stopRecording();
    flush(); // samples that arrived before the start are not part of the recording
    RecordingMetadata meta;
    meta.start = QDateTime::currentDateTimeUtc();
    meta.device = device;
    meta.params = m_builder.deviceParams();
    if (m_effectsKnown)
        meta.effects = m_effects;
    meta.host = m_builder.hostParams();
    meta.source = source;
    m_recording.open(csvPath, meta);
}

void SamplePipeline::stopRecording()
{
    if (!m_recording.isOpen())
        return;
    flush();
    m_recording.close();
}

} // namespace hatpic
