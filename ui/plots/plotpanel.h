// The three live time plots: angle θ (with θ0 and the dead-zone and notch bands), torques
// (τ, τ_rec, τ_ext, τ_total) and references (v_ref, p_ref on its own right axis), stacked on
// one shared time axis.
//
// Telemetry rate and paint rate are decoupled: the panel reads a SampleBuffer that someone
// else fills, and a timer repaints at a fixed rate only when the buffer or the view changed.
// Each repaint decimates the visible range per pixel column (Decimator). Data stay SI; angles
// are converted to degrees only for display.
#pragma once

#include "model/params.h"
#include "plots/channel.h"
#include "plots/decimator.h"
#include "plots/displayunits.h"
#include "plots/latencyprobe.h"
#include "plots/logging.h"
#include "plots/plotexport.h"
#include "plots/plotframe.h"
#include "plots/samplebuffer.h"
#include "telemetry/recording.h"

#include <QElapsedTimer>
#include <QWidget>

#include <array>
#include <memory>
#include <optional>

class QCustomPlot;
class QCPAxisRect;
class QCPGraph;
class QCPLegend;
class QCPAbstractLegendItem;
class QTimer;

namespace hatpic {

class PlotGhost;
class MeasureCursors;
class PlotOverlays;

class PlotPanel : public QWidget
{
    Q_OBJECT
public:
    using Plot = PlotKind;
    static constexpr int kPlotCount = PlotFrame::kPlotCount;
    static constexpr double kDefaultRepaintHz = 30; //!< [Hz]
    //! The least height of the three plots [px].
    static constexpr int kMinPlotsHeight = 300;

    //! Timing of the repaints, for the status line, the benchmark and the performance notes.
    struct RepaintStats
    {
        quint64 replots = 0;       //!< repaints since construction
        double lastDecimateMs = 0; //!< decimation of all visible series, last repaint [ms]
        double lastReplotMs = 0;   //!< QCustomPlot::replot, last repaint [ms]
        qsizetype lastPoints = 0;  //!< points handed to the graphs, last repaint
    };

    explicit PlotPanel(QWidget *parent = nullptr);
    ~PlotPanel() override;

    //! The buffer to draw (not owned; must outlive the panel or be replaced). nullptr: nothing.
    void setSource(const SampleBuffer *buffer);
    const SampleBuffer *source() const { return m_source; }

    //! A second buffer drawn fainter on the same plots (a recording overlaid on the replay;
    //! not owned, must outlive the panel or be replaced). nullptr: none.
    void setOverlaySource(const SampleBuffer *buffer);
    const PlotGhost *overlay() const { return m_ghost.get(); }

    //! Length of the visible time range [s].
    void setWindowLength(double seconds);
    double windowLength() const { return m_window; }

    //! Live mode: the view ends at the newest sample.
    void setFollowLatest(bool follow);
    bool followsLatest() const { return m_follow && !m_paused; }
    //! Ends the view at `t` (replay playhead, or scrolling while paused) [s].
    void setViewEnd(double t);
    double viewStart() const; //!< [s]
    double viewEnd() const;   //!< [s]
    //! Draws no data after `t` (the replay playhead), wherever the view ends; nullopt: all.
    void setDataEnd(std::optional<double> t);
    std::optional<double> dataEnd() const { return m_dataEnd; }

    //! Freezes the view on a snapshot of the source; the source itself keeps filling.
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }

    void setAutoscale(bool on); //!< off: the y ranges stay put and the mouse drags/zooms them
    bool autoscale() const { return m_autoscale; }

    void setAngleInDegrees(bool degrees);
    bool angleInDegrees() const { return m_units.degrees(); }

    //! θ0, dead zone and notch bands; nullopt hides them.
    void setDeviceParams(const std::optional<DeviceParams> &params);
    //! Units of the reference plot (translation: m, m/s; rotation: rad, rad/s).
    void setHostParams(const HostParams &host);

    void setChannelVisible(Channel channel, bool visible);
    bool isChannelVisible(Channel channel) const;
    void setBandsVisible(bool visible);
    bool bandsVisible() const { return m_bandsVisible; }

    //! Parameter changes and other events, marked on the time axis.
    void setEvents(const QList<RecordingEvent> &events);
    void addEvent(const RecordingEvent &event);
    QList<RecordingEvent> events() const { return m_events; }

