#include "bridge.h"

#include <chrono>

namespace hatpic::bridge {

namespace {

//! The host's wall-clock time of a sample decoded at `arrivalNs` on sampleClockNs() [s since
//! the Unix epoch]; now for a sample that does not say.
double wallNow()
{
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
        .count();
}

double wallSecondsOf(const Sample &sample)
{
    const double wall = wallNow();
    if (sample.arrival_ns <= 0)
        return wall;
    return wall - double(sampleClockNs() - sample.arrival_ns) * 1e-9;
}

} // namespace

Bridge::Bridge(DeviceClient &client, QObject *parent) : QObject(parent), m_client(client)
{
    m_checkTimer.setInterval(kCheckIntervalMs);
    connect(&m_checkTimer, &QTimer::timeout, this, &Bridge::checkStale);
}

Bridge::~Bridge()
{
    stop();
}

QString Bridge::start(const BridgeSettings &settings)
{
    stop();
    if (const auto errors = validate(settings); !errors.empty())
        return QString::fromStdString(errors.front()) + u'.';
    if (const std::string problem = limitProblem(settings.feedback, deviceTauLimit());
        !problem.empty())
        return QString::fromStdString(problem) + u'.';
    // Opened without the lock: a wrench that arrives meanwhile waits for it in onWrench(), and
    // endpoints that fail are deleted here, which waits for that handler.
    std::string error;
    auto endpoints = RosEndpoints::open(
        settings, [this](const RosEndpoints::Wrench &w) { onWrench(w); }, &error);
    if (!endpoints)
        return QString::fromStdString(error);
    {
        const std::lock_guard publishing(m_publishMutex);
        const std::lock_guard lock(m_mutex);
        m_settings = settings;
        m_feedback = WrenchFeedback(settings.feedback);
        m_timing = WrenchTiming();
        m_timing.setPauseAfter(settings.feedback.staleAfter);
        m_passivity.reset();
        m_rate = RateLimiter(settings.publishRateHz);
        m_released = false;
        m_tauExt = 0;
        m_deviceTauExt = std::numeric_limits<double>::quiet_NaN();
        m_echoes = 0;
        m_endpoints = std::move(endpoints);
    }
    m_client.setFeedback(0);
    m_client.addSampleListener(this);
    m_checkTimer.start();
    return {};
}

void Bridge::releaseFeedback()
{
    const std::lock_guard lock(m_mutex);
    m_released = true;
    applyTorque(0);
}

void Bridge::stop()
{
    m_checkTimer.stop();
    if (!isRunning())
        return; // never started, or stopped: the client is not touched (it may be gone)
    m_client.removeSampleListener(this); // no sampleDecoded() runs after this
    std::unique_ptr<RosEndpoints> closing;
    {
        const std::lock_guard publishing(m_publishMutex); // no write under way after this
        const std::lock_guard lock(m_mutex);
        if (!m_endpoints)
            return;
        for (int i = 0; i < kOutTopicCount; ++i)
            m_publishedBefore[i] += m_endpoints->written(OutTopic(i));
        m_writeErrorsBefore += m_endpoints->writeErrors();
        closing = std::move(m_endpoints); // onWrench() ignores what still arrives
        applyTorque(0);
    }
    closing.reset(); // waits for a handler in progress, outside the lock it may be waiting for
}

bool Bridge::isRunning() const
{
    const std::lock_guard lock(m_mutex);
    return m_endpoints != nullptr;
}

double Bridge::deviceTauLimit() const
{
    if (m_client.state() != SessionState::Connected)
        return std::numeric_limits<double>::quiet_NaN(); // not known
    const double limit = m_client.deviceInfo().tauLimit;
    return limit > 0 ? limit : std::numeric_limits<double>::quiet_NaN();
}

QString Bridge::setFeedbackSettings(const FeedbackSettings &feedback)
{
    if (const std::string problem = limitProblem(feedback, deviceTauLimit()); !problem.empty())
        return QString::fromStdString(problem) + u'.';
    const std::lock_guard lock(m_mutex);
    m_settings.feedback = feedback;
    m_feedback.setSettings(feedback);
    m_timing.setPauseAfter(feedback.staleAfter);
    if (m_endpoints && !m_released)
        applyTorque(m_feedback.torqueAt(now()));
    return {};
}

bool Bridge::setPublishRate(double rateHz)
{
    const std::lock_guard lock(m_mutex);
    BridgeSettings changed = m_settings;
    changed.publishRateHz = rateHz;
    if (!validate(changed).empty())
        return false;
    m_settings.publishRateHz = rateHz;
    m_rate.setRate(rateHz);
    return true;
}

void Bridge::setReferenceMode(ReferenceMode mode)
{
    const std::lock_guard lock(m_mutex);
    m_mode = mode;
}

BridgeSettings Bridge::settings() const
{
    const std::lock_guard lock(m_mutex);
    return m_settings;
}

QString Bridge::where() const
{
    const std::lock_guard lock(m_mutex);
    return m_endpoints ? QString::fromStdString(m_endpoints->where()) : QString();
}

BridgeStats Bridge::stats() const
{
    const std::lock_guard lock(m_mutex);
    BridgeStats s;
    s.published = m_publishedBefore;
    s.writeErrors = m_writeErrorsBefore;
    if (m_endpoints) {
        for (int i = 0; i < kOutTopicCount; ++i)
            s.published[i] += m_endpoints->written(OutTopic(i));
        s.writeErrors += m_endpoints->writeErrors();
    }
    s.wrenches = m_feedback.counters();
    s.echoes = m_echoes;
    s.lastWrench = m_feedback.lastValue();
    s.tauExt = m_tauExt;
    s.publishedTauExt = m_publishedTauExt;
    s.deviceTauExt = m_deviceTauExt;
    s.timing = m_timing.stats(now());
    s.passivity = m_passivity.state();
    return s;
}

void Bridge::sampleDecoded(const Sample &sample)
{
    const std::lock_guard publishing(m_publishMutex); // m_endpoints stays while it is held
    ReferenceMessages m;
    {
        const std::lock_guard lock(m_mutex);
        if (!m_endpoints)
            return;
        m_passivity.add(sample.t_s, sample.tau_ext, sample.omega);
        m_deviceTauExt = sample.tau_ext;
        if (sample.arrival_ns > 0)
            m_timing.sampleShows(sample.tau_ext, double(sample.arrival_ns) * 1e-9);
        applyTorque(m_released ? 0.0 : m_feedback.torqueAt(now())); // counts a wrench gone stale
        if (!m_rate.due(sample.t_s))
            return;
        m = referenceMessages(sample, wallSecondsOf(sample), m_settings,
                              m_settings.axisFor(m_mode));
        m_publishedTauExt = m.feedbackTorque;
    }
    // Without m_mutex: a wrench handler called inside publish() takes it.
    m_endpoints->publish(m);
}

void Bridge::onWrench(const RosEndpoints::Wrench &wrench)
{
    const double arrived = now();
    const double wall = wallNow();
    const std::lock_guard lock(m_mutex);
    if (!m_endpoints || m_released)
        return;
    if (wrench.echo) {
        ++m_echoes; // the bridge's own feedback, come back: never the robot's wrench
        return;
    }
    m_timing.arrived(arrived, wall, wrench.stamp);
    const Component c = m_settings.feedback.component;
    const double tau = m_feedback.receive(wrench.values[(c.angular ? 3 : 0) + c.index], arrived);
    if (tau != m_tauExt)
        m_timing.torqueAsked(tau, arrived);
    applyTorque(tau);
}

void Bridge::checkStale()
{
    const std::lock_guard lock(m_mutex);
    if (m_endpoints)
        applyTorque(m_released ? 0.0 : m_feedback.torqueAt(now()));
}

void Bridge::applyTorque(double tau)
{
    if (tau == m_tauExt)
        return;
    m_tauExt = tau;
    m_client.setFeedback(tau); // posts to the session thread: never waits
}

} // namespace hatpic::bridge
