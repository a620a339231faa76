// A second recording overlaid on the replay: aligned at the trigger (the first "trigger:" event)
// or at the start, drawn fainter on the same plots by real QCustomPlot graphs, shown on the
// replay bar, removed by its ✕ and by going back to live; a refused file changes nothing.
#include "plots/plotfeed.h"
#include "plots/plotghost.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"
#include "plots/replaycontroller.h"
#include "recording/replaybar.h"
#include "telemetry/recordingwriter.h"

#include <QComboBox>
#include <QLabel>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

using namespace hatpic;

class TestReplayOverlay : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void anchors();
    void alignsAtTriggerOrStart();
    void drawnFainterOnThePlots();
    void barShowsAndRemovesIt();
    void refusedOverlayChangesNothing();

private:
    //! `seconds` of samples from `start`, θ = `theta`, with "trigger: …" at `trigger` [s].
    QString write(const char *name, double start, double seconds, double trigger, double theta);
    QTemporaryDir m_dir;
    QString m_first;  //!< 100 … 104 s, trigger at 101 s
    QString m_second; //!< 50 … 53 s, trigger at 52 s
};

QString TestReplayOverlay::write(const char *name, double start, double seconds, double trigger,
                                 double theta)
{
    const QString path = m_dir.filePath(QLatin1String(name));
    RecordingWriter writer;
    RecordingMetadata meta;
    meta.start = QDateTime::currentDateTimeUtc();
    meta.source = QStringLiteral("tst_replayoverlay");
    if (!writer.open(path, meta))
        return {};
    const int count = int(seconds * 1000);
    for (int i = 0; i <= count; ++i) {
        Sample s;
        s.t_s = start + i / 1000.0;
        s.theta = theta;
        s.tau = 0.01;
        if (std::abs(s.t_s - trigger) < 1e-9)
            writer.addEvent(QStringLiteral("trigger: theta rising through 0.1"));
        writer.append({s});
    }
    writer.close();
    return path;
}

void TestReplayOverlay::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_first = write("first.csv", 100, 4, 101, 0.2);
    m_second = write("second.csv", 50, 3, 52, -0.3);
    QVERIFY(!m_first.isEmpty() && !m_second.isEmpty());
}

void TestReplayOverlay::anchors()
{
    using A = ReplayController::Align;
    QList<Sample> samples(2);
    samples[0].t_s = 3;
    samples[1].t_s = 4;
    const QList<RecordingEvent> events{{3.5, QStringLiteral("K_max 0.4 → 0.6")},
                                       {3.8, QStringLiteral("trigger: push")}};
    QCOMPARE(ReplayController::anchorTime(samples, events, A::Start), 3.0);
    QCOMPARE(ReplayController::anchorTime(samples, events, A::Trigger), 3.8);
    QCOMPARE(ReplayController::anchorTime(samples, events.first(1), A::Trigger), 3.5);
    QCOMPARE(ReplayController::anchorTime(samples, {}, A::Trigger), 3.0);
}

void TestReplayOverlay::alignsAtTriggerOrStart()
{
    ReplayController replay;
    QString error;
    QVERIFY(!replay.openOverlay(m_second, &error)); // nothing replayed yet
    QVERIFY(!error.isEmpty());
    QVERIFY2(replay.open(m_first, &error), qPrintable(error));
    QSignalSpy changed(&replay, &ReplayController::overlayChanged);
    QVERIFY2(replay.openOverlay(m_second, &error), qPrintable(error));
    QCOMPARE(changed.size(), 1);
    QVERIFY(replay.hasOverlay());
    QCOMPARE(replay.overlayAlign(), ReplayController::Align::Trigger);
    QCOMPARE(replay.overlayOffset(), 101.0 - 52.0);
    QCOMPARE(replay.overlayBuffer().firstTime(), 50.0 + 49.0);
    QCOMPARE(replay.overlayBuffer().size(), 3001);

    replay.setOverlayAlign(ReplayController::Align::Start);
    QCOMPARE(changed.size(), 2);
    QCOMPARE(replay.overlayOffset(), 50.0);
    QCOMPARE(replay.overlayBuffer().firstTime(), 100.0);
    QCOMPARE(replay.overlayBuffer().lastTime(), 103.0);

    replay.close(); // leaving replay drops the overlay too
    QVERIFY(!replay.hasOverlay());
    QCOMPARE(changed.size(), 3);
}

