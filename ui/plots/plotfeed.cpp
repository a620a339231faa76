#include "plots/plotfeed.h"

#include "plots/plotpanel.h"
#include "plots/replaycontroller.h"

#include <algorithm>
#include <cmath>

namespace hatpic {

namespace {

//! What the stiffness view's curve predicts for a knob at rest: τ_rec + τ_fx as measured.
double measuredStaticTorque(const Sample &s)
{
    return std::isnan(s.tau_fx) ? s.tau_rec : s.tau_rec + s.tau_fx;
}

} // namespace

PlotFeed::PlotFeed(PlotPanel *plots, QObject *parent) : QObject(parent), m_plots(plots)
{
    m_replay = new ReplayController(this);
    m_replay->setObjectName(QStringLiteral("replayController"));
    connect(m_replay, &ReplayController::activeChanged, this, &PlotFeed::onReplayActive);
    connect(m_replay, &ReplayController::positionChanged, this, &PlotFeed::onReplayPosition);
    // The replay bar's ▶ and the end of the recording change the state too.
    connect(m_replay, &ReplayController::playingChanged, this, &PlotFeed::pausedChanged);
    connect(m_plots, &PlotPanel::pausedChanged, this, &PlotFeed::pausedChanged);
    connect(m_replay, &ReplayController::overlayChanged, this, [this] {
        m_plots->setOverlaySource(m_replay->hasOverlay() ? &m_replay->overlayBuffer() : nullptr);
    });
    m_plots->setSource(&m_live);
    m_plots->setHostParams(m_liveHost);
}

PlotFeed::~PlotFeed()
{
    // The panel may outlive the buffers it draws.
    if (m_plots) {
        m_plots->setSource(nullptr);
        m_plots->setOverlaySource(nullptr);
    }
}

bool PlotFeed::isReplaying() const
{
    return m_replay->isActive();
}

void PlotFeed::appendLive(const SampleBatch &batch)
{
    if (batch.isEmpty())
        return;
    m_live.append(batch);
    if (!isReplaying()) {
        m_plots->noteArrivals(batch);
        const Sample &last = batch.constLast();
        Q_EMIT operatingPoint(last.theta, measuredStaticTorque(last));
    }
}

void PlotFeed::setLiveDeviceTuning(const DeviceTuning &tuning)
{
    m_liveTuning = {tuning.params, tuning.params ? tuning.effects : std::nullopt};
    // τ_fx's parts of the samples from now on; they need θ0 (which may have changed).
    m_live.setEffects(m_liveTuning.effects, tuning.params ? tuning.params->theta0 : 0.0);
    if (isReplaying())
        return;
    m_plots->setDeviceParams(m_liveTuning.params);
    Q_EMIT deviceTuningShown(m_liveTuning);
    if (!tuning.params)
        Q_EMIT operatingPointCleared();
}

void PlotFeed::setLiveHostParams(const HostParams &host)
{
    m_liveHost = host;
    if (!isReplaying())
        m_plots->setHostParams(host);
}

void PlotFeed::addLiveEvent(const QString &text)
{
    if (m_live.isEmpty())
        return;
    // Forget markers that scrolled out of the live buffer.
    const double oldest = m_live.firstTime();
    m_liveEvents.removeIf([oldest](const RecordingEvent &e) { return e.t_s < oldest; });
    m_liveEvents.append({m_live.lastTime(), text});
    if (!isReplaying())
        m_plots->setEvents(m_liveEvents);
}

bool PlotFeed::openRecording(const QString &csvPath, QString *error)
{
    if (!m_replay->open(csvPath, error))
        return false;
    onReplayActive(true); // refresh also when already replaying another file
    // Open on a full first window rather than on a single sample.
    m_replay->setPosition(
        std::min(m_replay->startTime() + m_plots->windowLength(), m_replay->endTime()));
    return true;
}

void PlotFeed::backToLive()
{
    m_replay->close();
}

void PlotFeed::togglePause()
{
    if (isReplaying())
        m_replay->togglePlay();
    else
        m_plots->setPaused(!m_plots->isPaused());
}

bool PlotFeed::isPaused() const
{
    return isReplaying() ? !m_replay->isPlaying() : m_plots->isPaused();
}

void PlotFeed::setWindowLength(double seconds)
{
    m_plots->setWindowLength(seconds);
    if (isReplaying())
        onReplayPosition(m_replay->position());
}

void PlotFeed::onReplayActive(bool active)
{
    if (active) {
        const Recording &rec = m_replay->recording();
        m_plots->setPaused(false);
        m_plots->setSource(&m_replay->buffer());
        m_plots->setFollowLatest(false);
        m_plots->setEvents(rec.events);
        const DeviceTuning recorded = rec.hasMetadata
                                          ? DeviceTuning{rec.metadata.params, rec.metadata.effects}
                                          : DeviceTuning{};
        m_plots->setDeviceParams(recorded.params);
        m_plots->setHostParams(rec.hasMetadata ? rec.metadata.host : m_liveHost);
        Q_EMIT replayingChanged(true);
        Q_EMIT deviceTuningShown(recorded);
        onReplayPosition(m_replay->position());
    } else {
        m_plots->setDataEnd(std::nullopt);
        m_plots->setSource(&m_live);
        m_plots->setFollowLatest(true);
        m_plots->setEvents(m_liveEvents);
        m_plots->setDeviceParams(m_liveTuning.params);
        m_plots->setHostParams(m_liveHost);
        Q_EMIT replayingChanged(false);
        Q_EMIT deviceTuningShown(m_liveTuning);
        Q_EMIT operatingPointCleared();
    }
    Q_EMIT pausedChanged();
}

void PlotFeed::onReplayPosition(double t)
{
    if (!isReplaying())
        return;
    // As live: data up to the playhead, sweeping in from the left until they fill the window.
    m_plots->setDataEnd(t);
    m_plots->setViewEnd(std::max(t, m_replay->startTime() + m_plots->windowLength()));
    if (const std::optional<Sample> s = m_replay->currentSample())
        Q_EMIT operatingPoint(s->theta, measuredStaticTorque(*s));
}

} // namespace hatpic
