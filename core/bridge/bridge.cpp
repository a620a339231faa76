#include "bridge.h"

#include <QDateTime>

#include <cmath>

namespace hatpic::bridge {

Bridge::Bridge(DeviceClient &client, QObject *parent) : QObject(parent), m_client(client)
{
    m_clock.start();
    m_checkTimer.setInterval(kCheckIntervalMs);
    connect(&m_checkTimer, &QTimer::timeout, this, [this] {
        const double tau = m_feedback.torqueAt(now()); // counts a wrench that went stale
        applyTorque(m_released ? 0.0 : tau);
    });
    connect(&m_client, &DeviceClient::samplesReady, this, &Bridge::onSamples);
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
    std::string error;
    m_endpoints = RosEndpoints::open(
        settings, [this](const RosEndpoints::Wrench &w) { onWrench(w); }, &error);
    if (!m_endpoints)
        return QString::fromStdString(error);
    m_settings = settings;
    m_feedback = WrenchFeedback(settings.feedback);
    m_rate = RateLimiter(settings.publishRateHz);
    m_released = false;
    m_checkTimer.start();
    return {};
}

void Bridge::releaseFeedback()
{
    m_released = true;
    applyTorque(0);
}

void Bridge::stop()
{
    if (!m_endpoints)
        return;
    m_checkTimer.stop();
    for (int i = 0; i < kOutTopicCount; ++i)
        m_publishedBefore[i] += m_endpoints->written(OutTopic(i));
    m_writeErrorsBefore += m_endpoints->writeErrors();
    m_endpoints.reset(); // no onWrench() runs after this
    {
        const std::lock_guard lock(m_mutex);
        m_arrivals.clear();
    }
    applyTorque(0);
}

void Bridge::setFeedbackSettings(const FeedbackSettings &feedback)
{
    m_settings.feedback = feedback;
    m_feedback.setSettings(feedback);
    if (m_endpoints && !m_released)
        applyTorque(m_feedback.torqueAt(now()));
}

bool Bridge::setPublishRate(double rateHz)
{
    BridgeSettings changed = m_settings;
    changed.publishRateHz = rateHz;
    if (!validate(changed).empty())
        return false;
    m_settings.publishRateHz = rateHz;
    m_rate.setRate(rateHz);
    return true;
}

QString Bridge::where() const
{
    return m_endpoints ? QString::fromStdString(m_endpoints->where()) : QString();
}

BridgeStats Bridge::stats() const
{
    BridgeStats s;
    s.published = m_publishedBefore;
    s.writeErrors = m_writeErrorsBefore;
    if (m_endpoints) {
        for (int i = 0; i < kOutTopicCount; ++i)
            s.published[i] += m_endpoints->written(OutTopic(i));
        s.writeErrors += m_endpoints->writeErrors();
    }
    s.wrenches = m_feedback.counters();
    s.lastWrench = m_feedback.lastValue();
    s.tauExt = m_tauExt;
    s.publishedTauExt = m_publishedTauExt;
    const std::lock_guard lock(m_mutex);
    s.overflow = m_overflow;
    return s;
}

void Bridge::onSamples(const SampleBatch &batch)
{
    if (!m_endpoints || batch.isEmpty())
        return;
    const double arrival = double(QDateTime::currentMSecsSinceEpoch()) * 1e-3;
    const double newest = batch.last().t_s;
    const Component axis = m_settings.axisFor(m_mode);
    for (const Sample &sample : batch) {
        if (!m_rate.due(sample.t_s))
            continue;
        const ReferenceMessages m = referenceMessages(
            sample, sampleWallSeconds(arrival, newest, sample.t_s), m_settings, axis);
        m_endpoints->publish(m);
        m_publishedTauExt = m.feedbackTorque;
    }
}

void Bridge::onWrench(const RosEndpoints::Wrench &wrench)
{
    bool post = false;
    {
        const std::lock_guard lock(m_mutex);
        if (m_arrivals.size() >= kMaxArrivals) {
            m_arrivals.pop_front();
            ++m_overflow;
        }
        m_arrivals.push_back({wrench, now()});
        post = !m_takePosted;
        m_takePosted = true;
    }
    if (post)
        QMetaObject::invokeMethod(this, &Bridge::takeWrench, Qt::QueuedConnection);
}

void Bridge::takeWrench()
{
    std::deque<Arrival> arrivals;
    {
        const std::lock_guard lock(m_mutex);
        arrivals.swap(m_arrivals);
        m_takePosted = false;
    }
    if (!m_endpoints || arrivals.empty() || m_released)
        return;
    const Component c = m_settings.feedback.component;
    for (const Arrival &a : arrivals)
        m_feedback.receive(a.wrench[(c.angular ? 3 : 0) + c.index], a.time);
    applyTorque(m_feedback.torqueAt(now())); // 0 if even the newest waited too long
}

void Bridge::applyTorque(double tau)
{
    const bool changed = tau != m_tauExt;
    m_tauExt = tau;
    m_client.setFeedback(tau);
    if (changed)
        Q_EMIT feedbackChanged(tau);
}

} // namespace hatpic::bridge
