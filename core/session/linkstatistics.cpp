#include "linkstatistics.h"

namespace hatpic {

void LinkStatistics::clear()
{
    m_stats = {};
    m_dropBase = {};
    m_legacyMalformedBase = 0;
    m_rateMarks.clear();
    m_telemetrySeq.reset();
}

void LinkStatistics::countBytes(qsizetype n, qint64 nowNs)
{
    m_lastRxNs = nowNs;
    m_stats.bytes += static_cast<quint64>(n);
}

bool LinkStatistics::countTelemetry(quint8 seq, quint32 tUs)
{
    ++m_stats.frames;
    const TelemetrySequence::Step step = m_telemetrySeq.accept(seq, tUs);
    if (step.duplicate) { // the same frame again (a link that repeats): one sample only
        ++m_stats.duplicates;
        return false;
    }
    m_stats.seqDrops += step.missing;
    return true;
}

void LinkStatistics::absorb(const v2::DecoderStats &stats)
{
    for (int i = 0; i < v2::kDropReasonCount; ++i)
        m_dropBase[i] += stats.drops[i];
}

void LinkStatistics::absorb(const legacy::DecoderStats &stats)
{
    m_legacyMalformedBase += stats.malformed;
}

void LinkStatistics::tick(qint64 nowNs)
{
    m_rateMarks.push_back({nowNs, m_stats.frames, m_stats.bytes});
    // Rates over the last second: the oldest mark at least 1 s old (or the oldest we have).
    while (m_rateMarks.size() > 2 && nowNs - m_rateMarks[1].ns >= 1'000'000'000)
        m_rateMarks.pop_front();
    const RateMark &from = m_rateMarks.front();
    const double seconds = static_cast<double>(nowNs - from.ns) * 1e-9;
    if (seconds > 0) {
        m_stats.framesPerSecond = static_cast<double>(m_stats.frames - from.frames) / seconds;
        m_stats.bytesPerSecond = static_cast<double>(m_stats.bytes - from.bytes) / seconds;
    }
}

LinkStats LinkStatistics::snapshot(const v2::DecoderStats *v2,
                                   const legacy::DecoderStats *legacy) const
{
    LinkStats s = m_stats;
    for (int i = 0; i < v2::kDropReasonCount; ++i)
        s.decoderDrops[i] = m_dropBase[i] + (v2 ? v2->drops[i] : 0);
    s.legacyMalformed = m_legacyMalformedBase + (legacy ? legacy->malformed : 0);
    return s;
}

} // namespace hatpic
