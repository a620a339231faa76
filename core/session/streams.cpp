#include "streams.h"

#include <algorithm>
#include <cmath>

namespace hatpic {

FeedbackStream::FeedbackStream(Sender send, QObject *parent)
    : QObject(parent), m_send(std::move(send)), m_timer(this)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &FeedbackStream::send);
}

void FeedbackStream::start(double rateHz)
{
    m_timer.stop();
    if (!(rateHz > 0))
        return;
    m_timer.setInterval(std::max(1, static_cast<int>(std::lround(1000.0 / rateHz))));
    m_timer.start();
    send();
}

void FeedbackStream::stop()
{
    m_timer.stop();
}

void FeedbackStream::setTauExt(double tauExt)
{
    m_tauExt = std::isfinite(tauExt) ? tauExt : 0.0;
}

void FeedbackStream::send()
{
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
