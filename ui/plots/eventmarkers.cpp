#include "plots/eventmarkers.h"

#include <QCoreApplication>
#include <QHash>
#include <QSet>
#include <QStringList>

#include <algorithm>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

const QString kArrow = u" → "_s;

//! One burst's parts, merged: "name a → b" keeps its first a and last b; any other text
//! appears once. Bounded by the number of distinct parts, however long the burst; each part is
//! looked up in a hash, so a burst of n distinct events costs O(n), not O(n²). Its details
//! list at most kMaxDetailLines of them and count the rest.
class Burst
{
public:
    void add(const QString &text)
    {
        ++m_count;
        for (const QString &raw : text.split(u"; "_s, Qt::SkipEmptyParts)) {
            const QString part = raw.trimmed();
            const qsizetype space = part.indexOf(u' ');
            const qsizetype arrow = part.indexOf(kArrow);
            const QString name = space > 0 ? part.left(space) : part;
            if (!m_nameSet.contains(name)) {
                m_nameSet.insert(name);
                if (m_names.size() < 2)
                    m_names << name;
            }
            if (space > 0 && arrow > space) {
                const QString before = part.mid(space + 1, arrow - space - 1);
                const QString after = part.mid(arrow + kArrow.size());
                const auto at = m_changeAt.constFind(name);
                if (at == m_changeAt.cend()) {
                    m_changeAt.insert(name, m_changes.size());
                    m_changes.append({name, before, after});
                } else {
                    m_changes[*at].after = after;
                }
            } else if (!m_otherSet.contains(part)) {
                m_otherSet.insert(part);
                m_other << part;
            }
        }
    }

    EventMarker marker(double t) const
    {
        EventMarker m;
        m.t_s = t;
        m.count = m_count;
        const qsizetype names = m_nameSet.size();
        m.label = names <= 2 ? m_names.join(u", "_s)
                             : m_names.first() + QStringLiteral(" +%1").arg(names - 1);
        QStringList lines;
        for (const Change &c : m_changes) {
            if (lines.size() == kMaxDetailLines)
                break;
            lines << c.name + u' ' + c.before + kArrow + c.after;
        }
        for (const QString &other : m_other) {
            if (lines.size() == kMaxDetailLines)
                break;
            lines << other;
        }
        if (const qsizetype more = m_changes.size() + m_other.size() - lines.size(); more > 0)
            lines << QCoreApplication::translate("hatpic::EventMarkers", "(and %1 more)").arg(more);
        if (m_count > 1)
            lines
                << QCoreApplication::translate("hatpic::EventMarkers", "(%1 events)").arg(m_count);
        m.details = lines.join(u'\n');
        return m;
    }

private:
    struct Change
    {
        QString name;
        QString before; //!< the first value
        QString after;  //!< the last value
    };
    int m_count = 0;
    QSet<QString> m_nameSet;
    QStringList m_names;                  //!< the first two, in order
    QHash<QString, qsizetype> m_changeAt; //!< index in m_changes, by name
    QList<Change> m_changes;
    QSet<QString> m_otherSet;
    QStringList m_other;
};

} // namespace

QList<EventMarker> groupEvents(const QList<RecordingEvent> &events, double gap,
                               qsizetype maxMarkers)
{
    QList<EventMarker> markers;
    if (events.isEmpty())
        return markers;
    // At most maxMarkers: a marker starts more than the span over that many after the one
    // before, and once there are that many the last takes the rest.
    const auto [earliest, latest] = std::minmax_element(
        events.cbegin(), events.cend(), [](const auto &a, const auto &b) { return a.t_s < b.t_s; });
    const qsizetype most = std::max<qsizetype>(maxMarkers, 1);
    const double spacing = (latest->t_s - earliest->t_s) / double(most);
    Burst burst;
    double start = 0;
    double last = 0;
    bool open = false;
    for (const RecordingEvent &event : events) {
        if (open && event.t_s - last > gap && event.t_s - start > spacing &&
            markers.size() + 1 < most) {
            markers << burst.marker(start);
            burst = Burst();
            open = false;
        }
        if (!open) {
            start = event.t_s;
            open = true;
        }
        burst.add(event.text);
        last = event.t_s;
    }
    if (open)
        markers << burst.marker(start);
    return markers;
}

} // namespace hatpic