    //! Shows the cursor line and the values at time t; nullopt hides it.
    void setCursorTime(std::optional<double> t);
    std::optional<double> cursorTime() const { return m_cursor; }
    //! The values the legends show (at the cursor, else at the right edge of the data):
    //! "t = 12.345 s; θ = 3.21°; …".
    QString readout() const;

    //! Saves the three plots as an image at the widget's size: PDF for a ".pdf" path, SVG for
    //! ".svg", else PNG.
    bool exportImage(const QString &path, QString *error = nullptr);
    //! The same at the size and with the caption of `options` (plots/plotexport.h).
    bool exportImage(const QString &path, const PlotImageOptions &options,
                     QString *error = nullptr);
    //! Writes the raw samples of the visible time range as CSV; rows written or −1.
    qsizetype exportCsv(const QString &path, QString *error = nullptr) const;

    void setRepaintRate(double hz);
    RepaintStats repaintStats() const { return m_stats; }
    //! Live samples arrived (they wait for the frame that shows them: the latency probe).
    void noteArrivals(const SampleBatch &batch) { m_latency.arrived(batch); }
    //! Arrival → painted frame, since the last rate log line (every 5 s) [ms].
    LatencyProbe::Summary latency() const { return m_latency.summary(); }
    //! Points currently drawn for a channel (after decimation).
    qsizetype pointCount(Channel channel) const;
    //! Repaints now if anything changed (what the timer does).
    void repaintIfNeeded();
    //! Forces a full rebuild and repaint now.
    void repaintNow();

    //! The two measuring cursors (off until enabled).
    MeasureCursors *measure() const { return m_measure; }
    //! What the plots draw: the source, or its snapshot while paused; nullptr: nothing.
    const SampleBuffer *shownSource() const { return drawSource(); }
    const DisplayUnits &units() const { return m_units; }
    const std::optional<DeviceParams> &deviceParams() const { return m_params; }

    QCustomPlot *customPlot() const { return m_plot; }
    QCPAxisRect *axisRect(Plot plot) const { return m_frame->rect(plot); }
    QCPGraph *graph(Channel channel) const { return m_frame->graph(channel); }
    QCPLegend *legend(Plot plot) const { return m_frame->legend(plot); }

Q_SIGNALS:
    void channelVisibilityChanged(hatpic::Channel channel, bool visible);
    void bandsVisibilityChanged(bool visible);
    void pausedChanged(bool paused);
    void autoscaleChanged(bool on);
    void repainted();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void buildPlots();
    void updateLabels();
    void updateBands();
    void rebuildEvents();
    void updateInteractions();
    void applyXRange(double start, double end);
    void rebuildData();
    void updateLegendTexts();
    void onLegendClick(QCPAbstractLegendItem *item);
    void onXRangeChanged(int plotIndex);
    void logRate()
    {
        m_repaintLog.tick(m_stats.replots, m_stats.lastDecimateMs, m_stats.lastReplotMs,
                          m_stats.lastPoints, m_latency);
    }
    const SampleBuffer *drawSource() const;
    double dataEdge() const; //!< right end of the drawn data: view end or data end [s]

    QCustomPlot *m_plot = nullptr;
    std::unique_ptr<PlotFrame> m_frame;
    QTimer *m_timer = nullptr;
    std::unique_ptr<PlotOverlays> m_overlays;
    std::unique_ptr<PlotGhost> m_ghost;
    MeasureCursors *m_measure = nullptr;
    DisplayUnits m_units;

    const SampleBuffer *m_source = nullptr;
    SampleBuffer m_frozen{1}; //!< snapshot shown while paused
    Decimator m_decimator;
    QVector<QCPGraphData> m_points;
    std::array<DecimationResult, kChannelCount> m_ranges{};
    std::optional<DeviceParams> m_params;
    QList<RecordingEvent> m_events;
    std::optional<double> m_cursor;
    std::optional<double> m_dataEnd;

    double m_window = 10; //!< [s]
    bool m_follow = true;
    bool m_paused = false;
    bool m_autoscale = true;
    bool m_bandsVisible = true;
    bool m_dataDirty = true;    //!< graphs must be decimated again
    bool m_replotNeeded = true; //!< something on screen changed
    bool m_settingRange = false;
    const SampleBuffer *m_drawnSource = nullptr;
    quint64 m_drawnGeneration = 0;
    QSize m_laidOutSize; //!< widget size at the last replot (when the rects were laid out)

    RepaintStats m_stats;
    LatencyProbe m_latency;
    RepaintLog m_repaintLog;
};

} // namespace hatpic
