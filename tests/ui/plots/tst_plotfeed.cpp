// PlotFeed: the plots' one source. Live it keeps every batch and shows the device's parameters
// and events; a recording replaces all of that at once, and back to live restores it; pause
// means the plots live and the playback in replay; a refused file changes nothing.
#include "plots/eventmarkers.h"
#include "plots/plotfeed.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"
#include "plots/replaycontroller.h"
#include "telemetry/recordingformat.h"
#include "telemetry/recordingwriter.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace hatpic;

namespace {

SampleBatch ramp(double start, int count)
{
    SampleBatch batch;
    for (int i = 0; i < count; ++i) {
        Sample s;
        s.t_s = start + i * 0.001;
        s.theta = 0.1 + i * 1e-4;
        s.tau_rec = -0.02 - i * 1e-5;
        batch.append(s);
    }
    return batch;
}

//! A recording with only t_s, theta and the event column: `rows` rows `step` s apart, each with
//! an event of its own text ("e17": every one a different name).
QString bareRecording(const QString &path, qint64 rows, double step, bool events)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write("t_s,theta,event\n");
    QByteArray chunk;
    for (qint64 i = 0; i < rows; ++i) {
        chunk += QByteArray::number(i * step, 'g', 10) + ",0," +
                 (events ? "e" + QByteArray::number(i) : QByteArray()) + '\n';
        if (chunk.size() > (1 << 20)) {
            file.write(chunk);
            chunk.clear();
        }
    }
    file.write(chunk);
    return path;
}

} // namespace

class TestPlotFeed : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void liveKeepsEveryBatch();
    void liveParamsReachThePlotsAndTheViews();
    void replayReplacesEverythingAndBackToLiveRestoresIt();
    void pauseMeansPlotsLiveAndPlaybackInReplay();
    void windowLengthKeepsTheReplayOnItsPlayhead();
    void refusedRecordingChangesNothing();
    void manyEventsOpenBounded();
    void moreSamplesThanHeldAreSaidSo();

private:
    QTemporaryDir m_dir;
    QString m_recording; //!< 100 … 105 s, K_max 0.45, one event at 102.5 s
};

void TestPlotFeed::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_recording = m_dir.filePath(QStringLiteral("replay.csv"));
    RecordingWriter writer;
    RecordingMetadata meta;
    meta.start = QDateTime::currentDateTimeUtc();
    meta.source = QStringLiteral("tst_plotfeed");
    meta.params.K_max = 0.45;
    meta.host.mode = ReferenceMode::Rotation;
    QVERIFY2(writer.open(m_recording, meta), qPrintable(writer.error()));
    QVERIFY(writer.append(ramp(100, 2500)));
    writer.addEvent(QStringLiteral("K_max 0.4 → 0.45"));
    QVERIFY(writer.append(ramp(102.5, 2501)));
    writer.close();
}

void TestPlotFeed::liveKeepsEveryBatch()
{
    PlotPanel panel;
    PlotFeed feed(&panel);
    QCOMPARE(panel.source(), &feed.liveBuffer());
    QVERIFY(panel.followsLatest());
    QVERIFY(!feed.isReplaying());
    // Events mark the newest live sample, none before there is one.
    feed.addLiveEvent(QStringLiteral("nothing to mark"));
    QVERIFY(panel.events().isEmpty());
    QSignalSpy point(&feed, &PlotFeed::operatingPoint);
    feed.appendLive({});
    QCOMPARE(point.size(), 0);
    const SampleBatch batch = ramp(1, 50);
    feed.appendLive(batch);
    QCOMPARE(feed.liveBuffer().size(), 50);
    QCOMPARE(point.size(), 1);
    QCOMPARE(point.constLast().at(0).toDouble(), batch.constLast().theta);
    QCOMPARE(point.constLast().at(1).toDouble(), batch.constLast().tau_rec);
    feed.addLiveEvent(QStringLiteral("K_max 0.4 → 0.6"));
    QCOMPARE(panel.events().size(), 1);
    QCOMPARE(panel.events().constFirst().t_s, batch.constLast().t_s);
}

