// A bounded, preallocated ring of samples stored column by column, for the live plots.
//
// Owned and used by one thread (the GUI thread). Appending never allocates: when the ring is
// full the oldest sample is overwritten. Times are kept non-decreasing so that lookups by time
// can bisect: a sample whose time goes backwards (a new session restarting its clock) is moved
// to kRestartGap after the newest one, and every later sample of that run keeps the same shift.
#pragma once

#include "model/effects.h"
#include "plots/channel.h"
#include "telemetry/sample.h"

#include <algorithm>
#include <array>
#include <optional>
#include <ranges>
#include <vector>

namespace hatpic {

class SampleBuffer
{
public:
    static constexpr qsizetype kDefaultCapacity = 120'000; //!< 120 s at 1 kHz [samples]
    static constexpr double kRestartGap = 0.5;             //!< spacing after a clock restart [s]

    explicit SampleBuffer(qsizetype capacity = kDefaultCapacity);

    void append(const Sample &sample);
    void append(const SampleBatch &batch);
    void clear();

    //! The effect block and θ0 [rad] that τ_fx's parts (TauDet, TauWall, TauVib) of the samples
    //! appended from now on are computed with (splitEffectTorque). nullopt (the default):
    //! unknown, so the parts are NaN; they are NaN too wherever τ_fx is.
    void setEffects(const std::optional<EffectParams> &effects, double theta0);

    qsizetype size() const { return m_size; }
    qsizetype capacity() const { return m_capacity; }
    bool isEmpty() const { return m_size == 0; }

    //! Index 0 is the oldest sample kept, size()−1 the newest. Indices are not checked.
    double time(qsizetype index) const { return m_time[slot(index)]; } //!< [s]
    double value(Channel channel, qsizetype index) const               //!< SI
    {
        return m_values[channelIndex(channel)][slot(index)];
    }
    quint16 flags(qsizetype index) const { return m_flags[slot(index)]; }
    Sample sample(qsizetype index) const; //!< t_s is the buffer's (possibly shifted) time

    double firstTime() const; //!< 0 when empty [s]
    double lastTime() const;  //!< 0 when empty [s]

    qsizetype lowerBound(double t) const; //!< first index with time ≥ t; size() if none
    qsizetype upperBound(double t) const; //!< first index with time > t; size() if none
    qsizetype nearest(double t) const;    //!< index closest in time to t; −1 when empty

    //! A stretch of indices whose slots are contiguous: the samples at indices
    //! [index, index + count) sit in the slots [slot, slot + count) of timeSlots() and
    //! valueSlots().
    struct Run
    {
        qsizetype index = 0;
        qsizetype slot = 0;
        qsizetype count = 0;
    };
    //! The indices [first, last) as at most two runs (the second is empty unless they wrap
    //! around the ring), for loops that read many samples in order. Indices are not checked.
    std::array<Run, 2> runs(qsizetype first, qsizetype last) const;
    const double *timeSlots() const { return m_time.data(); } //!< [s], by slot
    const double *valueSlots(Channel channel) const           //!< SI, by slot
    {
        return m_values[channelIndex(channel)].data();
    }

    //! Changes whenever the content changes, so a reader can tell it needs to redraw.
    quint64 generation() const { return m_generation; }
    quint64 appendedCount() const { return m_appended; }       //!< samples ever appended
    quint64 overwrittenCount() const { return m_overwritten; } //!< oldest samples dropped
    quint64 restartCount() const { return m_restarts; }        //!< clock restarts shifted

private:
    //! The first index at which `before` is false; it holds for a prefix (times only grow).
    template<class Before> qsizetype partitionPoint(Before before) const
    {
        const auto indices = std::views::iota(qsizetype(0), m_size);
        return std::ranges::partition_point(indices, before) - indices.begin();
    }
    qsizetype slot(qsizetype index) const
    {
        const qsizetype s = m_head + index;
        return s >= m_capacity ? s - m_capacity : s;
    }

    qsizetype m_capacity = 0;
    qsizetype m_head = 0; //!< slot of the oldest sample
    qsizetype m_size = 0;
    std::vector<double> m_time;
    std::array<std::vector<double>, kChannelCount> m_values;
    std::vector<quint16> m_flags;
    std::array<std::vector<double>, kUnplottedColumns.size()> m_unplotted; //!< kUnplottedColumns
    std::optional<EffectParams> m_effects;
    double m_effectsTheta0 = 0; //!< [rad]
    double m_shift = 0;         //!< added to incoming t_s after a clock restart [s]
    double m_lastInput = 0;     //!< last t_s received, before the shift [s]
    bool m_hasInput = false;
    quint64 m_generation = 0;
    quint64 m_appended = 0;
    quint64 m_overwritten = 0;
    quint64 m_restarts = 0;
};

} // namespace hatpic
