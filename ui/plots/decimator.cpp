#include "plots/decimator.h"

#include "plots/samplebuffer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hatpic {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

//! Smallest and largest finite value seen.
struct Range
{
    double lo = kInf;
    double hi = -kInf;
    void note(double v)
    {
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
};

//! One pixel column's bucket: the min and max of its samples, with their times.
struct Bucket
{
    int column = -1;     //!< −1: none open
    qsizetype start = 0; //!< index of the first sample
    double firstT = 0;   //!< [s]
    double minT = 0, minV = 0;
    double maxT = 0, maxV = 0;
    bool hasValue = false; //!< min and max are set (not every sample was NaN)
};

//! The min/max pass over the samples [first, last) inside [t0, t1], one pixel column after
//! another; `prevT` and `hasPrev` describe the sample before (the line's last point so far) and
//! come back describing the last one. Written for the 60 000 samples of a full window: the
//! samples are read run by run from the buffer's columns, the state stays in registers, the
//! column index is computed only near a column's edge, and the range of values is taken from
//! each bucket's extremes instead of from every sample.
void scanColumns(const SampleBuffer &buffer, Channel channel, qsizetype first, qsizetype last,
                 double t0, double t1, int pixels, double gap, double scale,
                 QVector<QCPGraphData> &out, Range &range, double &prevT, bool &hasPrev)
{
    const double width = (t1 - t0) / pixels;
    // Below `edge` a sample is certainly in the open column: the margin is far above the
    // rounding of t − t0 and of the edge itself, so every sample at or past it gets the very
    // column int((t − t0) / width) gives.
    const double margin = width * 1e-6 + (std::abs(t0) + std::abs(t1)) * 1e-13;
    Bucket b;
    double edge = -kInf;
    // Draws the open bucket (ending before index `end`): its min and max in time order (one
    // point when they coincide), or a NaN point when all its samples are NaN.
    auto flush = [&](qsizetype end) {
        if (b.column < 0)
            return;
        b.column = -1;
        if (!b.hasValue) {
            out.append(QCPGraphData(b.firstT, kNaN));
            return;
        }
        if (b.minT == b.maxT) {
            out.append(QCPGraphData(b.minT, b.minV));
        } else if (b.minT < b.maxT) {
            out.append(QCPGraphData(b.minT, b.minV));
            out.append(QCPGraphData(b.maxT, b.maxV));
        } else {
            out.append(QCPGraphData(b.maxT, b.maxV));
            out.append(QCPGraphData(b.minT, b.minV));
        }
        if (std::isfinite(b.minV) && std::isfinite(b.maxV)) {
            range.note(b.minV); // every other value of the bucket lies between them
            range.note(b.maxV);
        } else {
            for (qsizetype i = b.start; i < end; ++i) // ±Inf: the finite ones, one by one
                range.note(buffer.value(channel, i) * scale);
        }
    };

    const double *times = buffer.timeSlots();
    const double *values = buffer.valueSlots(channel);
    for (const SampleBuffer::Run &run : buffer.runs(first, last)) {
        const double *tRun = times + run.slot;
        const double *vRun = values + run.slot;
        for (qsizetype k = 0; k < run.count; ++k) {
            const double t = tRun[k];
            const double v = vRun[k] * scale;
            if (hasPrev && t - prevT > gap) {
                flush(run.index + k); // a gap closes the bucket and breaks the line
                out.append(QCPGraphData((prevT + t) / 2, kNaN));
                edge = -kInf;
            }
            prevT = t;
            hasPrev = true;
            if (!(t < edge)) {
                const int column = std::clamp(static_cast<int>((t - t0) / width), 0, pixels - 1);
                if (column != b.column) {
                    flush(run.index + k);
                    b.column = column;
                    b.start = run.index + k;
                    b.firstT = t;
                    b.hasValue = false;
                }
                edge = column + 1 < pixels ? t0 + (column + 1) * width - margin : kInf;
            }
            if (std::isnan(v))
                continue;
            if (!b.hasValue) {
                b.hasValue = true;
                b.minT = b.maxT = t;
                b.minV = b.maxV = v;
                continue;
            }
            if (v < b.minV) {
                b.minV = v;
                b.minT = t;
            }
            if (v > b.maxV) {
                b.maxV = v;
                b.maxT = t;
            }
        }
    }
    flush(last);
}

} // namespace

Decimator::Decimator(int pixels, double gap) : m_pixels(std::max(pixels, 1)), m_gap(gap) {}

void Decimator::setPixels(int pixels)
{
    m_pixels = std::max(pixels, 1);
}

DecimationResult Decimator::run(const SampleBuffer &buffer, Channel channel, double t0, double t1,
                                double scale, QVector<QCPGraphData> &out) const
{
    DecimationResult result;
    out.resize(0);
    if (buffer.isEmpty() || !(t1 > t0))
        return result;

    const qsizetype first = buffer.lowerBound(t0); // inside: [first, last)
    const qsizetype last = buffer.upperBound(t1);
    const qsizetype from = std::max<qsizetype>(first - 1, 0);
    const qsizetype to = std::min<qsizetype>(last + 1, buffer.size());
    result.rawCount = last - first;
    result.decimated = result.rawCount > 2 * qsizetype(m_pixels);
    out.reserve(result.decimated ? 2 * m_pixels + 16 : (to - from) + 16);

    Range range;
    double prevT = 0;
    bool hasPrev = false;
    auto gapBefore = [&](double t) {
        if (hasPrev && t - prevT > m_gap)
            out.append(QCPGraphData((prevT + t) / 2, kNaN));
    };

    if (!result.decimated) {
        for (qsizetype i = from; i < to; ++i) {
            const double t = buffer.time(i);
            const double v = buffer.value(channel, i) * scale;
            gapBefore(t);
            out.append(QCPGraphData(t, v));
            if (i >= first && i < last)
                range.note(v);
            prevT = t;
            hasPrev = true;
        }
    } else {
        if (from < first) { // the neighbour before the range, so the line reaches the edge
            prevT = buffer.time(from);
            out.append(QCPGraphData(prevT, buffer.value(channel, from) * scale));
            hasPrev = true;
        }
        scanColumns(buffer, channel, first, last, t0, t1, m_pixels, m_gap, scale, out, range, prevT,
                    hasPrev);
        if (last < to) {
            const double t = buffer.time(last);
            gapBefore(t);
            out.append(QCPGraphData(t, buffer.value(channel, last) * scale));
        }
    }

    if (range.lo <= range.hi) {
        result.min = range.lo;
        result.max = range.hi;
        result.hasValues = true;
    }
    return result;
}

} // namespace hatpic
