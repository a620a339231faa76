#include "plots/logging.h"

Q_LOGGING_CATEGORY(lcPlots, "hatpic.ui.plots", QtWarningMsg)

namespace hatpic {

void RepaintLog::tick(quint64 replots, double decimateMs, double replotMs, qsizetype points,
                      LatencyProbe &latency)
{
    const qint64 ms = m_clock.elapsed();
    if (ms < 5000)
        return;
    const double rate = (replots - m_replots) * 1000.0 / ms;
    qCDebug(lcPlots).nospace() << "repaint rate " << rate << " Hz; last decimate " << decimateMs
                               << " ms, replot " << replotMs << " ms, " << points << " points";
    const LatencyProbe::Summary s = latency.summary();
    if (s.count > 0)
        qCDebug(lcPlots).nospace()
            << "latency arrival to frame: median " << s.medianMs << " ms, p95 " << s.p95Ms
            << " ms, max " << s.maxMs << " ms over " << s.count << " samples (" << s.dropped
            << " not shown)";
    latency.resetSummary();
    m_replots = replots;
    m_clock.restart();
}

} // namespace hatpic
