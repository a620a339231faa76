#include "rttstats.h"

#include <algorithm>

namespace hatpic {

void RttStats::add(double ms)
{
    if (m_window.size() < kWindow) {
        m_window.append(ms);
    } else {
        m_window[m_next] = ms;
        m_next = (m_next + 1) % kWindow;
    }
    ++m_count;
    m_last = ms;
    m_max = std::max(m_max, ms);
}

void RttStats::clear()
{
    *this = RttStats();
}

double RttStats::median() const
{
    if (m_window.isEmpty())
        return -1;
    QList<double> sorted = m_window;
    std::sort(sorted.begin(), sorted.end());
    const qsizetype n = sorted.size();
    return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

} // namespace hatpic
