// The telemetry stream's seq and device clock, read for frames lost and frames seen twice.
//
// seq is a u8 (protocol.md § 2): a gap alone counts losses modulo 256, so a link cut for a
// second at 1 kHz would look like a few frames lost. The device clock t_us settles how many
// times the seq wrapped: with the period learnt from consecutive frames, a gap counts the
// frames that fit in it, rounded to the seq's own count. A frame whose (seq, t_us) is among
// the last kRecent accepted is a duplicate: it was seen already and is no new sample.
#pragma once

#include <QtGlobal>

#include <array>
#include <optional>

namespace hatpic {

class TelemetrySequence
{
public:
    static constexpr int kRecent = 32; //!< frames remembered for spotting duplicates

    struct Step
    {
        bool duplicate = false; //!< seen already: count it, make no sample of it
        quint64 missing = 0;    //!< frames lost between the previous frame and this one
    };

    //! Reads one TELEMETRY frame's seq and device time [µs].
    Step accept(quint8 seq, quint32 tUs);
    //! Forgets the stream (a new connection, a new SET_STREAM): the next frame starts it.
    void reset();

private:
    struct Seen
    {
        quint8 seq = 0;
        quint32 tUs = 0;
    };
    std::optional<Seen> m_last;
    qint64 m_periodUs = 0; //!< device time between consecutive frames; 0 = not known yet
    std::array<Seen, kRecent> m_recent{};
    int m_recentCount = 0;
    int m_recentNext = 0;
};

} // namespace hatpic
