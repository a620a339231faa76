#include "plots/decimator.h"

#include "plots/samplebuffer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hatpic {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

//! Min and max of one pixel column, with the times they occurred.
struct Bucket
{
    int index = -1;
    double firstT = 0;
    double minT = 0, minV = 0;
    double maxT = 0, maxV = 0;
    bool hasValue = false;
    bool hasSample = false;

    void reset(int i)
    {
        index = i;
        hasValue = false;
        hasSample = false;
    }
    void add(double t, double v)
    {
        if (!hasSample) {
            firstT = t;
            hasSample = true;
        }
        if (std::isnan(v))
            return;
        if (!hasValue) {
            minT = maxT = t;
            minV = maxV = v;
            hasValue = true;
            return;
        }
        if (v < minV) {
            minV = v;
            minT = t;
        }
        if (v > maxV) {
            maxV = v;
            maxT = t;
        }
    }
};

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

    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    auto note = [&](double v) {
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    };

    double prevT = 0;
    bool hasPrev = false;
    auto gapBefore = [&](double t) {
        const bool isGap = hasPrev && t - prevT > m_gap;
        if (isGap)
            out.append(QCPGraphData((prevT + t) / 2, kNaN));
        return isGap;
    };

    if (!result.decimated) {
        for (qsizetype i = from; i < to; ++i) {
            const double t = buffer.time(i);
            const double v = buffer.value(channel, i) * scale;
            gapBefore(t);
            out.append(QCPGraphData(t, v));
            if (i >= first && i < last)
                note(v);
            prevT = t;
            hasPrev = true;
        }
    } else {
        const double width = (t1 - t0) / m_pixels;
        Bucket bucket;
        auto flush = [&] {
            if (bucket.index < 0 || !bucket.hasSample)
                return;
            if (!bucket.hasValue) {
                out.append(QCPGraphData(bucket.firstT, kNaN));
            } else if (bucket.minT == bucket.maxT) {
                out.append(QCPGraphData(bucket.minT, bucket.minV));
            } else if (bucket.minT < bucket.maxT) {
                out.append(QCPGraphData(bucket.minT, bucket.minV));
                out.append(QCPGraphData(bucket.maxT, bucket.maxV));
            } else {
                out.append(QCPGraphData(bucket.maxT, bucket.maxV));
                out.append(QCPGraphData(bucket.minT, bucket.minV));
            }
            bucket.reset(-1);
        };

        if (from < first) {
            prevT = buffer.time(from);
            out.append(QCPGraphData(prevT, buffer.value(channel, from) * scale));
            hasPrev = true;
        }
        for (qsizetype i = first; i < last; ++i) {
            const double t = buffer.time(i);
            const double v = buffer.value(channel, i) * scale;
            if (hasPrev && t - prevT > m_gap) {
                flush();
                gapBefore(t);
            }
            const int column = std::clamp(static_cast<int>((t - t0) / width), 0, m_pixels - 1);
            if (column != bucket.index) {
                flush();
                bucket.reset(column);
            }
            bucket.add(t, v);
            note(v);
            prevT = t;
            hasPrev = true;
        }
        flush();
        if (last < to) {
            const double t = buffer.time(last);
            gapBefore(t);
            out.append(QCPGraphData(t, buffer.value(channel, last) * scale));
        }
    }

    if (lo <= hi) {
        result.min = lo;
        result.max = hi;
        result.hasValues = true;
    }
    return result;
}

} // namespace hatpic
