#include "wrenchtiming.h"

#include <algorithm>
#include <cmath>

namespace hatpic::bridge {

void RecentValues::add(double value)
{
    m_values[m_next] = value;
    m_next = (m_next + 1) % kRecent;
    m_size = std::min(m_size + 1, kRecent);
    ++m_count;
}

Spread RecentValues::spread() const
{
    Spread s;
    s.count = m_count;
    if (m_size == 0)
        return s;
    std::array<double, kRecent> sorted = m_values;
    const auto begin = sorted.begin();
    const auto end = begin + std::ptrdiff_t(m_size);
    std::sort(begin, end);
    // Nearest rank: the smallest value with at least that share of the values at or below it.
    const auto rank = [&](double share) {
        const auto index = std::size_t(std::ceil(share * double(m_size))) - 1;
        return sorted[std::min(index, m_size - 1)];
    };
    s.median = rank(0.5);
    s.p95 = rank(0.95);
    return s;
}

void WrenchTiming::arrived(double now, double wallNow, double stamp)
{
    if (std::isfinite(stamp))
        m_stampDelays.add(wallNow - stamp);
    else
        ++m_unstamped;
    if (std::isfinite(m_lastArrival)) {
        const double gap = now - m_lastArrival;
        if (gap > m_pauseAfter) {
            ++m_pauses;
        } else {
            const Spread typical = m_intervals.spread();
            if (typical.count >= kMinIntervals && typical.median > 0 &&
                gap > kGapFactor * typical.median)
                m_lost += std::uint64_t(std::llround(gap / typical.median)) - 1;
            m_intervals.add(gap);
        }
    }
    m_lastArrival = now;
}

void WrenchTiming::torqueAsked(double tau, double now)
{
    if (m_pendingCount == kPendingEchoes) { // the oldest is forgotten
        std::move(m_pending.begin() + 1, m_pending.end(), m_pending.begin());
        --m_pendingCount;
    }
    m_pending[m_pendingCount++] = {float(tau), now};
}

void WrenchTiming::sampleShows(double tauExt, double at)
{
    // The newest change the sample shows is measured; it and every older one are done (an
    // older one the device never showed was overtaken before it got there).
    const float shown = float(tauExt);
    for (std::size_t i = m_pendingCount; i-- > 0;) {
        const Pending &p = m_pending[i];
        if (p.tau != shown || p.asked > at)
            continue;
        m_echoDelays.add(at - p.asked);
        std::move(m_pending.begin() + std::ptrdiff_t(i + 1),
                  m_pending.begin() + std::ptrdiff_t(m_pendingCount), m_pending.begin());
        m_pendingCount -= i + 1;
        break;
    }
    // What the device has not shown for kEchoTimeout it will not show as this change.
    std::size_t expired = 0;
    while (expired < m_pendingCount && at - m_pending[expired].asked > kEchoTimeout)
        ++expired;
    std::move(m_pending.begin() + std::ptrdiff_t(expired),
              m_pending.begin() + std::ptrdiff_t(m_pendingCount), m_pending.begin());
    m_pendingCount -= expired;
}

WrenchTiming::Stats WrenchTiming::stats(double now) const
{
    Stats s;
    if (std::isfinite(m_lastArrival))
        s.age = now - m_lastArrival;
    s.stampDelay = m_stampDelays.spread();
    s.echoDelay = m_echoDelays.spread();
    s.interval = m_intervals.spread().median;
    s.lost = m_lost;
    s.pauses = m_pauses;
    s.unstamped = m_unstamped;
    return s;
}

} // namespace hatpic::bridge
