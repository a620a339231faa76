// Where complete samples go: each one at once to the sample listeners (the robot path), then
// in batches to the session's users (samplesReady at least every kBatchIntervalMs, or sooner
// when kBatchMaxSamples wait) and the recording, with the events that mark on the right row
// when a change was applied. Holds the SampleBuilder, so the host's copy
// of the device parameters and the host parameters change here, in step with the events.
#pragma once

#include "session/recordingsink.h"
#include "session/samplebuilder.h"
#include "session/samplelisteners.h"
#include "session/sessiontypes.h"
#include "telemetry/recordingtrigger.h"
#include "telemetry/sample.h"

#include <QObject>
#include <QTimer>

#include <deque>
#include <optional>

namespace hatpic {

class SamplePipeline : public QObject
{
    Q_OBJECT
public:
    static constexpr int kBatchIntervalMs = 20; //!< samplesReady() at least this often [ms]
    static constexpr int kBatchMaxSamples = 64; //!< …or when this many samples wait
    //! Recent samples kept for a recording's pre-trigger span: those of the last
    //! RecordingPlan::kMaxPreTrigger_s, and never more than this many.
    static constexpr qsizetype kMaxRecentSamples = 50'000;
    //! After a reconnect, a waiting recording resumes at the latest this long after the first
    //! sample, even when the device's parameters were not read back [s].
    static constexpr double kResumeWait_s = 2.0;

    explicit SamplePipeline(QObject *parent = nullptr);

    SampleBuilder &builder() { return m_builder; }
    //! Who takes each sample as it comes, before any batch (the robot path); thread-safe.
    SampleListeners &listeners() { return m_listeners; }
    const SampleBuilder &builder() const { return m_builder; }

    //! A new connectDevice(): t_s, p_ref and the gap count start over.
    void clear()
    {
        m_builder.clear();
        m_recent.clear();
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
                        const RecordingPlan &plan = {});
    //! Closes the recording, or calls off an armed one.
    void stopRecording();
    bool isRecording() const { return m_recording.isOpen(); }
    bool isArmed() const { return m_armed.has_value(); }

Q_SIGNALS:
    void samplesReady(const hatpic::SampleBatch &batch);
    void recordingChanged(const hatpic::RecordingStatus &status);
    //! The device's tuning as read: each part once the device has told it on this connection.
    void deviceTuningChanged(const hatpic::DeviceTuning &tuning);
    //! The recording waits for, resumed after or closed at a link loss.
    void notice(const hatpic::SessionNotice &notice);

private:
    //! A recording across a link loss: what held when the link was lost, and what the device
    //! that came back has told so far.
    struct Gap
    {
        DeviceTuning held; //!< the device's tuning at the loss (effects: when known)
        bool reconnected = false;
        //! The parts the device that came back has yet to tell (effects: a device with them)
        DeviceTuning pending;
        std::optional<double> resumeBy; //!< t_s after which rows resume regardless [s]
        QStringList changes; //!< what the device holds differently now ("K_max 0.6 → 0.4")
    };
    struct Armed
    {
        QString csvPath;
        QString source;
        DeviceInfo device;
        RecordingTrigger trigger;
    };
    //! Opens the armed recording: the recent samples after `anchor` − pre-trigger span, then
    //! (for a trigger) its event on the next sample; the length counts from `anchor`.
    void fire(std::optional<double> anchor);
    void keepRecent(const Sample &sample);
    //! Appends to the recording up to its end time, and closes it there.
    void record(const SampleBatch &batch);
    //! The device that came back has told its tuning: rows resume.
    void resumeIfReady();
    //! Rows resume after the gap; `unread`: without the device's parameters read back.
    void resume(bool unread);

    SampleBuilder m_builder;
    SampleListeners m_listeners;
    SampleBatch m_batch;
    QTimer m_batchTimer;
    RecordingSink m_recording;
    //! The device's tuning as the host believes it: each part once told on this connection
    //! (its parameters also live in the builder, which renders with them from the start).
    DeviceTuning m_device;
    std::deque<Sample> m_recent;
    std::optional<Armed> m_armed;
    DeviceInfo m_recordingDevice;   //!< the device the open recording records
    std::optional<Gap> m_gap;       //!< the open recording waits after a link loss
    std::optional<double> m_stopAt; //!< the recording closes after its last sample here [s]
    double m_pendingDuration_s = 0; //!< a length to count from the first sample recorded [s]
};

} // namespace hatpic
