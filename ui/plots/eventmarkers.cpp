#include "plots/eventmarkers.h"

#include <QCoreApplication>
#include <QStringList>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

const QString kArrow = u" → "_s;

//! One burst's parts, merged: "name a → b" keeps its first a and last b; any other text
//! appears once. Bounded by the number of distinct parts, however long the burst.
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
            if (!m_names.contains(name))
                m_names << name;
            if (space > 0 && arrow > space) {
                const QString before = part.mid(space + 1, arrow - space - 1);
                const QString after = part.mid(arrow + kArrow.size());
                const qsizetype at = m_changeNames.indexOf(name);
                if (at < 0) {
                    m_changeNames << name;
                    m_changes << QStringList{before, after};
                } else {
                    m_changes[at][1] = after;
                }
            } else if (!m_other.contains(part)) {
                m_other << part;
            }
        }
    }

    EventMarker marker(double t) const
    {
        EventMarker m;
        m.t_s = t;
        m.count = m_count;
        m.label = m_names.size() <= 2
                      ? m_names.join(u", "_s)
                      : m_names.first() + QStringLiteral(" +%1").arg(m_names.size() - 1);
        QStringList lines;
        for (qsizetype i = 0; i < m_changeNames.size(); ++i)
            lines << m_changeNames[i] + u' ' + m_changes[i][0] + kArrow + m_changes[i][1];
        lines << m_other;
        if (m_count > 1)
            lines
                << QCoreApplication::translate("hatpic::EventMarkers", "(%1 events)").arg(m_count);
        m.details = lines.join(u'\n');
        return m;
    }

private:
    int m_count = 0;
    QStringList m_names;
    QStringList m_changeNames;
    QList<QStringList> m_changes; //!< {first before, last after} per changed name
    QStringList m_other;
};

} // namespace

QList<EventMarker> groupEvents(const QList<RecordingEvent> &events, double gap)
{
    QList<EventMarker> markers;
    Burst burst;
    double start = 0;
    double last = 0;
    bool open = false;
    for (const RecordingEvent &event : events) {
        if (open && event.t_s - last > gap) {
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
