// Replay of a recording: holds the samples in a SampleBuffer the plots can draw, and a
// playhead that the slider scrubs or that plays at 1×, 2× or 5× real time.
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
    //! Leaves replay and frees the samples.
    void close();

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

private:
    void tick();

    bool m_active = false;
    QString m_path;
    Recording m_recording;
    std::unique_ptr<SampleBuffer> m_buffer;
    QStringList m_warnings;
    double m_position = 0;
    double m_speed = 1;
    bool m_playing = false;
    QTimer *m_timer = nullptr;
    QElapsedTimer m_clock;
};

} // namespace hatpic
