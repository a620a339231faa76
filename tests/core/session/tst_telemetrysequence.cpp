// TelemetrySequence: gaps counted past the u8 seq's wrap by the device clock, duplicates.
#include "session/telemetrysequence.h"

#include <QTest>

using namespace hatpic;

class TestTelemetrySequence : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void consecutiveFramesMissNothing()
    {
        TelemetrySequence s;
        for (int i = 0; i < 600; ++i) {
            const auto step = s.accept(quint8(i), quint32(1000 * i));
            QVERIFY(!step.duplicate);
            QCOMPARE(step.missing, quint64(0));
        }
    }

    void gapsCountedPastTheWrap_data()
    {
        QTest::addColumn<int>("lost");
        for (const int lost : {1, 5, 255, 256, 257, 1500, 2000, 70000})
            QTest::newRow(qPrintable(QString::number(lost))) << lost;
    }
    void gapsCountedPastTheWrap()
    {
        QFETCH(int, lost);
        TelemetrySequence s;
        s.accept(0, 0);
        s.accept(1, 1000); // the period is learnt here
        const int next = 2 + lost;
        // A little jitter on the device clock does not change the count.
        const auto step = s.accept(quint8(next), quint32(1000 * next + 300));
        QVERIFY(!step.duplicate);
        QCOMPARE(step.missing, quint64(lost));
    }

    void withoutAPeriodOnlyTheSeqCounts()
    {
        TelemetrySequence s;
        s.accept(10, 0);
        QCOMPARE(s.accept(13, 300000).missing, quint64(2));
    }

    void theDeviceClockWraps()
    {
        TelemetrySequence s;
        s.accept(0, 0xFFFFFC18u); // 2³² − 1000 µs
        s.accept(1, 0);
        QCOMPARE(s.accept(quint8(2 + 300), quint32(301000)).missing, quint64(300));
    }

    void duplicatesAreSpotted()
    {
        TelemetrySequence s;
        for (int i = 0; i < 40; ++i)
            s.accept(quint8(i), quint32(1000 * i));
        QVERIFY(s.accept(39, 39000).duplicate);  // just seen
        QVERIFY(s.accept(10, 10000).duplicate);  // 29 frames back
        QVERIFY(!s.accept(40, 40000).duplicate); // new
        QVERIFY(!s.accept(41, 41000).duplicate);
        QCOMPARE(s.accept(42, 42000).missing, quint64(0));
        s.reset();
        QVERIFY(!s.accept(42, 42000).duplicate); // forgotten
    }
};

QTEST_GUILESS_MAIN(TestTelemetrySequence)
#include "tst_telemetrysequence.moc"
