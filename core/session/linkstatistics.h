// The link's figures over one connectDevice(): bytes, frames, seq gaps, skipped frames,
// resends, decoder drops (kept across reconnects), receive rates over the last second and
// the time of the last byte (for the silence watchdog).
#pragma once

#include "protocol/legacy.h"
#include "protocol/v2codec.h"
#include "session/sessiontypes.h"
#include "session/telemetrysequence.h"

#include <array>
#include <deque>

namespace hatpic {

class LinkStatistics
{
public:
    //! Back to zero (a new connectDevice()).
    void clear();

    void countBytes(qsizetype n, qint64 nowNs);
    void markReceived(qint64 nowNs) { m_lastRxNs = nowNs; }
    qint64 lastReceivedNs() const { return m_lastRxNs; }
    void countFrame() { ++m_stats.frames; }
    //! A telemetry frame's seq and device time [µs]: frames missing since the last one count
    //! as drops. False for a frame seen already (counted as a duplicate: make no sample of it).
    bool countTelemetry(quint8 seq, quint32 tUs);
    //! The next telemetry seq starts a new count (a new stream or connection).
    void restartSeq() { m_telemetrySeq.reset(); }
    void countNonFinite() { ++m_stats.nonFinite; }
    void countRetry() { ++m_stats.retries; }

    //! Keeps the drop counts of a decoder that is going away.
    void absorb(const v2::DecoderStats &stats);
    void absorb(const legacy::DecoderStats &stats);

    //! Updates the rates over the last second.
    void tick(qint64 nowNs);

    //! The figures so far; `v2` and `legacy` are the live decoders' counts (may be null).
    LinkStats snapshot(const v2::DecoderStats *v2, const legacy::DecoderStats *legacy) const;

private:
    struct RateMark
    {
        qint64 ns;
        quint64 frames;
        quint64 bytes;
    };

    LinkStats m_stats; //!< counters; decoder drops of closed decoders are in m_dropBase
    std::array<quint64, v2::kDropReasonCount> m_dropBase{};
    quint64 m_legacyMalformedBase = 0;
    std::deque<RateMark> m_rateMarks;
    TelemetrySequence m_telemetrySeq;
    qint64 m_lastRxNs = 0;
};

} // namespace hatpic
