#include "plots/plotghost.h"

#include "plots/displayunits.h"
#include "plots/plotframe.h"
#include "plots/qcp.h"
#include "plots/samplebuffer.h"

#include <algorithm>

namespace hatpic {

PlotGhost::PlotGhost(const PlotFrame &frame)
{
    for (Channel channel : kAllChannels) {
        QCPGraph *main = frame.graph(channel);
        auto *g = new QCPGraph(main->keyAxis(), main->valueAxis());
        g->removeFromLegend();
        QPen pen = main->pen();
        QColor color = pen.color();
        color.setAlpha(kAlpha);
        pen.setColor(color);
        pen.setWidthF(std::max(pen.widthF(), 1.5));
        g->setPen(pen);
        g->setSelectable(QCP::stNone);
        g->setVisible(false);
        // Beneath the main data, so the recording replayed stays in front.
        g->setLayer(main->layer());
        m_graphs[channelIndex(channel)] = g;
    }
}

void PlotGhost::rebuild(const PlotFrame &frame, Decimator &decimator, double t0, double t1,
                        const DisplayUnits &units)
{
    for (Channel channel : kAllChannels) {
        QCPGraph *g = graph(channel);
        const bool shown = m_source && !m_source->isEmpty() && frame.graph(channel)->visible();
        g->setVisible(shown);
        if (!shown) {
            g->data()->clear();
            continue;
        }
        QVector<QCPGraphData> points;
        decimator.run(*m_source, channel, t0, t1, units.scale(channel), points);
        g->data()->set(points, true);
    }
}

} // namespace hatpic
