#include "plots/latencyprobe.h"

#include <algorithm>
#include <cmath>

namespace hatpic {

void LatencyProbe::arrived(const SampleBatch &batch)
{
    for (const Sample &sample : batch) {
        if (sample.arrival_ns == 0)
            continue;
        if (m_waiting.size() + m_drawn.size() >= kMaxWaiting) {
            ++m_dropped;
            continue;
        }
        m_waiting.push_back(sample.arrival_ns);
    }
}

void LatencyProbe::drawn()
{
    m_drawn.insert(m_drawn.end(), m_waiting.begin(), m_waiting.end());
    m_waiting.clear();
}

void LatencyProbe::painted(std::int64_t nowNs)
{
    for (const std::int64_t arrival : m_drawn)
        record(nowNs - arrival);
    m_drawn.clear();
}

void LatencyProbe::discard()
{
    m_dropped += m_waiting.size() + m_drawn.size();
    m_waiting.clear();
    m_drawn.clear();
}

void LatencyProbe::record(std::int64_t latencyNs)
{
    latencyNs = std::max<std::int64_t>(latencyNs, 0);
    const auto bin = static_cast<std::size_t>(static_cast<double>(latencyNs) / 1e6 / kBinMs);
    ++m_bins[std::min(bin, kBins - 1)];
    ++m_count;
    m_maxNs = std::max(m_maxNs, latencyNs);
}

LatencyProbe::Summary LatencyProbe::summary() const
{
    Summary s;
    s.count = m_count;
    s.dropped = m_dropped;
    s.maxMs = static_cast<double>(m_maxNs) / 1e6;
    if (m_count == 0)
        return s;
    // The bin holding the sample of rank ⌈q·count⌉, reported by its upper edge (never below
    // the true value); the last bin is open-ended, so it reports the maximum.
    const auto edge = [&](double q) {
        const auto rank = static_cast<std::uint64_t>(std::max(1.0, std::ceil(q * m_count)));
        std::uint64_t seen = 0;
        for (std::size_t i = 0; i < kBins; ++i) {
            seen += m_bins[i];
            if (seen >= rank)
                return i + 1 == kBins ? s.maxMs : std::min((i + 1) * kBinMs, s.maxMs);
        }
        return s.maxMs;
    };
    s.medianMs = edge(0.5);
    s.p95Ms = edge(0.95);
    return s;
}

void LatencyProbe::resetSummary()
{
    m_bins.fill(0);
    m_count = 0;
    m_dropped = 0;
    m_maxNs = 0;
}

} // namespace hatpic
