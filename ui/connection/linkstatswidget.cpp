#include "connection/linkstatswidget.h"

namespace hatpic {

LinkStatsWidget::LinkStatsWidget(QWidget *parent) : QLabel(parent)
{
    setObjectName(QStringLiteral("linkStats"));
    clear();
}

void LinkStatsWidget::clear()
{
    setText(tr("no link"));
    setToolTip({});
}

void LinkStatsWidget::setStats(const LinkStats &stats)
{
    const QString rtt = stats.rttLastMs < 0 ? tr("RTT —")
                                            : tr("RTT %1 ms (median %2)")
                                                  .arg(stats.rttLastMs, 0, 'f', 2)
                                                  .arg(stats.rttMedianMs, 0, 'f', 2);
    setText(tr("%1 frames/s · drops %2 · decoder errors %3 · %4")
                .arg(stats.framesPerSecond, 0, 'f', 0)
                .arg(stats.seqDrops)
                .arg(stats.totalDecoderDrops() + stats.legacyMalformed)
                .arg(rtt));

    QStringList tip;
    tip << tr("%1 frames, %2 bytes received (%3 kB/s)")
               .arg(stats.frames)
               .arg(stats.bytes)
               .arg(stats.bytesPerSecond / 1000, 0, 'f', 1);
    tip << tr("Telemetry frames missing (sequence gaps): %1").arg(stats.seqDrops);
    for (int i = 0; i < v2::kDropReasonCount; ++i) {
        if (stats.decoderDrops[i] > 0)
            tip << tr("Decoder dropped (%1): %2")
                       .arg(v2::dropReasonName(static_cast<v2::DropReason>(i)))
                       .arg(stats.decoderDrops[i]);
    }
    if (stats.duplicates > 0)
        tip << tr("Telemetry frames received twice (skipped): %1").arg(stats.duplicates);
    if (stats.legacyMalformed > 0)
        tip << tr("Malformed legacy frames: %1").arg(stats.legacyMalformed);
    if (stats.rttMaxMs >= 0)
        tip << tr("Round trip: last %1 ms, median %2 ms, max %3 ms")
                   .arg(stats.rttLastMs, 0, 'f', 2)
                   .arg(stats.rttMedianMs, 0, 'f', 2)
                   .arg(stats.rttMaxMs, 0, 'f', 2);
    tip << tr("Reference gaps held: %1; command retries: %2")
               .arg(stats.referenceGaps)
               .arg(stats.retries);
    setToolTip(tip.join(u'\n'));
}

} // namespace hatpic
