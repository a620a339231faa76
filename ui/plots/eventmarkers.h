// Event markers as the plots show them: events closer together than a burst gap (a slider
// dragged with live push, a push and its read-back) make one marker with a short label; the
// whole story goes in the marker's details, shown on hover.
#pragma once

#include "telemetry/recording.h"

#include <QList>
#include <QString>

namespace hatpic {

struct EventMarker
{
    double t_s = 0;  //!< the first event of the burst [s]
    QString label;   //!< short: the parameter names, e.g. "K_max, N" or "K_max +2"
    QString details; //!< every change from its first value to its last, one per line
    int count = 0;   //!< events in the burst
};

//! Four times the live-push interval: a drag stays one burst, separate pushes stay apart.
inline constexpr double kEventBurstGap = 0.4; // [s]

//! Most markers the plots draw: a long recording's events become at most this many (a plot item
//! each per plot; QCustomPlot's item lists cost O(n) per item added or removed).
inline constexpr qsizetype kMaxEventMarkers = 500;
//! Most lines of a marker's details; the rest are counted ("(and 12 more)").
inline constexpr qsizetype kMaxDetailLines = 20;

//! Groups time-ordered `events` into bursts (the gap is between neighbours), at most
//! `maxMarkers` of them: a burst also lasts at least the events' span over that many, and the
//! last marker takes whatever is left. Linear in the events.
QList<EventMarker> groupEvents(const QList<RecordingEvent> &events, double gap = kEventBurstGap,
                               qsizetype maxMarkers = kMaxEventMarkers);

} // namespace hatpic
