// An XY view of any two channels over the time plots' visible range: one quantity against the
// other (θ–ω, the phase plane, by default), the path fading with age and a dot at the newest
// sample. It follows a PlotPanel — live, paused or replayed — and its display units.
#pragma once

#include "plots/channel.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QCPGraph;
class QCustomPlot;

namespace hatpic {

class FadingTrail;
class PlotPanel;

class XyView : public QWidget
{
    Q_OBJECT
public:
    //! Follows `panel` (not owned), refreshing after each of its repaints while visible.
    explicit XyView(PlotPanel *panel, QWidget *parent = nullptr);
    ~XyView() override;

    void setChannels(Channel x, Channel y);
    Channel xChannel() const;
    Channel yChannel() const;

    //! Redraws from what the panel shows, over its visible range.
    void refresh();

    QCustomPlot *plot() const { return m_plot; }
    const FadingTrail &trail() const { return *m_trail; }
    QCPGraph *pointGraph() const { return m_point; } //!< the newest sample
    QComboBox *yBox() const { return m_y; }

private:
    PlotPanel *m_panel;
    QComboBox *m_x = nullptr;
    QComboBox *m_y = nullptr;
    QCustomPlot *m_plot = nullptr;
    std::unique_ptr<FadingTrail> m_trail;
    QCPGraph *m_point = nullptr;
};

} // namespace hatpic
