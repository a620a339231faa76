#include "bridge.h"

#include "protocol/messages.h"

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
    auto endpoints = RosEndpoints::open(settings,
                                        {[this](const RosEndpoints::Wrench &w) { onWrench(w); },
                                         [this](bool value) { onEnable(value); },
                                         [this](const RosEndpoints::AxisRequest &r) { onAxis(r); }},
                                        &error);
    if (!endpoints)
        return QString::fromStdString(error);
    {
        const std::lock_guard publishing(m_publishMutex);
        const std::lock_guard lock(m_mutex);
        m_settings = settings;
        m_selector = AxisSelector(settings.axisFor(m_mode));
        m_axisRejected = 0;
        m_lastAxisRejected.clear();
        m_axes = knobComponents(settings, m_selector.axis());
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
        m_torques = {};
        m_deviceTauExt = std::numeric_limits<double>::quiet_NaN();
        m_echoes = 0;
        m_endpoints = std::move(endpoints);
    }
    m_client.setFeedback(AxisTorques{});
    m_client.addSampleListener(this);
    m_checkTimer.start();
    return {};
}

void Bridge::releaseFeedback()
{
    const std::lock_guard lock(m_mutex);
    m_released = true;
    applyTorques({});
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
        applyTorques({});
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
        applyTorques(torquesAt(now()));
    return {};
}

void Bridge::setEngaged(bool engaged)
{
    const std::lock_guard lock(m_mutex);
    m_gate.setLocal(engaged);
    if (m_endpoints)
        applyTorques(torquesAt(now()));
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
    m_selector.setDefault(m_settings.axisFor(mode));
    m_axes = knobComponents(m_settings, m_selector.axis());
}

bool Bridge::selectAxis(Component axis)
{
    const std::lock_guard lock(m_mutex);
    if (!m_endpoints)
        return false;
    m_selector.request(axis);
    return true;
}

Component Bridge::feltComponent() const
{
    return m_selector.chosen() ? m_selector.axis() : m_settings.feedback.component;
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
    s.tauExt = m_torques[0];
    s.torques = m_torques;
    s.publishedTauExt = m_publishedTauExt;
    s.deviceTauExt = m_deviceTauExt;
    s.timing = m_timing.stats(now());
    s.passivity = m_passivity.state();
    s.engaged = m_gate.engaged(now());
    s.localEngaged = m_gate.local();
    s.axis = m_selector.axis();
    s.pendingAxis = m_selector.pending();
    s.feltComponent = feltComponent();
    s.axisSwitches = m_selector.switches();
    s.axisRejected = m_axisRejected;
    s.lastAxisRejected = m_lastAxisRejected;
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
        applyTorques(torquesAt(t)); // counts a wrench gone stale
        // Released: no motion asked of the robot, each knob's pose held; engaged again:
        // re-anchored.
        const bool engaged = m_gate.engaged(t);
        Knobs knobs{};
        for (int n = 1; n <= sample.axes(); ++n) {
            AxisSample &knob = knobs[std::size_t(n - 1)];
            knob = sample.knob(n);
            knob.p_ref = m_gate.reference(knob.p_ref, engaged, n - 1);
            if (!engaged)
                knob.v_ref = 0;
        }
        // The operator's axis: switched only while knob 1 rests in its dead zone, its pose
        // going on from what each axis held (ros.md § Choosing the knob's axis).
        const bool inDeadZone = (sample.flags & v2::kFlagDeadZone) != 0;
        if (m_selector.update(knobs[0].p_ref, inDeadZone)) {
            m_axes = knobComponents(m_settings, m_selector.axis());
            if (m_feedback.counters().received > 0) // feel the new component of the last wrench
                m_feedback.rechoose(m_lastWrench[std::size_t(feltComponent().slot())]);
            applyTorques(torquesAt(t));
        }
        if (!m_rate.due(sample.t_s))
            return;
        const SlotPose knob1Pose = m_selector.pose(knobs[0].p_ref);
        m = referenceMessages(knobs, sample.axes(), wallSecondsOf(sample), m_settings, m_axes,
                              sample.roll(), sample.pitch(), &knob1Pose);
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
    const int chosen = feltComponent().slot();
    m_lastWrench = wrench.values;
    bool another = false;
    for (int i = 0; i < 6; ++i)
        another =
            another || (i != chosen && wrench.values[i] != 0 && std::isfinite(wrench.values[i]));
    m_otherComponentStreak = wrench.values[chosen] == 0 && another ? m_otherComponentStreak + 1 : 0;
    // A board's knobs 2 … 4 feel the components of their own axes (ros.md § A board's knobs).
    WrenchFeedback::OtherKnobs others{};
    for (std::size_t k = 0; k < others.size(); ++k)
        others[k] = wrench.values[std::size_t(m_axes[k + 1].slot())];
    m_feedback.receive(wrench.values[chosen], arrived, others);
    const AxisTorques applied =
        m_gate.engaged(arrived) ? m_feedback.torquesAt(arrived) : AxisTorques{};
    if (applied[0] != m_torques[0])
        m_timing.torqueAsked(applied[0], arrived);
    applyTorques(applied);
}

void Bridge::onEnable(bool value)
{
    const double t = now();
    const std::lock_guard lock(m_mutex);
    if (!m_endpoints)
        return;
    m_gate.received(value, t);
    applyTorques(torquesAt(t));
}

void Bridge::onAxis(const RosEndpoints::AxisRequest &request)
{
    const std::lock_guard lock(m_mutex);
    if (!m_endpoints)
        return;
    if (request.axis) {
        m_selector.request(*request.axis);
    } else {
        ++m_axisRejected; // untrusted input: counted, shown, never acted on
        m_lastAxisRejected = request.text;
    }
}

void Bridge::checkStale()
{
    const std::lock_guard lock(m_mutex);
    if (m_endpoints)
        applyTorques(torquesAt(now()));
}

AxisTorques Bridge::torquesAt(double t)
{
    return m_released || !m_gate.engaged(t) ? AxisTorques{} : m_feedback.torquesAt(t);
}

void Bridge::applyTorques(const AxisTorques &torques)
{
    if (torques == m_torques)
        return;
    m_torques = torques;
    m_client.setFeedback(torques); // posts to the session thread: never waits
}

} // namespace hatpic::bridge
