// Replay of a recording: holds the samples in a SampleBuffer the plots can draw, and a
// playhead that the slider scrubs or that plays at 1×, 2× or 5× real time. A second recording
// may be overlaid, moved onto the first one's time base: aligned at their starts, or at their
// triggers (the first "trigger:" event, else the first event, else the start).
#pragma once

#include "plots/samplebuffer.h"
#include "telemetry/recordingreader.h"

#include <QElapsedTimer>
#include <QObject>

#include <memory>

class QTimer;

namespace hatpic {

class ReplayController : public QObject
{
    Q_OBJECT
public:
    static constexpr int kTickMs = 20; //!< playhead update period while playing [ms]

    explicit ReplayController(QObject *parent = nullptr);
    ~ReplayController() override;

    //! Reads a recording (readRecording) and enters replay at its start. On failure nothing
    //! changes and `error` says why.
    bool open(const QString &csvPath, QString *error = nullptr);
    //! Leaves replay and frees the samples (and the overlay).
    void close();

    enum class Align { Start, Trigger };
    //! Reads a second recording to draw over the one replayed (only while replaying). On
    //! failure nothing changes and `error` says why.
    bool openOverlay(const QString &csvPath, QString *error = nullptr);
    void closeOverlay();
    bool hasOverlay() const { return !m_overlayPath.isEmpty(); }
    QString overlayPath() const { return m_overlayPath; }
    //! The overlay's samples on the replayed recording's time base.
    const SampleBuffer &overlayBuffer() const { return *m_overlay; }
    void setOverlayAlign(Align align);
    Align overlayAlign() const { return m_align; }
    //! What is added to the overlay's times to align it [s].
    double overlayOffset() const { return m_overlayOffset; }
    //! Where a recording is aligned: its start, or its trigger (see above) [s].
    static double anchorTime(const QList<Sample> &samples, const QList<RecordingEvent> &events,
                             Align align);

    bool isActive() const { return m_active; }
    QString path() const { return m_path; }
    const Recording &recording() const { return m_recording; }
    const SampleBuffer &buffer() const { return *m_buffer; }
    QStringList warnings() const { return m_warnings; }

    double startTime() const;                      //!< first sample [s]
    double endTime() const;                        //!< last sample [s]
    double position() const { return m_position; } //!< playhead [s]
    //! The sample at (or just before) the playhead; nullopt when there is none.
    std::optional<Sample> currentSample() const;

    void setPosition(double t);  //!< clamped to [startTime, endTime]
    void setSpeed(double speed); //!< 1, 2, 5 … × real time
    double speed() const { return m_speed; }
    bool isPlaying() const { return m_playing; }
    void play(); //!< from the start again when at the end
    void pause();
    void togglePlay();

Q_SIGNALS:
    void activeChanged(bool active);
    void positionChanged(double t);
    void playingChanged(bool playing);
    //! An overlay was opened, moved or closed.
    void overlayChanged();

private:
    void tick();
    void placeOverlay();
    //! Gives `buffer` the effect block and θ0 `recording` started with, for τ_fx's parts.
    static void setEffectsOf(const Recording &recording, SampleBuffer &buffer);
    //! readRecording(), with a recording without samples refused; the error goes to `error`.
    static RecordingReadResult readReplayable(const QString &csvPath, QString *error);

    bool m_active = false;
    QString m_path;
    Recording m_recording;
    std::unique_ptr<SampleBuffer> m_buffer;
    QStringList m_warnings;
    QString m_overlayPath;
    Recording m_overlayRecording; //!< its samples as recorded (m_overlay holds them moved)
    std::unique_ptr<SampleBuffer> m_overlay;
    Align m_align = Align::Trigger;
    double m_overlayOffset = 0;
    double m_position = 0;
    double m_speed = 1;
    bool m_playing = false;
    QTimer *m_timer = nullptr;
    QElapsedTimer m_clock;
};

} // namespace hatpic