void TestPlotFeed::liveParamsReachThePlotsAndTheViews()
{
    PlotPanel panel;
    PlotFeed feed(&panel);
    QSignalSpy shown(&feed, &PlotFeed::deviceTuningShown);
    QSignalSpy cleared(&feed, &PlotFeed::operatingPointCleared);
    DeviceParams device;
    device.K_max = 0.6;
    feed.setLiveDeviceTuning({device, std::nullopt});
    QCOMPARE(shown.size(), 1);
    QCOMPARE(shown.constLast().at(0).value<DeviceTuning>().params, std::optional(device));
    QCOMPARE(cleared.size(), 0);
    // No device: no bands and no operating point.
    feed.setLiveDeviceTuning({});
    QCOMPARE(shown.size(), 2);
    QVERIFY(!shown.constLast().at(0).value<DeviceTuning>().params);
    QCOMPARE(cleared.size(), 1);
}

void TestPlotFeed::replayReplacesEverythingAndBackToLiveRestoresIt()
{
    PlotPanel panel;
    PlotFeed feed(&panel);
    DeviceParams device;
    device.K_max = 0.6;
    feed.setLiveDeviceTuning({device, std::nullopt});
    feed.appendLive(ramp(1, 100));
    feed.addLiveEvent(QStringLiteral("live event"));

    QSignalSpy replaying(&feed, &PlotFeed::replayingChanged);
    QSignalSpy shown(&feed, &PlotFeed::deviceTuningShown);
    QSignalSpy point(&feed, &PlotFeed::operatingPoint);
    QString error;
    QVERIFY2(feed.openRecording(m_recording, &error), qPrintable(error));
    QVERIFY(feed.isReplaying());
    QVERIFY(!replaying.isEmpty());
    QCOMPARE(replaying.constLast().at(0).toBool(), true);
    QCOMPARE(panel.source(), &feed.replay()->buffer());
    QVERIFY(!panel.followsLatest());
    QCOMPARE(panel.events().size(), 1);
    QCOMPARE(panel.events().constFirst().text, QStringLiteral("K_max 0.4 → 0.45"));
    QCOMPARE(shown.constLast().at(0).value<DeviceTuning>().params->K_max, 0.45);
    // On a full first window (the whole 5 s recording); the views follow the playhead.
    QCOMPARE(feed.replay()->position(), feed.replay()->endTime());
    QCOMPARE(panel.dataEnd(), feed.replay()->endTime());
    QVERIFY(!point.isEmpty());

    // Live data keep arriving into the live buffer but are not shown.
    const int points = int(point.size());
    const int shownBefore = int(shown.size());
    feed.appendLive(ramp(2, 100));
    feed.setLiveDeviceTuning({DeviceParams(), std::nullopt});
    QCOMPARE(feed.liveBuffer().size(), 200);
    QCOMPARE(point.size(), points);
    QCOMPARE(shown.size(), shownBefore);
    QCOMPARE(panel.source(), &feed.replay()->buffer());

    QSignalSpy cleared(&feed, &PlotFeed::operatingPointCleared);
    feed.backToLive();
    QVERIFY(!feed.isReplaying());
    QCOMPARE(replaying.constLast().at(0).toBool(), false);
    QCOMPARE(panel.source(), &feed.liveBuffer());
    QVERIFY(panel.followsLatest());
    QVERIFY(!panel.dataEnd());
    QCOMPARE(panel.events().size(), 1);
    QCOMPARE(panel.events().constFirst().text, QStringLiteral("live event"));
    // The live parameters as they are now, not as they were when the replay began.
    QCOMPARE(shown.constLast().at(0).value<DeviceTuning>().params, std::optional(DeviceParams()));
    QCOMPARE(cleared.size(), 1);
}

void TestPlotFeed::pauseMeansPlotsLiveAndPlaybackInReplay()
{
    PlotPanel panel;
    PlotFeed feed(&panel);
    QSignalSpy paused(&feed, &PlotFeed::pausedChanged);
    QVERIFY(!feed.isPaused());
    feed.togglePause();
    QVERIFY(panel.isPaused());
    QVERIFY(feed.isPaused());
    QVERIFY(!paused.isEmpty());

    // A replay opens thawed plots and a paused playback.
    QVERIFY(feed.openRecording(m_recording));
    QVERIFY(!panel.isPaused());
    QVERIFY(feed.isPaused());
    feed.replay()->setPosition(feed.replay()->startTime());
    feed.togglePause();
    QVERIFY(feed.replay()->isPlaying());
    QVERIFY(!feed.isPaused());
    QVERIFY(!panel.isPaused());
    feed.togglePause();
    QVERIFY(!feed.replay()->isPlaying());
    QVERIFY(feed.isPaused());
}

