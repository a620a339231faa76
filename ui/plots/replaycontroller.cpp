#include "plots/replaycontroller.h"

#include <QTimer>

#include <algorithm>

namespace hatpic {

RecordingReadResult ReplayController::readReplayable(const QString &csvPath, QString *error)
{
    RecordingReadResult result = readRecording(csvPath);
    if (result.recording && result.recording->samples.isEmpty()) {
        result.recording.reset();
        result.error = tr("%1 holds no samples.").arg(csvPath);
    }
    if (!result.recording && error)
        *error = result.error;
    return result;
}

ReplayController::ReplayController(QObject *parent)
    : QObject(parent), m_buffer(std::make_unique<SampleBuffer>(1)),
      m_overlay(std::make_unique<SampleBuffer>(1))
{
    m_timer = new QTimer(this);
    m_timer->setInterval(kTickMs);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &ReplayController::tick);
}

ReplayController::~ReplayController() = default;

void ReplayController::setEffectsOf(const Recording &recording, SampleBuffer &buffer)
{
    // τ_fx's parts with the block the recording started with (a later push is an event only).
    if (recording.hasMetadata)
        buffer.setEffects(recording.metadata.effects, recording.metadata.params.theta0);
}

bool ReplayController::open(const QString &csvPath, QString *error)
{
    RecordingReadResult result = readReplayable(csvPath, error);
    if (!result.recording)
        return false;
    pause();
    m_recording = std::move(*result.recording);
    m_warnings = result.warnings;
    m_path = csvPath;
    m_buffer = std::make_unique<SampleBuffer>(m_recording.samples.size());
    setEffectsOf(m_recording, *m_buffer);
    m_buffer->append(m_recording.samples);
    m_recording.samples.clear(); // the buffer holds them now
    m_recording.samples.squeeze();
    m_position = startTime();
    if (hasOverlay())
        placeOverlay(); // on the new recording's time base
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
    closeOverlay();
    m_active = false;
    Q_EMIT activeChanged(false);
    m_buffer = std::make_unique<SampleBuffer>(1);
    m_recording = Recording();
    m_path.clear();
    m_warnings.clear();
}

bool ReplayController::openOverlay(const QString &csvPath, QString *error)
{
    if (!m_active) {
        if (error)
            *error = tr("Open a recording to replay first.");
        return false;
    }
    RecordingReadResult result = readReplayable(csvPath, error);
    if (!result.recording)
        return false;
    m_overlayRecording = std::move(*result.recording);
    m_overlayPath = csvPath;
    placeOverlay();
    return true;
}

void ReplayController::closeOverlay()
{
    if (!hasOverlay())
        return;
    m_overlayPath.clear();
    m_overlayRecording = Recording();
    m_overlay = std::make_unique<SampleBuffer>(1);
    m_overlayOffset = 0;
    Q_EMIT overlayChanged();
}

void ReplayController::setOverlayAlign(Align align)
{
    if (align == m_align)
        return;
    m_align = align;
    if (hasOverlay())
        placeOverlay();
}

double ReplayController::anchorTime(const QList<Sample> &samples,
                                    const QList<RecordingEvent> &events, Align align)
{
    if (align == Align::Trigger) {
        for (const RecordingEvent &e : events) {
            if (e.text.startsWith(QLatin1String("trigger:")))
                return e.t_s;
        }
        if (!events.isEmpty())
            return events.constFirst().t_s;
    }
    return samples.isEmpty() ? 0.0 : samples.constFirst().t_s;
}

void ReplayController::placeOverlay()
{
    // The replayed recording's samples live in m_buffer only; its first sample and events
    // give its anchor.
    QList<Sample> first;
    if (!m_buffer->isEmpty())
        first.append(m_buffer->sample(0));
    const double mine = anchorTime(first, m_recording.events, m_align);
    const double theirs =
        anchorTime(m_overlayRecording.samples, m_overlayRecording.events, m_align);
    m_overlayOffset = mine - theirs;
    QList<Sample> moved = m_overlayRecording.samples;
    for (Sample &sample : moved)
        sample.t_s += m_overlayOffset;
    m_overlay = std::make_unique<SampleBuffer>(moved.size());
    setEffectsOf(m_overlayRecording, *m_overlay);
    m_overlay->append(moved);
    Q_EMIT overlayChanged();
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
