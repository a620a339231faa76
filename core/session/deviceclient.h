// The application's handle on a joystick: owns the session thread, forwards commands to it,
// and delivers the session's signals on the owner's thread. All methods return immediately.
#pragma once

#include "session/sessiontypes.h"
#include "telemetry/recordingtrigger.h"
#include "telemetry/sample.h"

#include <QObject>
#include <QPointer>

#include <atomic>
#include <functional>
#include <mutex>
#include <string>

class QThread;

namespace hatpic {

class DeviceSession;
class SampleListener;

//! Where a request's outcome goes: `done` is called once, on the client's thread, when the
//! request ends — done, refused, timed out, cut short or not sent (the Outcome says which) —
//! unless `context` is gone by then. `context` is the object whose state `done` touches.
//! Empty: nobody waits for the outcome. Nothing is broadcast: the caller alone hears.
struct CommandDone
{
    QPointer<QObject> context;
    std::function<void(const Outcome &)> done;
};

class DeviceClient : public QObject
{
    Q_OBJECT
public:
    //! Deliveries that may wait on this object's thread at once; beyond that the session
    //! drops the newest, so a frozen GUI thread never makes the event queue grow unbounded.
    static constexpr int kMaxPendingBatches = 100;  //!< samplesReady (≥ 2 s of samples)
    static constexpr int kMaxPendingStats = 4;      //!< statsUpdated, recording progress
    static constexpr int kMaxPendingLogLines = 256; //!< deviceLog

    explicit DeviceClient(QObject *parent = nullptr);
    ~DeviceClient() override; //!< closes the session and joins its thread

    void connectDevice(const ConnectOptions &options);
    void disconnectDevice();

    //! Empty once the session thread runs SCHED_FIFO (realtime::kPriority), else the sentence
    //! saying why it does not (performance.md § The loop with the CPU busy); empty before the
    //! thread started. Any thread.
    std::string realtimeProblem() const;

    //! Sends `request` (request.h; DeviceSession::request() checks it); it ends once, with its
    //! outcome given to `then`.
    void request(const Request &request, CommandDone then = {});

    //! τ_ext streamed to the device [N·m]: sent at once, within ConnectOptions'
    //! feedbackRateHz. Callable from any thread (the robot path calls it from the
    //! middleware's). This one sets knob 1's; the other knobs' stay as they are.
    void setFeedback(double tauExt);
    //! Every knob's τ_ext at once, knob 1 first (a device with fewer knobs ignores the rest).
    void setFeedback(const AxisTorques &tauExt);
    void setHostParams(const HostParams &host); //!< reference model settings
    void resetReference();                      //!< p_ref := 0

    //! `listener` gets every sample on the session thread the moment it is decoded, before
    //! any batch (samplelisteners.h): the robot path. Callable from any thread.
    void addSampleListener(SampleListener *listener);
    //! After it returns, `listener` is never called again. Callable from any thread.
    void removeSampleListener(SampleListener *listener);

    //! Records to `csvPath` (+ NAME.json); `source` names the program in the metadata.
    void startRecording(const QString &csvPath,
                        const QString &source = QStringLiteral("hatpic-tuner"));
    //! Records as `plan` says: now or armed until its trigger, with a pre-trigger span and a
    //! length (recordingtrigger.h). recordingChanged reports the armed state.
    void startRecording(const QString &csvPath, const RecordingPlan &plan,
                        const QString &source = QStringLiteral("hatpic-tuner"));
    //! Stops the recording or calls off an armed one.
    void stopRecording();

    // Last values seen on this thread (updated before the matching signal is emitted).
    SessionState state() const { return m_state; }
    DeviceInfo deviceInfo() const { return m_info; }
    //! The device's tuning as read on this connection: each part once the device has told it
    //! (effects: a device with the capability).
    DeviceTuning deviceTuning() const { return m_tuning; }
    //! The options of the current or last connectDevice(): its link, e.g. the simulated joystick.
    const ConnectOptions &options() const { return m_options; }
    LinkStats stats() const { return m_stats; }
    RecordingStatus recordingStatus() const { return m_recording; }
    //! Sample batches never delivered because kMaxPendingBatches were already waiting (the
    //! recording still has them).
    quint64 droppedSampleBatches() const { return m_droppedBatches.load(); }

Q_SIGNALS:
    //! `detail` says why, in codes and numbers (ui/ and hatpicctl word it).
    void stateChanged(hatpic::SessionState state, const hatpic::StateDetail &detail);
    void deviceInfoChanged(const hatpic::DeviceInfo &info);
    void deviceTuningChanged(const hatpic::DeviceTuning &tuning); //!< the device told a part
    void samplesReady(const hatpic::SampleBatch &batch);
    void statsUpdated(const hatpic::LinkStats &stats);
    void recordingChanged(const hatpic::RecordingStatus &status);
    void deviceLog(const QString &line); //!< what the device says for people
    //! The session's own notes for people (a recording closed by a loss, …); never dropped.
    void notice(const hatpic::SessionNotice &notice);

private:
    //! Calls `(m_session->*Method)(args...)` on the session thread with copies of `args`, so
    //! they outlive the caller's; queued (returns at once) unless `Type` says otherwise.
    template<auto Method, Qt::ConnectionType Type = Qt::AutoConnection, typename... Args>
    void onSession(Args &&...args);
    //! Session thread: posts `deliver` to this object's thread unless `cap` deliveries counted
    //! by `pending` already wait there. False when dropped.
    template<typename Deliver> bool post(std::atomic<int> &pending, int cap, Deliver deliver);
    void postFeedback(); //!< hands the newest m_feedback to the session thread, once

    QThread *m_thread = nullptr;
    mutable std::mutex m_realtimeMutex;
    std::string m_realtimeProblem;      //!< set on the session thread as it starts
    DeviceSession *m_session = nullptr; //!< lives on m_thread
    SessionState m_state = SessionState::Disconnected;
    DeviceInfo m_info;
    DeviceTuning m_tuning;
    ConnectOptions m_options;
    LinkStats m_stats;
    RecordingStatus m_recording;
    // Shared with the session thread: only these atomics, and m_feedback under its mutex, are
    // touched from both threads.
    std::atomic<int> m_pendingBatches{0};
    std::atomic<int> m_pendingStats{0};
    std::atomic<int> m_pendingRecording{0};
    std::atomic<int> m_pendingLogLines{0};
    std::atomic<quint64> m_droppedBatches{0};
    // The newest setFeedback(), whole: one wrench's torques never reach the device half old.
    std::mutex m_feedbackMutex;
    AxisTorques m_feedback{};                  //!< [N·m], with m_feedbackMutex held
    std::atomic<bool> m_feedbackPosted{false}; //!< a call to take it waits on the session thread
};

} // namespace hatpic
