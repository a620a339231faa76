// Reduces one channel of a SampleBuffer to what a plot of a given pixel width can show.
//
// When a time range holds more samples than twice the plot's pixel columns, each column keeps
// only its minimum and its maximum (in time order), so a 1 kHz stream drawn on 800 pixels shows
// every peak without drawing 60 000 points. Fewer samples are passed through unchanged. A time
// step longer than the gap (kDefaultGap) becomes a NaN point, which breaks the line (link loss,
// reconnection).
#pragma once

#include "plots/channel.h"
#include "plots/qcp.h"

namespace hatpic {

class SampleBuffer;

struct DecimationResult
{
    qsizetype rawCount = 0; //!< samples inside [t0, t1]
    bool decimated = false; //!< min/max per column was used
    double min = 0;         //!< smallest finite value inside [t0, t1], scaled
    double max = 0;         //!< largest finite value inside [t0, t1], scaled
    bool hasValues = false; //!< min/max are set
};

class Decimator
{
public:
    static constexpr double kDefaultGap = 0.25; //!< longest step drawn as a line [s]

    explicit Decimator(int pixels = 1000, double gap = kDefaultGap);

    void setPixels(int pixels); //!< clamped to ≥ 1

    //! Replaces `out` with the points of `channel` over [t0, t1] (plus one neighbour on each
    //! side so lines reach the edges), values multiplied by `scale` (unit conversion).
    DecimationResult run(const SampleBuffer &buffer, Channel channel, double t0, double t1,
                         double scale, QVector<QCPGraphData> &out) const;

private:
    int m_pixels;
    double m_gap;
};

} // namespace hatpic
