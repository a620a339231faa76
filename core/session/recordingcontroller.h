// The session's recording as one state machine, apart from the samples' path (recording.md):
// idle; armed, waiting for its trigger; open, its rows going to the file until its length if it
// has one; or waiting, the link lost inside it and its files open, until the same device is back
// and has told what it holds. It owns the file (RecordingSink), keeps the recent samples a
// pre-trigger span is cut from, and puts each event on the right row. SamplePipeline hands it
// every sample, every batch and every change; before an event it asks the pipeline to hand on
// the samples waiting (Session::flush), so that the event lands on the next row.
#pragma once

#include "session/recordingsink.h"
#include "session/sessiontypes.h"
#include "telemetry/recordingtrigger.h"
#include "telemetry/sample.h"

#include <QObject>

#include <deque>
#include <functional>
#include <optional>
#include <variant>

namespace hatpic {

namespace recording {

struct Idle
{};
//! Waits for its trigger (RecordingPlan::start) with nothing written yet.
struct Armed
{
    QString csvPath;
    QString source;
    DeviceInfo device;
    RecordingTrigger trigger;
};
//! Rows go to the file.
struct Open
{
    DeviceInfo device;            //!< the device it records (one file, one device)
    std::optional<double> stopAt; //!< it closes after its last sample here [s]
    double pendingDuration_s = 0; //!< a length to count from the first row [s]
};
//! The link was lost inside the recording: the files stay open, no row comes.
struct Waiting
{
    Open open;                      //!< what resumes
    DeviceTuning held;              //!< the device's tuning at the loss (effects: when known)
    bool reconnected = false;       //!< the same device is back
    DeviceTuning pending;           //!< the parts it has yet to tell
    std::optional<double> resumeBy; //!< t_s after which rows resume regardless [s]
    QStringList changes;            //!< what it holds differently now ("K_max 0.6 → 0.4")
};
using State = std::variant<Idle, Armed, Open, Waiting>;

} // namespace recording

class RecordingController : public QObject
{
    Q_OBJECT
public:
    //! Recent samples kept for a recording's pre-trigger span: those of the last
    //! RecordingPlan::kMaxPreTrigger_s, and never more than this many.
    static constexpr qsizetype kMaxRecentSamples = 50'000;
    //! After a reconnect, a waiting recording resumes at the latest this long after the first
    //! sample, even when the device's parameters were not read back [s].
    static constexpr double kResumeWait_s = 2.0;

    //! What the recording asks of the samples' path.
    struct Session
    {
        //! Hands on the samples waiting; they come back through record().
        std::function<void()> flush;
        //! The device's tuning in force: the parameters the samples are rendered with, and the
        //! blocks as known on this connection.
        std::function<DeviceTuning()> tuning;
        std::function<HostParams()> host; //!< the host's parameters in force
    };

    explicit RecordingController(Session session, QObject *parent = nullptr);

    const recording::State &state() const { return m_state; }
    //! Open or waiting: its files are open.
    bool isRecording() const;
    bool isArmed() const { return std::holds_alternative<recording::Armed>(m_state); }

    //! Starts a recording of `device` as `plan` says (now, or armed until its trigger, with its
    //! pre-trigger span from the recent samples and its length); a running or armed one is
    //! closed first. A recording with a length closes itself after its last sample.
    void start(const QString &csvPath, const QString &source, const DeviceInfo &device,
               const RecordingPlan &plan);
    //! Closes the recording, or calls off an armed one.
    void stop();

    // ---- the samples' path ----
    //! Each sample as it comes, before its batch: a trigger fires on it, a waiting recording
    //! counts to its resume, and it joins the recent samples.
    void sample(const Sample &sample);
    //! Each batch handed on: its rows, while open, up to the recording's end.
    void record(const SampleBatch &batch);
    void clearRecent() { m_recent.clear(); } //!< a new connection: t_s starts over

    // ---- the link ----
    //! A connection to `device` began. A waiting recording resumes when `device` is the one it
    //! records (once it has told its tuning), and closes when it is not.
    void connectionStarted(const DeviceInfo &device);
    //! The link is gone (`lost`; the samples waiting were handed on). An armed recording is
    //! called off; an open one waits for the device when the session is `reconnecting`, and
    //! closes when it is not.
    void connectionEnded(const StateDetail &lost, bool reconnecting);

    // ---- changes: each after the samples waiting were handed on, before the tuning in force
    // follows it ----
    //! SET_PARAMS, SET_EFFECTS or SET_PASSIVITY applied (`applied` has its part): a recording
    //! armed for the next push opens.
    void tuningApplied(const DeviceTuning &applied);
    void zeroed(double theta0Before); //!< ZERO applied
    //! The device told its tuning (`told`); `known` has the parts this connection knew already
    //! (a read-back that differs is an event). A waiting recording notes what the device that
    //! came back holds differently.
    void tuningReceived(const DeviceTuning &known, const DeviceTuning &told);
    //! After tuningReceived and the tuning in force followed it: a waiting recording whose
    //! device has told everything resumes.
    void resumeIfReady();
    void hostChanged(const HostParams &from, const HostParams &to);
    void referenceReset();

Q_SIGNALS:
    void statusChanged(const hatpic::RecordingStatus &status);
    //! The recording waits for, resumed after or closed at a link loss.
    void notice(const hatpic::SessionNotice &notice);

private:
    //! Opens the armed recording: the recent samples after `anchor` − pre-trigger span, then
    //! (for a trigger) its event on the next sample; the length counts from `anchor`.
    void fire(std::optional<double> anchor);
    //! Rows resume after the gap; `unread`: without the device's parameters read back.
    void resume(bool unread);
    void keepRecent(const Sample &sample);
    std::optional<double> lastTime() const;
    //! Calls off an armed recording (reported).
    void disarm();

    Session m_session;
    recording::State m_state;
    std::deque<Sample> m_recent;
    RecordingSink m_sink; //!< last: gone first, while what its reports reach is still here
};

} // namespace hatpic
