// Where complete samples go: the batches to the session's users (samplesReady at least every
// kBatchIntervalMs, or sooner when kBatchMaxSamples wait), the recording, and the events that
// mark on the right row when a change took effect. Holds the SampleBuilder, so the host's copy
// of the device parameters and the host parameters change here, in step with the events.
#pragma once

#include "session/recordingsink.h"
#include "session/samplebuilder.h"
#include "session/sessiontypes.h"
#include "telemetry/sample.h"

#include <QObject>
#include <QTimer>

namespace hatpic {

class SamplePipeline : public QObject
{
    Q_OBJECT
public:
    static constexpr int kBatchIntervalMs = 20; //!< samplesReady() at least this often [ms]
    static constexpr int kBatchMaxSamples = 64; //!< …or when this many samples wait

    explicit SamplePipeline(QObject *parent = nullptr);

    SampleBuilder &builder() { return m_builder; }
    const SampleBuilder &builder() const { return m_builder; }

    //! A new connectDevice(): t_s, p_ref and the gap count start over.
    void clear() { m_builder.clear(); }
    //! A connection began: its first PARAMS sets the copy without an event; batches flow.
    void connectionStarted();
    //! The link is gone: hands on the samples waiting; t_s follows host time across the gap.
    void connectionEnded();
    //! Stops the batch timer (shutdown).
    void stop();

    void push(const Sample &sample);
    //! Hands on the samples waiting (to the recording and samplesReady).
    void flush();

    //! SET_PARAMS (`params`) or ZERO took effect on the device: from the next sample on.
    void applyEffect(CommandKind kind, const DeviceParams &params);
    //! A PARAMS message: the copy follows it (an event when it differs from what was held).
    void paramsReceived(const DeviceParams &params);
    //! SET_EFFECTS (`effects`) took effect on the device: from the next sample on.
    void effectsApplied(const EffectParams &effects);
    //! An EFFECTS message: the copy follows it (an event when it differs from what was held).
    void effectsReceived(const EffectParams &effects);
    const EffectParams &deviceEffects() const { return m_effects; }
    //! False when `host` equals the parameters in force (nothing changed).
    bool setHostParams(const HostParams &host);
    void resetReference();

    //! Starts a recording of `device`; a running one is closed first.
    void startRecording(const QString &csvPath, const QString &source, const DeviceInfo &device);
    void stopRecording();
    bool isRecording() const { return m_recording.isOpen(); }

Q_SIGNALS:
    void samplesReady(const hatpic::SampleBatch &batch);
    void recordingChanged(const hatpic::RecordingStatus &status);
    void deviceParamsChanged(const hatpic::DeviceParams &params);
    void deviceEffectsChanged(const hatpic::EffectParams &effects);

private:
    SampleBuilder m_builder;
    SampleBatch m_batch;
    QTimer m_batchTimer;
    RecordingSink m_recording;
    bool m_paramsKnown = false;  //!< a PARAMS arrived on this connection
    EffectParams m_effects;      //!< the device's effect block as the host believes it
    bool m_effectsKnown = false; //!< an EFFECTS arrived on this connection
};

} // namespace hatpic
