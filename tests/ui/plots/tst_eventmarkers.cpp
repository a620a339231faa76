// Event markers: one per burst, a short label, every change in the details.
#include "plots/eventmarkers.h"

#include <QTest>

using namespace hatpic;
using namespace Qt::StringLiterals;

class TestEventMarkers : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void separateEventsStaySeparate();
    void dragIsOneMarker();
    void multiParameterPushHasShortLabel();
    void otherTextAppearsOnce();
    void manyBurstsBecomeAtMostTheMostMarkers();
    void longBurstListsAFewAndCountsTheRest();
};

void TestEventMarkers::separateEventsStaySeparate()
{
    const QList<EventMarker> m =
        groupEvents({{0.5, u"K_max 0.4 → 0.6"_s}, {1.5, u"N 0.1 → 0.2"_s}});
    QCOMPARE(m.size(), 2);
    QCOMPARE(m[0].label, u"K_max"_s);
    QCOMPARE(m[0].details, u"K_max 0.4 → 0.6"_s);
    QCOMPARE(m[1].t_s, 1.5);
    QCOMPARE(m[1].count, 1);
}

void TestEventMarkers::dragIsOneMarker()
{
    // A slider dragged with live push: a push every 100 ms, fifteen of them.
    QList<RecordingEvent> events;
    for (int i = 0; i < 15; ++i) {
        events.append({2.0 + 0.1 * i, QStringLiteral("K_max %1 → %2")
                                          .arg(0.4 + 0.01 * i, 0, 'g', 3)
                                          .arg(0.41 + 0.01 * i, 0, 'g', 3)});
    }
    events.append({5.0, u"K_min 0.1 → 0.2"_s});
    const QList<EventMarker> m = groupEvents(events);
    QCOMPARE(m.size(), 2);
    QCOMPARE(m[0].t_s, 2.0);
    QCOMPARE(m[0].count, 15);
    QCOMPARE(m[0].label, u"K_max"_s);
    QCOMPARE(m[0].details, u"K_max 0.4 → 0.55\n(15 events)"_s);
    QCOMPARE(m[1].label, u"K_min"_s);
}

void TestEventMarkers::multiParameterPushHasShortLabel()
{
    const QList<EventMarker> m =
        groupEvents({{1.0, u"K_max 0.4 → 0.6; N 0.1 → 0.2; Q_dz 0.01 → 0.02"_s}});
    QCOMPARE(m.size(), 1);
    QCOMPARE(m[0].label, u"K_max +2"_s);
    QCOMPARE(m[0].details, u"K_max 0.4 → 0.6\nN 0.1 → 0.2\nQ_dz 0.01 → 0.02"_s);

    const QList<EventMarker> two = groupEvents({{1.0, u"K_max 0.4 → 0.6; N 0.1 → 0.2"_s}});
    QCOMPARE(two[0].label, u"K_max, N"_s);
}

void TestEventMarkers::otherTextAppearsOnce()
{
    const QList<EventMarker> m = groupEvents(
        {{1.0, u"p_ref reset to 0"_s}, {1.1, u"p_ref reset to 0"_s}, {1.2, u"K_max 1 → 2"_s}});
    QCOMPARE(m.size(), 1);
    QCOMPARE(m[0].label, u"p_ref, K_max"_s);
    QCOMPARE(m[0].details, u"K_max 1 → 2\np_ref reset to 0\n(3 events)"_s);
}

// A recording with 20 000 separate events (issue 27): at most kMaxEventMarkers markers, every
// event in one of them.
void TestEventMarkers::manyBurstsBecomeAtMostTheMostMarkers()
{
    QList<RecordingEvent> events;
    for (int i = 0; i < 20000; ++i)
        events.append({1.0 * i, u"note %1"_s.arg(i)});
    const QList<EventMarker> m = groupEvents(events);
    QVERIFY2(m.size() <= kMaxEventMarkers && m.size() > kMaxEventMarkers / 2,
             qPrintable(QString::number(m.size())));
    int count = 0;
    for (const EventMarker &marker : m)
        count += marker.count;
    QCOMPARE(count, 20000);
    QCOMPARE(m.first().t_s, 0.0);
}

// 5000 different parameters changed in one burst: the details list kMaxDetailLines of them
// and count the rest.
void TestEventMarkers::longBurstListsAFewAndCountsTheRest()
{
    QList<RecordingEvent> events;
    for (int i = 0; i < 5000; ++i)
        events.append({0.01 * i, u"p%1 1 → 2"_s.arg(i)});
    const QList<EventMarker> m = groupEvents(events);
    QCOMPARE(m.size(), 1);
    QCOMPARE(m[0].label, u"p0 +4999"_s);
    const QStringList lines = m[0].details.split(u'\n');
    QCOMPARE(lines.size(), kMaxDetailLines + 2);
    QCOMPARE(lines.first(), u"p0 1 → 2"_s);
    QCOMPARE(lines[kMaxDetailLines], u"(and 4980 more)"_s);
    QCOMPARE(lines.last(), u"(5000 events)"_s);
}

QTEST_APPLESS_MAIN(TestEventMarkers)
#include "tst_eventmarkers.moc"
