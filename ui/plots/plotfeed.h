// What the plots show: the live stream or a replayed recording, never a mix. The feed holds the
// live buffer, the live events and the parameters the plots draw with, owns the replay, and
// alone decides between the two: the panel's source, its events, bands and units, and the
// operating point other views follow all come from here.
#pragma once

#include "model/devicetuning.h"
#include "plots/samplebuffer.h"
#include "telemetry/recording.h"

#include <QList>
#include <QObject>
#include <QPointer>

#include <optional>

namespace hatpic {

class PlotPanel;
class ReplayController;

class PlotFeed : public QObject
{
    Q_OBJECT
public:
    //! Draws into `plots` (not owned) from now on, starting live.
    explicit PlotFeed(PlotPanel *plots, QObject *parent = nullptr);
    ~PlotFeed() override;

    ReplayController *replay() const { return m_replay; }
    bool isReplaying() const;

    //! The live stream: every batch is kept (also while replaying or paused).
    void appendLive(const SampleBatch &batch);
    const SampleBuffer &liveBuffer() const { return m_live; }
    //! The connected device's tuning as read: its parameters (θ0 and the bands; absent: no
    //! device, and so no effects either) and its effect block (absent: none known).
    void setLiveDeviceTuning(const DeviceTuning &tuning);
    //! The editor's host parameters (units of the reference plot; also for a replayed
    //! recording that carries none).
    void setLiveHostParams(const HostParams &host);
    //! Marks `text` at the newest live sample (nothing while there is none).
    void addLiveEvent(const QString &text);

    //! Enters replay of a recording on a full first window, also when already replaying; false
    //! (with `error`) when it cannot be read, and nothing changes.
    bool openRecording(const QString &csvPath, QString *error = nullptr);
    void backToLive();

    //! Live: freezes or thaws the plots. Replay: plays or pauses the recording.
    void togglePause();
    //! Whether the view stands still (live paused, or replay not playing).
    bool isPaused() const;
    //! Length of the plots' time window [s]; in replay the view stays on the playhead.
    void setWindowLength(double seconds);

Q_SIGNALS:
    void replayingChanged(bool replaying);
    //! Live paused or thawed, replay played or paused.
    void pausedChanged();
    //! The device's tuning of what is shown: the device's live, the recording's in replay.
    void deviceTuningShown(const hatpic::DeviceTuning &tuning);
    //! The knob's state at the newest live sample or at the replay's playhead: θ [rad] and the
    //! static torque measured, τ_rec + τ_fx (τ_rec alone where τ_fx is not known) [N·m].
    void operatingPoint(double theta, double tauRec);
    void operatingPointCleared();

private:
    void onReplayActive(bool active);
    void onReplayPosition(double t);

    QPointer<PlotPanel> m_plots;
    ReplayController *m_replay = nullptr;
    SampleBuffer m_live;
    QList<RecordingEvent> m_liveEvents;
    DeviceTuning m_liveTuning; //!< effects only with parameters
    HostParams m_liveHost;
};

} // namespace hatpic
