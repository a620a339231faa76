#include "bridge.h"

#include <chrono>
#include <cmath>

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
        settings, [this](const RosEndpoints::Wrench &w) { onWrench(w); },
        [this](bool value) { onEnable(value); }, &error);
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
        // The local switch stays as the user set it: a reopening never engages by itself.
        const bool local = m_gate.local();
        m_gate = EnableGate(!settings.topics.enable.empty(), kEnableTimeout);
        m_gate.setLocal(local);
        m_lastWrench.fill(NAN);
        m_otherComponentStreak = 0;
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
    if (m_endpoints)
        applyTorque(torqueAt(now()));
    return {};
}

void Bridge::setEngaged(bool engaged)
{
    const std::lock_guard lock(m_mutex);
    m_gate.setLocal(engaged);
    if (m_endpoints)
        applyTorque(torqueAt(now()));
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
    s.lastWrenchValues = m_lastWrench;
    s.otherComponentStreak = m_otherComponentStreak;
    s.tauExt = m_tauExt;
    s.publishedTauExt = m_publishedTauExt;
    s.deviceTauExt = m_deviceTauExt;
    s.timing = m_timing.stats(now());
    s.passivity = m_passivity.state();
    s.engaged = m_gate.engaged(now());
    s.localEngaged = m_gate.local();
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
        m_passivity.add(sample.t_s, sample.tau_ext, sample.omega, sample.tau_pc, sample.pc_reserve,
                        sample.theta);
        m_deviceTauExt = sample.tau_ext;
        if (sample.arrival_ns > 0)
            m_timing.sampleShows(sample.tau_ext, double(sample.arrival_ns) * 1e-9);
        const double t = now();
        applyTorque(torqueAt(t)); // counts a wrench gone stale
        // Released: no motion asked of the robot, the pose held; engaged again: re-anchored.
        const bool engaged = m_gate.engaged(t);
        Sample gated = sample;
        gated.p_ref = m_gate.reference(sample.p_ref, engaged);
        if (!engaged)
            gated.v_ref = 0;
        if (!m_rate.due(sample.t_s))
            return;
        m = referenceMessages(gated, wallSecondsOf(sample), m_settings, m_settings.axisFor(m_mode));
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
    const int chosen = (c.angular ? 3 : 0) + c.index;
    m_lastWrench = wrench.values;
    bool another = false;
    for (int i = 0; i < 6; ++i)
        another =
            another || (i != chosen && wrench.values[i] != 0 && std::isfinite(wrench.values[i]));
    m_otherComponentStreak = wrench.values[chosen] == 0 && another ? m_otherComponentStreak + 1 : 0;
    const double tau = m_feedback.receive(wrench.values[chosen], arrived);
    const double applied = m_gate.engaged(arrived) ? tau : 0.0;
    if (applied != m_tauExt)
        m_timing.torqueAsked(applied, arrived);
    applyTorque(applied);
}

void Bridge::onEnable(bool value)
{
    const double t = now();
    const std::lock_guard lock(m_mutex);
    if (!m_endpoints)
        return;
    m_gate.received(value, t);
    applyTorque(torqueAt(t));
}

void Bridge::checkStale()
{
    const std::lock_guard lock(m_mutex);
    if (m_endpoints)
        applyTorque(torqueAt(now()));
}

double Bridge::torqueAt(double t)
{
    return m_released || !m_gate.engaged(t) ? 0.0 : m_feedback.torqueAt(t);
}

void Bridge::applyTorque(double tau)
{
    if (tau == m_tauExt)
        return;
    m_tauExt = tau;
    m_client.setFeedback(tau); // posts to the session thread: never waits
}

} // namespace hatpic::bridge
