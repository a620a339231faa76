// The items drawn over the three plots, apart from the data: θ0 and the dead-zone and notch
// bands on the angle plot, the event markers (a dashed line through every plot and a label),
// and the cursor (a line through every plot and its time).
//
// Not a widget: it owns nothing but QCustomPlot items, which the plot deletes with itself.
#pragma once

#include "model/params.h"
#include "telemetry/recording.h"

#include <QColor>
#include <QFont>
#include <QList>
#include <QPointF>
#include <QStringList>

#include <array>
#include <optional>

class QCustomPlot;
class QCPAbstractItem;
class QCPAxisRect;
class QCPItemLine;
class QCPItemRect;
class QCPItemStraightLine;
class QCPItemText;

namespace hatpic {

class PlotOverlays
{
public:
    static constexpr int kPlotCount = 3;

    //! rects[0] is the angle plot; the bands go there. Adds the "bands" layer under the grid.
    PlotOverlays(QCustomPlot *plot, const std::array<QCPAxisRect *, kPlotCount> &rects);

    //! θ0 line and bands from `params`, in display units (angles × `scale`); nullopt hides
    //! everything, `showBands` false keeps only the θ0 line.
    void setBands(const std::optional<DeviceParams> &params, double scale, bool showBands);
    //! One marker per burst of events (eventmarkers.h), a short label on each; replaces the
    //! previous markers.
    void setEvents(const QList<RecordingEvent> &events, const QFont &font);
    //! Puts each event label on the side of its line where it fits in the angle plot: right of
    //! the line, or left of it near the right edge (where live pushes land). Call before a
    //! replot, once the x range is set.
    void fitEventLabels();
    //! The details of the marker whose label or line is at `pixel`; empty when none.
    QString eventDetailsAt(const QPointF &pixel) const;
    //! The cursor at time t [s]; nullopt hides it.
    void setCursor(std::optional<double> t);

private:
    QCPItemStraightLine *verticalLine(int plot, const char *layer);

    QCustomPlot *m_plot;
    std::array<QCPAxisRect *, kPlotCount> m_rects;
    QCPItemRect *m_deadZone = nullptr;
    std::array<QCPItemRect *, 2> m_notch{};
    QCPItemLine *m_centerLine = nullptr;
    std::array<QCPItemStraightLine *, kPlotCount> m_cursorLines{};
    QCPItemText *m_cursorLabel = nullptr;
    QList<QCPAbstractItem *> m_eventItems;
    QList<QCPItemText *> m_eventLabels;
    QStringList m_eventDetails; //!< per label, shown on hover
};

} // namespace hatpic
