// How long a live sample waits between its arrival on the host (its frame decoded by the
// session) and the first painted frame of the plots that shows it: issue 10's "sample arrival
// → frame" latency, measured in the running tuner.
//
// The plots tell the probe three moments: samples arrived (with their Sample::arrival_ns),
// the data were drawn into the plot's buffer (everything arrived so far is in it), and the
// widget painted that buffer. A sample's latency is paint time − arrival time. Bounded: at
// most kMaxWaiting arrivals wait for a paint (more are counted as dropped), and the latencies
// go into a fixed histogram.
#pragma once

#include "telemetry/sample.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hatpic {

class LatencyProbe
{
public:
    static constexpr std::size_t kMaxWaiting = 16'384; //!< arrivals kept until a paint
    static constexpr double kBinMs = 0.5;              //!< histogram resolution [ms]
    static constexpr std::size_t kBins = 2000;         //!< up to 1 s; longer ones in the last

    struct Summary
    {
        std::uint64_t count = 0;   //!< samples measured
        std::uint64_t dropped = 0; //!< arrivals never measured (too many waiting, or discarded)
        double medianMs = 0;       //!< upper edge of the median's bin [ms]
        double p95Ms = 0;          //!< upper edge of the 95th percentile's bin [ms]
        double maxMs = 0;          //!< exact [ms]
    };

    //! Samples arrived; those with an arrival time (live ones) wait for their paint.
    void arrived(const SampleBatch &batch);
    //! Everything arrived so far was drawn into the plot's buffer.
    void drawn();
    //! The widget painted at `nowNs` (sampleClockNs()): the drawn samples are on screen.
    void painted(std::int64_t nowNs);
    //! The samples waiting will not be shown (paused, replay): counted as dropped.
    void discard();

    Summary summary() const;
    //! Starts a new measurement window (the summary's counts restart; waiting samples stay).
    void resetSummary();

private:
    void record(std::int64_t latencyNs);

    std::vector<std::int64_t> m_waiting; //!< arrivals not yet drawn
    std::vector<std::int64_t> m_drawn;   //!< arrivals drawn, not yet painted
    std::array<std::uint32_t, kBins> m_bins{};
    std::uint64_t m_count = 0;
    std::uint64_t m_dropped = 0;
    std::int64_t m_maxNs = 0;
};

} // namespace hatpic
