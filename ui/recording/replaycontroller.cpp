#include "recording/replaycontroller.h"

#include <QTimer>

#include <algorithm>

namespace hatpic {

ReplayController::ReplayController(QObject *parent)
    : QObject(parent), m_buffer(std::make_unique<SampleBuffer>(1))
{
    m_timer = new QTimer(this);
    m_timer->setInterval(kTickMs);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &ReplayController::tick);
}

ReplayController::~ReplayController() = default;

bool ReplayController::open(const QString &csvPath, QString *error)
{
    RecordingReadResult result = readRecording(csvPath);
    if (!result.recording) {
        if (error)
            *error = result.error;
        return false;
    }
    if (result.recording->samples.isEmpty()) {
        if (error)
            *error = tr("%1 holds no samples.").arg(csvPath);
        return false;
    }
    pause();
    m_recording = std::move(*result.recording);
    m_warnings = result.warnings;
    m_path = csvPath;
    m_buffer = std::make_unique<SampleBuffer>(m_recording.samples.size());
    m_buffer->append(m_recording.samples);
    m_recording.samples.clear(); // the buffer holds them now
    m_recording.samples.squeeze();
    m_position = startTime();
    const bool wasActive = m_active;
    m_active = true;
    if (!wasActive)
        Q_EMIT activeChanged(true);
    Q_EMIT positionChanged(m_position);
    return true;
}

void ReplayController::close()
{
    if (!m_active)
        return;
    pause();
    m_active = false;
    Q_EMIT activeChanged(false);
    m_buffer = std::make_unique<SampleBuffer>(1);
    m_recording = Recording();
    m_path.clear();
    m_warnings.clear();
}

double ReplayController::startTime() const
{
    return m_buffer->firstTime();
}

double ReplayController::endTime() const
{
    return m_buffer->lastTime();
}

std::optional<Sample> ReplayController::currentSample() const
{
    const qsizetype end = m_buffer->upperBound(m_position);
    if (end == 0)
        return std::nullopt;
    return m_buffer->sample(end - 1);
}

void ReplayController::setPosition(double t)
{
    const double clamped = std::clamp(t, startTime(), endTime());
    if (clamped == m_position)
        return;
    m_position = clamped;
    Q_EMIT positionChanged(m_position);
}

void ReplayController::setSpeed(double speed)
{
    if (speed > 0)
        m_speed = speed;
}

void ReplayController::play()
{
    if (!m_active || m_playing)
        return;
    if (m_position >= endTime())
        setPosition(startTime());
    m_playing = true;
    m_clock.start();
    m_timer->start();
    Q_EMIT playingChanged(true);
}

void ReplayController::pause()
{
    if (!m_playing)
        return;
    m_playing = false;
    m_timer->stop();
    Q_EMIT playingChanged(false);
}

void ReplayController::togglePlay()
{
    if (m_playing)
        pause();
    else
        play();
}

void ReplayController::tick()
{
    const double elapsed = m_clock.nsecsElapsed() / 1e9;
    m_clock.restart();
    setPosition(m_position + elapsed * m_speed);
    if (m_position >= endTime())
        pause();
}

} // namespace hatpic
