#include "plots/samplebuffer.h"

#include "model/staticcurve.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hatpic {

SampleBuffer::SampleBuffer(qsizetype capacity) : m_capacity(std::max<qsizetype>(capacity, 1))
{
    const auto n = static_cast<std::size_t>(m_capacity);
    m_time.resize(n);
    for (auto &column : m_values)
        column.resize(n);
    m_flags.resize(n);
    for (auto &column : m_unplotted)
        column.resize(n);
}

void SampleBuffer::append(const Sample &sample)
{
    double t = sample.t_s;
    if (!std::isfinite(t))
        return; // no place on a time axis
    if (m_hasInput && t < m_lastInput && m_size > 0) {
        // The source clock went backwards: keep the axis monotonic, leave a visible gap.
        m_shift = lastTime() + kRestartGap - t;
        ++m_restarts;
    }
    m_hasInput = true;
    m_lastInput = t;
    t += m_shift;
    if (m_size > 0 && t < lastTime())
        t = lastTime(); // cannot happen unless the shift was rounded; keep order anyway

    qsizetype s;
    if (m_size < m_capacity) {
        s = slot(m_size);
        ++m_size;
    } else {
        s = m_head;
        m_head = m_head + 1 == m_capacity ? 0 : m_head + 1;
        ++m_overwritten;
    }
    const auto u = static_cast<std::size_t>(s);
    m_time[u] = t;
    for (Channel channel : kAllChannels) {
        if (isSampleChannel(channel))
            m_values[channelIndex(channel)][u] = channelValue(sample, channel);
    }
    constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
    EffectTorques parts{kUnknown, kUnknown, kUnknown};
    if (m_effects)
        parts = splitEffectTorque(*m_effects, m_effectsTheta0, sample.theta, sample.omega,
                                  sample.tau_fx);
    m_values[channelIndex(Channel::TauDet)][u] = parts.det;
    m_values[channelIndex(Channel::TauWall)][u] = parts.wall;
    m_values[channelIndex(Channel::TauVib)][u] = parts.vib;
    m_flags[u] = sample.flags;
    for (std::size_t k = 0; k < kUnplottedColumns.size(); ++k)
        m_unplotted[k][u] = sample.*kSampleColumns[kUnplottedColumns[k]].value;
    ++m_appended;
    ++m_generation;
}

void SampleBuffer::append(const SampleBatch &batch)
{
    for (const Sample &sample : batch)
        append(sample);
}

void SampleBuffer::setEffects(const std::optional<EffectParams> &effects, double theta0)
{
    m_effects = effects;
    m_effectsTheta0 = theta0;
}

void SampleBuffer::clear()
{
    m_head = 0;
    m_size = 0;
    m_shift = 0;
    m_lastInput = 0;
    m_hasInput = false;
    ++m_generation;
}

Sample SampleBuffer::sample(qsizetype index) const
{
    Sample s;
    s.t_s = time(index);
    s.t_us = static_cast<quint32>(std::llround(std::fmod(s.t_s * 1e6, 4294967296.0)));
    for (Channel channel : kAllChannels) {
        if (isSampleChannel(channel))
            s.*channelColumn(channel).value = value(channel, index);
    }
    s.flags = flags(index);
    for (std::size_t k = 0; k < kUnplottedColumns.size(); ++k)
        s.*kSampleColumns[kUnplottedColumns[k]].value =
            m_unplotted[k][static_cast<std::size_t>(slot(index))];
    return s;
}

std::array<SampleBuffer::Run, 2> SampleBuffer::runs(qsizetype first, qsizetype last) const
{
    std::array<Run, 2> out{};
    if (last <= first)
        return out;
    const qsizetype start = slot(first);
    const qsizetype count = last - first;
    const qsizetype untilEnd = m_capacity - start;
    if (count <= untilEnd) {
        out[0] = {first, start, count};
    } else {
        out[0] = {first, start, untilEnd};
        out[1] = {first + untilEnd, 0, count - untilEnd};
    }
    return out;
}

double SampleBuffer::firstTime() const
{
    return m_size > 0 ? time(0) : 0.0;
}

double SampleBuffer::lastTime() const
{
    return m_size > 0 ? time(m_size - 1) : 0.0;
}

qsizetype SampleBuffer::lowerBound(double t) const
{
    return partitionPoint([&](qsizetype i) { return time(i) < t; });
}

qsizetype SampleBuffer::upperBound(double t) const
{
    return partitionPoint([&](qsizetype i) { return time(i) <= t; });
}

qsizetype SampleBuffer::nearest(double t) const
{
    if (m_size == 0)
        return -1;
    const qsizetype i = lowerBound(t);
    if (i == 0)
        return 0;
    if (i == m_size)
        return m_size - 1;
    return (t - time(i - 1) <= time(i) - t) ? i - 1 : i;
}

} // namespace hatpic
