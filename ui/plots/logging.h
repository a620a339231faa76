// Logging category of the plots and the main window ("hatpic.ui.plots", warnings by default).
// QT_LOGGING_RULES="hatpic.ui.plots.debug=true" prints the measured repaint rate every 5 s.
#pragma once

#include "plots/latencyprobe.h"

#include <QElapsedTimer>
#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcPlots)

namespace hatpic {

//! The plots' debug lines: every 5 s the repaint rate since the last line, the last repaint's
//! figures, and the arrival → frame latency of the samples shown since (then restarted).
class RepaintLog
{
public:
    RepaintLog() { m_clock.start(); }
    //! Called at each repaint timer tick; logs when 5 s have passed. `replots` counts all.
    void tick(quint64 replots, double decimateMs, double replotMs, qsizetype points,
              LatencyProbe &latency);

private:
    QElapsedTimer m_clock;
    quint64 m_replots = 0;
};

} // namespace hatpic
