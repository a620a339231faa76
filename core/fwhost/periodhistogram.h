// Timing statistics of a periodic loop: a histogram of durations in 1 µs bins, so that
// percentiles of a long run cost a fixed amount of memory and no allocation per sample.
#pragma once

#include <cstdint>
#include <vector>

namespace hatpic {

class PeriodHistogram
{
public:
    static constexpr std::int64_t kRangeUs = 20000; //!< durations ≥ this share the last bin [µs]

    PeriodHistogram(); //!< allocates the bins (the only allocation)

    void add(std::int64_t us); //!< one duration [µs]; negative counts as 0
    void clear();

    std::uint64_t count() const { return m_count; }
    double meanUs() const { return m_count ? double(m_sumUs) / double(m_count) : 0.0; }
    std::int64_t minUs() const { return m_count ? m_minUs : 0; }
    std::int64_t maxUs() const { return m_count ? m_maxUs : 0; } //!< exact, even beyond range
    //! The smallest duration d with at least fraction `p` (0…1) of the samples ≤ d [µs];
    //! kRangeUs when that falls in the overflow bin (read maxUs() then).
    std::int64_t percentileUs(double p) const;

private:
    std::vector<std::uint32_t> m_bins;
    std::uint64_t m_count = 0;
    std::int64_t m_sumUs = 0;
    std::int64_t m_minUs = 0;
    std::int64_t m_maxUs = 0;
};

} // namespace hatpic
