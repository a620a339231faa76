#include "periodhistogram.h"

#include <algorithm>
#include <cmath>

namespace hatpic {

PeriodHistogram::PeriodHistogram() : m_bins(std::size_t(kRangeUs) + 1, 0) {}

void PeriodHistogram::add(std::int64_t us)
{
    us = std::max<std::int64_t>(us, 0);
    ++m_bins[std::size_t(std::min(us, kRangeUs))];
    m_minUs = m_count ? std::min(m_minUs, us) : us;
    m_maxUs = m_count ? std::max(m_maxUs, us) : us;
    m_sumUs += us;
    ++m_count;
}

void PeriodHistogram::clear()
{
    std::fill(m_bins.begin(), m_bins.end(), 0);
    m_count = 0;
    m_sumUs = 0;
    m_minUs = 0;
    m_maxUs = 0;
}

std::int64_t PeriodHistogram::percentileUs(double p) const
{
    if (m_count == 0)
        return 0;
    const auto rank = std::uint64_t(std::ceil(std::clamp(p, 0.0, 1.0) * double(m_count)));
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < m_bins.size(); ++i) {
        seen += m_bins[i];
        if (seen >= std::max<std::uint64_t>(rank, 1))
            return std::int64_t(i);
    }
    return kRangeUs;
}

} // namespace hatpic
