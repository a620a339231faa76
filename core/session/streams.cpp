#include "streams.h"

#include <algorithm>
#include <cmath>

namespace hatpic {

FeedbackStream::FeedbackStream(Sender send, QObject *parent)
    : QObject(parent), m_send(std::move(send)), m_keepAlive(this), m_deferred(this)
{
    m_keepAlive.setInterval(kKeepAliveMs);
    m_keepAlive.setTimerType(Qt::PreciseTimer);
    connect(&m_keepAlive, &QTimer::timeout, this, &FeedbackStream::send);
    m_deferred.setSingleShot(true);
    m_deferred.setTimerType(Qt::PreciseTimer);
    connect(&m_deferred, &QTimer::timeout, this, &FeedbackStream::send);
}

void FeedbackStream::start(double maxRateHz)
{
    stop();
    if (!(maxRateHz > 0))
        return;
    m_minIntervalNs = static_cast<qint64>(std::llround(1e9 / maxRateHz));
    m_running = true;
    send();
}

void FeedbackStream::stop()
{
    m_running = false;
    m_keepAlive.stop();
    m_deferred.stop();
}

void FeedbackStream::setTauExt(double tauExt)
{
    AxisTorques torques = m_tauExt;
    torques[0] = tauExt;
    setTorques(torques);
}

void FeedbackStream::setTorques(const AxisTorques &tauExt)
{
    AxisTorques tau = tauExt;
    for (double &t : tau)
        t = std::isfinite(t) ? t : 0.0;
    if (tau == m_tauExt)
        return;
    m_tauExt = tau;
    if (!m_running || m_deferred.isActive())
        return; // the deferred frame takes the newest value
    const qint64 wait = m_minIntervalNs - m_sinceSend.nsecsElapsed();
    if (wait <= 0) {
        send();
        return;
    }
    m_deferred.start(static_cast<int>((wait + 999'999) / 1'000'000)); // whole ms, rounded up
}

void FeedbackStream::send()
{
    m_deferred.stop();
    m_keepAlive.start(); // the next keep-alive counts from this frame
    m_sinceSend.start();
    if (!m_paused)
        m_send(m_tauExt);
}

PingProbe::PingProbe(const QElapsedTimer &clock, Sender send, QObject *parent)
    : QObject(parent), m_clock(clock), m_send(std::move(send)), m_timer(this)
{
    m_timer.setInterval(kPingIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &PingProbe::ping);
}

void PingProbe::start()
{
    m_timer.start();
    ping();
}

void PingProbe::stop()
{
    m_timer.stop();
    m_pending.clear();
}

void PingProbe::clear()
{
    stop();
    m_rtt.clear();
}

void PingProbe::ping()
{
    const quint32 token = m_token + 1;
    // Remembered before sending: a link may answer within the write.
    m_pending.insert(token, m_clock.nsecsElapsed());
    if (!m_send(token)) {
        m_pending.remove(token); // the probe simply waits for the next tick
        return;
    }
    m_token = token;
    if (m_pending.size() > kMaxPendingPings) {
        // Forget the oldest unanswered probe.
        auto oldest = m_pending.begin();
        for (auto it = m_pending.begin(); it != m_pending.end(); ++it) {
            if (it.value() < oldest.value())
                oldest = it;
        }
        m_pending.erase(oldest);
    }
}

void PingProbe::onPong(quint32 token)
{
    const auto it = m_pending.find(token);
    if (it == m_pending.end())
        return;
    m_rtt.add(static_cast<double>(m_clock.nsecsElapsed() - it.value()) * 1e-6);
    m_pending.erase(it);
}

} // namespace hatpic
