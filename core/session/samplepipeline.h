// Where complete samples go: each one at once to the sample listeners (the robot path), then
// in batches to the session's users (samplesReady at least every kBatchIntervalMs, or sooner
// when kBatchMaxSamples wait) and to the recording (RecordingController, which it owns and
// hands every sample, batch and change), with the events that mark on the right row when a
// change was applied. Holds the SampleBuilder, so the host's copy of the device parameters and
// the host parameters change here, in step with the events.
#pragma once

#include "session/recordingcontroller.h"
#include "session/samplebuilder.h"
#include "session/samplelisteners.h"
#include "session/sessiontypes.h"
#include "telemetry/sample.h"

#include <QObject>
#include <QTimer>

#include <optional>

namespace hatpic {

class SamplePipeline : public QObject
{
    Q_OBJECT
public:
    static constexpr int kBatchIntervalMs = 20; //!< samplesReady() at least this often [ms]
    static constexpr int kBatchMaxSamples = 64; //!< …or when this many samples wait

    explicit SamplePipeline(QObject *parent = nullptr);

    SampleBuilder &builder() { return m_builder; }
    //! Who takes each sample as it comes, before any batch (the robot path); thread-safe.
    SampleListeners &listeners() { return m_listeners; }
    const SampleBuilder &builder() const { return m_builder; }

    //! A new connectDevice(): t_s, p_ref and the gap count start over.
    void clear()
    {
        m_builder.clear();
        m_recording.clearRecent();
    }
    //! A connection to `device` began: its first PARAMS sets the copy without an event;
    //! batches flow. A recording that waits after a loss resumes when `device` is the one it
    //! records (once its parameters and effects are read back), and closes when it is not.
    void connectionStarted(const DeviceInfo &device);
    //! The link is gone (`lost`): hands on the samples waiting; t_s follows host time across
    //! the gap. A recording waits for the device when the session is `reconnecting`, and
    //! closes when it is not; an armed one is called off.
    void connectionEnded(const StateDetail &lost, bool reconnecting);
    //! Stops the batch timer (shutdown).
    void stop();

    //! A complete sample: stamped with its arrival, to the listeners at once, then batched.
    void push(const Sample &sample);
    //! Hands on the samples waiting (to the recording and samplesReady).
    void flush();

    //! The device applied a change (`kind` SET_PARAMS or SET_EFFECTS: the part `applied`
    //! carries; ZERO): it holds from the next sample on.
    void tuningApplied(CommandKind kind, const DeviceTuning &applied);
    //! A PARAMS or EFFECTS (`told` has its part): the device's tuning follows it (an event when
    //! it differs from what was held), and deviceTuningChanged() says so.
    void tuningReceived(const DeviceTuning &told);
    //! False when `host` equals the parameters in force (nothing changed).
    bool setHostParams(const HostParams &host);
    void resetReference();

    //! Starts a recording of `device` as `plan` says (now, or armed until its trigger, with
    //! its pre-trigger span from the recent samples and its length); a running or armed one is
    //! closed first. A recording with a length closes itself after its last sample.
    void startRecording(const QString &csvPath, const QString &source, const DeviceInfo &device,
                        const RecordingPlan &plan = {})
    {
        m_recording.start(csvPath, source, device, plan);
    }
    //! Closes the recording, or calls off an armed one.
    void stopRecording() { m_recording.stop(); }
    const RecordingController &recording() const { return m_recording; }
    bool isRecording() const { return m_recording.isRecording(); }
    bool isArmed() const { return m_recording.isArmed(); }

Q_SIGNALS:
    void samplesReady(const hatpic::SampleBatch &batch);
    void recordingChanged(const hatpic::RecordingStatus &status);
    //! The device's tuning as read: each part once the device has told it on this connection.
    void deviceTuningChanged(const hatpic::DeviceTuning &tuning);
    //! The recording waits for, resumed after or closed at a link loss.
    void notice(const hatpic::SessionNotice &notice);

private:
    //! The device's tuning in force: the builder's parameters, the blocks as known.
    DeviceTuning held() const;

    SampleBuilder m_builder;
    SampleListeners m_listeners;
    SampleBatch m_batch;
    QTimer m_batchTimer;
    //! The device's tuning as the host believes it: each part once told on this connection
    //! (its parameters also live in the builder, which renders with them from the start).
    DeviceTuning m_device;
    RecordingController m_recording;
};

} // namespace hatpic
