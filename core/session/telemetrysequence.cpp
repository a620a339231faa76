#include "telemetrysequence.h"

#include <cmath>

namespace hatpic {

TelemetrySequence::Step TelemetrySequence::accept(quint8 seq, quint32 tUs)
{
    Step step;
    for (int i = 0; i < m_recentCount; ++i) {
        if (m_recent[std::size_t(i)].seq == seq && m_recent[std::size_t(i)].tUs == tUs) {
            step.duplicate = true;
            return step;
        }
    }
    if (m_last) {
        const auto gap = quint64(quint8(seq - m_last->seq - 1));
        const auto elapsed = qint64(quint32(tUs - m_last->tUs)); // the clock wraps at 2³² µs
        step.missing = gap;
        if (m_periodUs > 0 && elapsed > 0) {
            // The frames that fit in the gap, to the nearest count that the seq allows.
            const double fit = double(elapsed) / double(m_periodUs) - 1.0;
            const double wraps = std::round((fit - double(gap)) / 256.0);
            if (wraps > 0)
                step.missing = gap + 256 * quint64(wraps);
        }
        if (step.missing == 0 && elapsed > 0)
            m_periodUs = elapsed;
    }
    m_last = Seen{seq, tUs};
    m_recent[std::size_t(m_recentNext)] = *m_last;
    m_recentNext = (m_recentNext + 1) % kRecent;
    if (m_recentCount < kRecent)
        ++m_recentCount;
    return step;
}

void TelemetrySequence::reset()
{
    m_last.reset();
    m_periodUs = 0;
    m_recentCount = 0;
    m_recentNext = 0;
}

} // namespace hatpic
