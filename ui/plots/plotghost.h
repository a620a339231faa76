// A second recording drawn fainter on the same plots: one graph per channel beside each of
// PlotFrame's, on the same axes, in the channel's colour made translucent, out of the legends.
// It follows the channel's visibility and is decimated like the main data.
//
// Not a widget: it owns nothing but QCustomPlot graphs, which the plot deletes with itself.
#pragma once

#include "plots/channel.h"
#include "plots/decimator.h"

#include <QVector>

#include <array>

class QCPGraph;
class QCPGraphData;

namespace hatpic {

class DisplayUnits;
class PlotFrame;
class SampleBuffer;

class PlotGhost
{
public:
    static constexpr int kAlpha = 90; //!< opacity of the overlay's pens (of 255)

    explicit PlotGhost(const PlotFrame &frame);

    //! The buffer drawn fainter (not owned); nullptr hides the overlay.
    void setSource(const SampleBuffer *source) { m_source = source; }
    const SampleBuffer *source() const { return m_source; }

    //! Decimates the overlay over [t0, t1] for every channel whose main graph is visible.
    void rebuild(const PlotFrame &frame, Decimator &decimator, double t0, double t1,
                 const DisplayUnits &units);

    QCPGraph *graph(Channel channel) const { return m_graphs[channelIndex(channel)]; }

private:
    std::array<QCPGraph *, kChannelCount> m_graphs{};
    const SampleBuffer *m_source = nullptr;
};

} // namespace hatpic
