// The fixed structure of the three time plots inside one QCustomPlot: the axis rects stacked on
// one time axis (angle, torques, references), a legend column beside each, one graph per
// channel and the legend keys of the bands. Built once; it names the legend entries (with the
// values of one sample) and greys those that are hidden.
//
// Not a widget: it owns nothing but QCustomPlot elements, which the plot deletes with itself.
#pragma once

#include "model/params.h"
#include "plots/channel.h"
#include "plots/decimator.h"

#include <QCoreApplication>
#include <QFont>
#include <QList>

#include <array>
#include <optional>

class QColor;
class QCustomPlot;
class QCPAbstractPlottable;
class QCPAxisRect;
class QCPGraph;
class QCPLegend;

namespace hatpic {

class DisplayUnits;
class SampleBuffer;

enum class PlotKind { Angle, Torque, Reference };

class PlotFrame
{
    Q_DECLARE_TR_FUNCTIONS(hatpic::PlotPanel)
public:
    static constexpr int kPlotCount = 3;

    //! Replaces the layout of `plot` with the three plots, their legends and graphs.
    explicit PlotFrame(QCustomPlot *plot);

    const std::array<QCPAxisRect *, kPlotCount> &rects() const { return m_rects; }
    QCPAxisRect *rect(PlotKind plot) const { return m_rects[static_cast<int>(plot)]; }
    QCPLegend *legend(PlotKind plot) const { return m_legends[static_cast<int>(plot)]; }
    QCPGraph *graph(Channel channel) const { return m_graphs[channelIndex(channel)]; }

    //! The legend key of the dead-zone or notch band.
    bool isBandKey(const QCPAbstractPlottable *plottable) const;
    //! The channel a graph draws; nullopt for anything else.
    std::optional<Channel> channelOf(const QCPAbstractPlottable *plottable) const;

    //! Legends wide enough for the measuring cursors' Δ entries, or the narrower default that
    //! leaves the plots more room.
    void setWideLegends(bool wide);

    //! Vertical room one y tick label takes, with a gap to the next [px]. The y axes get as
    //! many ticks as their plot's height holds at this spacing, so labels never print over
    //! each other in a short plot (issue 27).
    static constexpr int kTickSpacing = 26;
    //! Fits the y axes' tick counts to the plots' heights (done after every layout); true
    //! when a count changed (the next layout uses it).
    bool fitTickCounts();

    //! Fits the legends to the plots' height `plotHeight` [px] (done after every layout): when
    //! the full legends do not fit beside their plots they go compact (a smaller font, tighter
    //! rows, the entries of hidden series left out) rather than clipping their entries
    //! (issue 27: a bottom panel squeezed "τ_rec" to "τ rec"). True when they changed.
    bool fitLegends(int plotHeight);

    //! Axis labels with the units of `units` ("θ [°]", "v_ref [m/s]", …).
    void setAxisLabels(const DisplayUnits &units);
    //! Keeps the y ranges on the same physical values when the display units change.
    void rescaleAxes(const DisplayUnits &before, const DisplayUnits &after);
    //! Fits every y axis to what its visible graphs drew (`ranges`, by channel), never
    //! narrower than a resting signal's noise, with hysteresis so that the axes do not breathe
    //! with every repaint. With `bands`, the notch band stays in sight on the angle plot.
    void autoscale(const std::array<DecimationResult, kChannelCount> &ranges,
                   const DisplayUnits &units, const std::optional<DeviceParams> &bands);

    //! Names every graph with its value at sample `index` of `source` (none for −1 or a hidden
    //! graph) and greys the legend entries of what is hidden.
    void updateLegends(const SampleBuffer *source, qsizetype index, const DisplayUnits &units,
                       bool bandsVisible);

private:
    void addGraph(Channel channel, PlotKind plot, bool rightAxis);
    //! Whether `p`, an entry of a legend, shows now (a band key while the bands do).
    bool isShown(const QCPAbstractPlottable *p) const;
    //! Puts in each legend, in their order, the entries that belong there in the current mode;
    //! true when that changed them.
    bool fillLegends();
    //! Greys the entries of what is hidden.
    void colourLegends();
    //! The height [px] the full legends take, stacked, each row at least three y ticks high,
    //! with the time axis under them.
    int fullLegendsHeight() const;

    std::array<QCPAxisRect *, kPlotCount> m_rects{};
    std::array<QCPLegend *, kPlotCount> m_legends{};
    int m_wideLegendWidth = 0; //!< [px]
    std::array<QCPGraph *, kChannelCount> m_graphs{};
    QCPGraph *m_deadZoneKey = nullptr; //!< legend entries of the bands (no data)
    QCPGraph *m_notchKey = nullptr;
    //! Each legend's entries in their order, shown or not (compact legends leave some out).
    std::array<QList<QCPAbstractPlottable *>, kPlotCount> m_entries;
    QFont m_fullFont; //!< the legends' font when not compact
    bool m_compact = false;
    bool m_bandsVisible = true;
    quint64 m_filled = ~quint64{0}; //!< the entries in the legends now, one bit each
};

} // namespace hatpic