void TestReplayOverlay::drawnFainterOnThePlots()
{
    PlotPanel plots;
    plots.resize(900, 600);
    plots.show();
    PlotFeed feed(&plots);
    QString error;
    QVERIFY2(feed.openRecording(m_first, &error), qPrintable(error));
    QVERIFY2(feed.replay()->openOverlay(m_second, &error), qPrintable(error));
    feed.replay()->setPosition(feed.replay()->endTime());
    plots.repaintNow();

    const PlotGhost *ghost = plots.overlay();
    QVERIFY(ghost);
    QCOMPARE(ghost->source(), &feed.replay()->overlayBuffer());
    QCPGraph *theta = ghost->graph(Channel::Theta);
    QVERIFY(theta->visible());
    QVERIFY(theta->dataCount() > 0);
    // On the same axes as θ, in θ's colour made translucent, out of the legend.
    QCOMPARE(theta->valueAxis(), plots.graph(Channel::Theta)->valueAxis());
    QCOMPARE(theta->pen().color().rgb(), plots.graph(Channel::Theta)->pen().color().rgb());
    QCOMPARE(theta->pen().color().alpha(), PlotGhost::kAlpha);
    QVERIFY(!plots.legend(PlotPanel::Plot::Angle)->hasItemWithPlottable(theta));
    QCOMPARE(theta->data()->at(0)->value, -0.3); // the overlay's θ, not the replayed one's

    // A hidden channel hides its overlay too.
    plots.setChannelVisible(Channel::Theta, false);
    plots.repaintNow();
    QVERIFY(!theta->visible());

    feed.backToLive();
    plots.repaintNow();
    QCOMPARE(ghost->source(), nullptr);
    QVERIFY(!ghost->graph(Channel::Tau)->visible());
}

void TestReplayOverlay::barShowsAndRemovesIt()
{
    ReplayController replay;
    ReplayBar bar(&replay);
    bar.show();
    QString error;
    QVERIFY2(replay.open(m_first, &error), qPrintable(error));
    QSignalSpy asked(&bar, &ReplayBar::overlayRequested);
    bar.overlayButton()->click();
    QCOMPARE(asked.size(), 1);
    auto *title = bar.findChild<QLabel *>(QStringLiteral("overlayTitle"));
    QVERIFY(title && !title->isVisible());
    QVERIFY(!bar.overlayAlignBox()->isVisible());

    QVERIFY2(replay.openOverlay(m_second, &error), qPrintable(error));
    QVERIFY(title->isVisible());
    QVERIFY(title->text().contains(QLatin1String("second.csv")));
    QVERIFY(bar.overlayAlignBox()->isVisible());
    bar.overlayAlignBox()->setCurrentIndex(
        bar.overlayAlignBox()->findData(int(ReplayController::Align::Start)));
    QCOMPARE(replay.overlayAlign(), ReplayController::Align::Start);
    QCOMPARE(replay.overlayOffset(), 50.0);

    bar.findChild<QToolButton *>(QStringLiteral("overlayClose"))->click();
    QVERIFY(!replay.hasOverlay());
    QVERIFY(!title->isVisible());
}

void TestReplayOverlay::refusedOverlayChangesNothing()
{
    ReplayController replay;
    QString error;
    QVERIFY2(replay.open(m_first, &error), qPrintable(error));
    QVERIFY2(replay.openOverlay(m_second, &error), qPrintable(error));
    const QString broken = m_dir.filePath(QStringLiteral("broken.csv"));
    QFile file(broken);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("not,a,recording\n1,2\n");
    file.close();
    QVERIFY(!replay.openOverlay(broken, &error));
    QVERIFY(!error.isEmpty());
    QCOMPARE(replay.overlayPath(), m_second);
    QCOMPARE(replay.overlayBuffer().size(), 3001);
}

QTEST_MAIN(TestReplayOverlay)
#include "tst_replayoverlay.moc"
