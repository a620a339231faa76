#include "editor/livepush.h"

#include <QTimer>

#include <algorithm>

namespace hatpic {

LivePush::LivePush(std::function<bool()> ready, QObject *parent)
    : QObject(parent), m_ready(std::move(ready))
{
    m_timer = new QTimer(this);
    m_timer->setSingleShot(true);
    connect(m_timer, &QTimer::timeout, this, &LivePush::retry);
}

void LivePush::setEnabled(bool enabled)
{
    m_enabled = enabled;
    if (!enabled)
        cancel();
}

void LivePush::setInterval(int milliseconds)
{
    m_interval = std::max(0, milliseconds);
}

void LivePush::edited()
{
    if (!m_enabled)
        return;
    m_pending = true;
    retry();
}

void LivePush::pushStarted()
{
    m_pending = false;
    m_sinceLastPush.start();
}

void LivePush::cancel()
{
    m_pending = false;
    m_timer->stop();
}

void LivePush::retry()
{
    if (!m_enabled || !m_pending || !m_ready())
        return; // retried on the next edit or when the push in flight finishes
    if (m_sinceLastPush.isValid() && m_sinceLastPush.elapsed() < m_interval) {
        if (!m_timer->isActive())
            m_timer->start(int(m_interval - m_sinceLastPush.elapsed()));
        return;
    }
    m_pending = false;
    Q_EMIT pushDue();
}

} // namespace hatpic