void TestPlotFeed::windowLengthKeepsTheReplayOnItsPlayhead()
{
    PlotPanel panel;
    PlotFeed feed(&panel);
    feed.setWindowLength(10);
    QVERIFY(feed.openRecording(m_recording));
    feed.replay()->setPosition(103);
    QCOMPARE(panel.dataEnd(), 103.0);
    QCOMPARE(panel.viewEnd(), 110.0); // 10 s window, not yet full
    feed.setWindowLength(2);
    QCOMPARE(panel.windowLength(), 2.0);
    QCOMPARE(panel.viewEnd(), 103.0);
    QCOMPARE(panel.viewStart(), 101.0);
}

void TestPlotFeed::refusedRecordingChangesNothing()
{
    PlotPanel panel;
    PlotFeed feed(&panel);
    feed.appendLive(ramp(1, 10));
    const QString broken = m_dir.filePath(QStringLiteral("broken.csv"));
    QFile file(broken);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("a,b\n1,2\n");
    file.close();
    QSignalSpy replaying(&feed, &PlotFeed::replayingChanged);
    QString error;
    QVERIFY(!feed.openRecording(broken, &error));
    QVERIFY(!error.isEmpty());
    QVERIFY(!feed.isReplaying());
    QCOMPARE(replaying.size(), 0);
    QCOMPARE(panel.source(), &feed.liveBuffer());
}

// 200 000 events (an hour at the recorder's 50 events/s), every text different, then the same
// number a second apart: the replay opens (issue 27: quadratic, it never did), holds at most
// kMaxReadEvents events, says so, and draws at most kMaxEventMarkers markers.
void TestPlotFeed::manyEventsOpenBounded()
{
    for (const double step : {0.02, 1.0}) {
        const QString path =
            bareRecording(m_dir.filePath(QStringLiteral("events.csv")), 200000, step, true);
        PlotPanel panel;
        PlotFeed feed(&panel);
        QString error;
        QVERIFY2(feed.openRecording(path, &error), qPrintable(error));
        const ReplayController *replay = feed.replay();
        QCOMPARE(replay->buffer().size(), qsizetype(200000));
        QCOMPARE(replay->recording().events.size(), recording::kMaxReadEvents);
        QVERIFY2(replay->warnings().constFirst().startsWith(u"Events from line 50002 on"),
                 qPrintable(replay->warnings().join(u'\n')));
        // Three plots draw a line per marker, the angle plot its label too.
        const int items = panel.customPlot()->itemCount();
        QVERIFY2(items <= 4 * kMaxEventMarkers + 50, qPrintable(QString::number(items)));
    }
}

// A file with more samples than a replay holds: the first kMaxReadSamples are shown, and the
// first warning says so (issue 27: a 20 MB CSV held 1.09 GB).
void TestPlotFeed::moreSamplesThanHeldAreSaidSo()
{
    const qint64 rows = recording::kMaxReadSamples + 1000;
    const QString path =
        bareRecording(m_dir.filePath(QStringLiteral("long.csv")), rows, 0.001, false);
    PlotPanel panel;
    PlotFeed feed(&panel);
    QString error;
    QVERIFY2(feed.openRecording(path, &error), qPrintable(error));
    const ReplayController *replay = feed.replay();
    QCOMPARE(replay->buffer().size(), recording::kMaxReadSamples);
    QCOMPARE(replay->endTime(), (recording::kMaxReadSamples - 1) * 0.001);
    const QString first = replay->warnings().constFirst();
    QVERIFY2(first.startsWith(u"Only the first 1000000 samples (to t_s = 999.999 s) are shown"),
             qPrintable(first));
    QFile::remove(path);
}

QTEST_MAIN(TestPlotFeed)
#include "tst_plotfeed.moc"
