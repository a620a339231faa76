// The real MainWindow's recording and replay, on the in-process simulator ("sim"): pause keeps
// the link and the data coming, a recording made from the window is a valid file with its
// events, a recording replays (scrub, play, back to live, broken files refused), and the replay
// bar keeps its slider and the window its size with long names and huge time spans.
#include "editor/parametereditor.h"
#include "mainwindowtest.h"
#include "plots/plotfeed.h"
#include "plots/plotpanel.h"
#include "plots/qcp.h"
#include "plots/replaycontroller.h"
#include "recording/recordingcontrols.h"
#include "recording/replaybar.h"
#include "telemetry/recordingreader.h"
#include "telemetry/recordingwriter.h"
#include "window/mainwindow.h"

#include <QAction>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QScreen>
#include <QSlider>
#include <QTest>

#include <cmath>
#include <memory>

using namespace hatpic;

class TestMainWindowReplay : public test::MainWindowTest
{
    Q_OBJECT
public:
    TestMainWindowReplay() : MainWindowTest(QStringLiteral("tst_mainwindowreplay")) {}

private Q_SLOTS:
    void pauseKeepsLinkRecording();
    void recordCreatesValidFile();
    void replayShowsRecordingAndReturnsToLive();
    void narrowReplayBarKeepsItsSlider();
    void hugeReplaySpanKeepsTheWindow_data();
    void hugeReplaySpanKeepsTheWindow();
};

void TestMainWindowReplay::pauseKeepsLinkRecording()
{
    connectSim();
    PlotPanel *plots = find<PlotPanel>("plotPanel");
    plots->setWindowLength(1);
    QVERIFY(waitForSamples(1200)); // more than the window: the view scrolls
    plots->repaintNow();
    find<QAction>("pauseAction")->trigger();
    QVERIFY(find<PlotPanel>("plotPanel")->isPaused());
    QVERIFY(find<QAction>("pauseAction")->isChecked());
    const double end = plots->viewEnd();
    const quint64 appended = liveBuffer().appendedCount();
    QVERIFY(waitForSamples(500));
    QVERIFY(liveBuffer().appendedCount() >= appended + 500);
    plots->repaintNow();
    QCOMPARE(plots->viewEnd(), end);
    find<QAction>("pauseAction")->trigger();
    QVERIFY(!find<PlotPanel>("plotPanel")->isPaused());
    QTRY_VERIFY(plots->viewEnd() > end);
}

void TestMainWindowReplay::recordCreatesValidFile()
{
    connectSim();
    ParameterEditor *editor = find<ParameterEditor>("parameterEditor");
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::InSync, kConnectMs);
    const QString path = m_dir.filePath(QStringLiteral("session.csv"));
    RecordingControls *controls = find<RecordingControls>("recordingControls");
    QString suggested;
    controls->setPathChooser([&](const QString &s) {
        suggested = s;
        return path;
    });
    QAction *record = controls->recordAction();
    QCOMPARE(record->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_R));
    QVERIFY(record->isEnabled());
    record->trigger();
    QVERIFY(QFileInfo(suggested).fileName().startsWith(QStringLiteral("hatpic-")));
    QVERIFY(suggested.endsWith(QStringLiteral(".csv")));
    QTRY_VERIFY_WITH_TIMEOUT(controls->status().active, kConnectMs);
    QVERIFY(record->isChecked());
    QTRY_VERIFY_WITH_TIMEOUT(controls->status().samples > 300, kDataMs);
    QVERIFY(controls->statusText().contains(QStringLiteral("samples")));

    DeviceParams edited = editor->params();
    edited.K_max = 0.5;
    editor->setParams(edited, editor->hostParams(), QStringLiteral("K_max"));
    editor->pushAction()->trigger();
    QTRY_COMPARE_WITH_TIMEOUT(editor->syncState(), SyncState::InSync, kConnectMs);
    QVERIFY(waitForSamples(200));
    record->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!controls->status().active, kConnectMs);
    QVERIFY(!record->isChecked());

    const RecordingReadResult result = readRecording(path);
    QVERIFY2(result.recording.has_value(), qPrintable(result.error));
    QVERIFY(result.recording->samples.size() > 300);
    QVERIFY(result.recording->hasMetadata);
    QCOMPARE(result.recording->metadata.source, QStringLiteral("hatpic-tuner"));
    QVERIFY(result.recording->metadata.device.simulated);
    QVERIFY(!result.recording->events.isEmpty());
    QVERIFY2(result.recording->events.constFirst().text.contains(QStringLiteral("K_max")),
             qPrintable(result.recording->events.constFirst().text));
}

void TestMainWindowReplay::replayShowsRecordingAndReturnsToLive()
{
    // A recording as the core writes it (the same file hatpicctl stream produces).
    const QString path = m_dir.filePath(QStringLiteral("replay.csv"));
    {
        RecordingWriter recorder;
        RecordingMetadata meta;
        meta.start = QDateTime::currentDateTimeUtc();
        meta.source = QStringLiteral("hatpicctl stream");
        meta.params.K_max = 0.45;
        QVERIFY2(recorder.open(path, meta), qPrintable(recorder.error()));
        SampleBatch batch;
        for (int i = 0; i < 5000; ++i) {
            Sample s;
            s.t_s = 100 + i * 0.001;
            s.theta = 0.2 * std::sin(i * 0.002);
            s.tau_rec = -0.4 * s.theta;
            batch.append(s);
            if (i == 2500) {
                QVERIFY(recorder.append(batch));
                batch.clear();
                recorder.addEvent(QStringLiteral("K_max 0.4 → 0.45"));
            }
        }
        QVERIFY(recorder.append(batch));
        recorder.close();
    }

    connectSim();
    QVERIFY(waitForSamples(100));
    QString error;
    QVERIFY2(m_window->openRecording(path, &error), qPrintable(error));
    QVERIFY(find<PlotFeed>("plotFeed")->isReplaying());
    ReplayBar *bar = find<ReplayBar>("replayBar");
    QVERIFY(bar->isVisible());
    PlotPanel *plots = find<PlotPanel>("plotPanel");
    ReplayController *replay = find<ReplayController>("replayController");
    QCOMPARE(plots->source(), &replay->buffer());
    QVERIFY(!plots->followsLatest());
    QCOMPARE(plots->events().size(), 1);
    QVERIFY(find<QAction>("pauseAction")->text().contains(QStringLiteral("Replay")));
    QCOMPARE(replay->startTime(), 100.0);

    // It opens on a full first window (here the whole 5 s recording).
    QCOMPARE(replay->position(), replay->endTime());
    QCOMPARE(plots->viewStart(), 100.0);
    // Scrub with the slider: data up to the playhead; the view ends there once it is full.
    bar->slider()->setValue(3000);
    QCOMPARE(replay->position(), 103.0);
    QCOMPARE(plots->dataEnd(), 103.0);
    QCOMPARE(plots->viewEnd(), 110.0); // 10 s window, not yet full
    m_window->setWindowSeconds(2);
    QCOMPARE(plots->viewEnd(), 103.0);
    QCOMPARE(plots->viewStart(), 101.0);
    plots->repaintNow();
    QVERIFY(plots->pointCount(Channel::Theta) > 0);
    const QCPGraphData last = *(plots->graph(Channel::Theta)->data()->constEnd() - 1);
    QVERIFY(last.key <= 103.001);
    QVERIFY(bar->positionText().startsWith(QStringLiteral("3.00")));
    // The slider counts from the recording's start, the plots' axis in session time: both
    // are shown, each labelled, and the session time is the axis's.
    QCOMPARE(find<QLabel>("replaySessionTime")->text(), QStringLiteral("t = 103.00 s"));
    QCOMPARE(find<QLabel>("replaySessionTime")->text(),
             ReplayBar::sessionTimeText(plots->dataEnd().value_or(0)));
    QVERIFY(find<QLabel>("replayTime")->toolTip().contains(QStringLiteral("recording")));
    QVERIFY(find<QLabel>("replaySessionTime")->toolTip().contains(QStringLiteral("axis")));

    // Play at 5×: the playhead moves; live samples keep arriving but are not shown.
    bar->speedBox()->setCurrentIndex(bar->speedBox()->findData(5.0));
    QCOMPARE(replay->speed(), 5.0);
    find<QAction>("pauseAction")->trigger(); // Space plays and pauses the replay
    QVERIFY(replay->isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(replay->position() > 103.5, 10000);
    find<QAction>("pauseAction")->trigger();
    QVERIFY(!replay->isPlaying());
    QVERIFY(find<QAction>("pauseAction")->isChecked());
    // The bar's ▶ plays too, and the Play / Pause action follows it.
    QTest::mouseClick(bar->playButton(), Qt::LeftButton);
    QVERIFY(replay->isPlaying());
    QVERIFY(!find<QAction>("pauseAction")->isChecked());
    QTest::mouseClick(bar->playButton(), Qt::LeftButton);
    QVERIFY(!replay->isPlaying());
    QVERIFY(find<QAction>("pauseAction")->isChecked());

    // One click back to live.
    QTest::mouseClick(bar->liveButton(), Qt::LeftButton);
    QVERIFY(!find<PlotFeed>("plotFeed")->isReplaying());
    QVERIFY(!bar->isVisible());
    QCOMPARE(plots->source(), &liveBuffer());
    QVERIFY(plots->followsLatest());
    QCOMPARE(plots->viewEnd(), liveViewEnd(*m_window));

    // A broken file is refused with a reason, and live stays live.
    const QString broken = m_dir.filePath(QStringLiteral("broken.csv"));
    QFile file(broken);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("a,b\n1,2\n");
    file.close();
    QVERIFY(!m_window->openRecording(broken, &error));
    QVERIFY(!error.isEmpty());
    QVERIFY(!find<PlotFeed>("plotFeed")->isReplaying());
}

void TestMainWindowReplay::narrowReplayBarKeepsItsSlider()
{
    // A long file name and source must not squeeze the scrub slider to nothing, nor widen the
    // centre of a laptop-sized window at the editor's expense.
    const QString path = m_dir.filePath(
        QStringLiteral("a-rather-long-recording-name-from-the-morning-session-trial-07.csv"));
    {
        RecordingWriter recorder;
        RecordingMetadata meta;
        meta.start = QDateTime::currentDateTimeUtc();
        meta.source = QStringLiteral("hatpicctl stream --csv on the lab bench computer");
        QVERIFY2(recorder.open(path, meta), qPrintable(recorder.error()));
        SampleBatch batch;
        for (int i = 0; i < 3000; ++i) {
            Sample s;
            s.t_s = i * 0.001;
            batch.append(s);
        }
        QVERIFY(recorder.append(batch));
        recorder.close();
    }
    m_window->resize(1000, 700);
    QString error;
    QVERIFY2(m_window->openRecording(path, &error), qPrintable(error));
    ReplayBar *bar = find<ReplayBar>("replayBar");
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QVERIFY(bar->isVisible());
    QVERIFY2(bar->slider()->width() >= 120, qPrintable(QString::number(bar->slider()->width())));
    QVERIFY2(bar->minimumSizeHint().width() < 600,
             qPrintable(QString::number(bar->minimumSizeHint().width())));
    auto *title = bar->findChild<QLabel *>(QStringLiteral("replayTitle"));
    QVERIFY(title);
    QVERIFY(title->toolTip().contains(QStringLiteral("morning-session-trial-07.csv")));
    QVERIFY(title->toolTip().contains(QStringLiteral("lab bench")));
}

void TestMainWindowReplay::hugeReplaySpanKeepsTheWindow_data()
{
    QTest::addColumn<QByteArray>("csv");
    QTest::addColumn<double>("middle"); // t at the slider's middle
    QTest::newRow("0 to 1e300 s") << QByteArray("t_s,theta\n0,0\n5e299,0.1\n1e300,0\n") << 5e299;
    QTest::newRow("35 days (ms overflow an int)")
        << QByteArray("t_s,theta\n0,0\n1500000,0.1\n3000000,0\n") << 1.5e6;
    QTest::newRow("beyond the largest double")
        << QByteArray("t_s,theta\n-1.7e308,0\n0,0.1\n1.7e308,0\n") << 0.0;
}

void TestMainWindowReplay::hugeReplaySpanKeepsTheWindow()
{
    // Issue 10: a recording whose t_s spans 0…1e300 widened the window to 5474 px (a 300-digit
    // time label) and saved that size for every later launch; spans over ~24.8 days overflowed
    // the slider's int.
    QFETCH(QByteArray, csv);
    QFETCH(double, middle);
    const QString path = m_dir.filePath(QStringLiteral("span.csv"));
    {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(csv);
    }
    const QRect available = m_window->screen()->availableGeometry();
    m_window->resize(m_window->minimumSizeHint().expandedTo(QSize(1100, 700))); // room for the bar
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    const int width = m_window->width();
    const int minimumWidth = m_window->minimumSizeHint().width();

    QString error;
    QVERIFY2(m_window->openRecording(path, &error), qPrintable(error));
    ReplayBar *bar = find<ReplayBar>("replayBar");
    ReplayController *replay = find<ReplayController>("replayController");
    for (int i = 0; i < 4; ++i)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    find<PlotPanel>("plotPanel")->repaintNow();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);

    // Nothing widens the window: not the replay bar, not the plots' axis labels.
    QCOMPARE(m_window->width(), width);
    QVERIFY2(m_window->minimumSizeHint().width() <= width,
             qPrintable(QString::number(m_window->minimumSizeHint().width())));
    QVERIFY2(bar->minimumSizeHint().width() < 700,
             qPrintable(QString::number(bar->minimumSizeHint().width())));
    QVERIFY2(bar->positionText().size() <= 24, qPrintable(bar->positionText()));
    auto *plot = find<PlotPanel>("plotPanel")->findChild<QCustomPlot *>();
    QVERIFY(plot);
    for (QCPAxisRect *rect : plot->axisRects()) {
        for (QCPAxis *axis : rect->axes()) {
            for (const QString &label : axis->tickVectorLabels())
                QVERIFY2(label.size() <= 16, qPrintable(label));
        }
    }

    // The slider covers the whole span in an int, both ways.
    QSlider *slider = bar->slider();
    QVERIFY(slider->maximum() > 0 && slider->maximum() <= ReplayBar::kMaxSliderSteps);
    slider->setValue(slider->maximum());
    QCOMPARE(replay->position(), replay->endTime());
    slider->setValue(slider->maximum() / 2);
    QVERIFY2(std::abs(replay->position() - middle) <= 1e-6 * replay->endTime(),
             qPrintable(QString::number(replay->position())));
    replay->setPosition(replay->startTime());
    QCOMPARE(slider->value(), 0);
    replay->setPosition(replay->endTime());
    QCOMPARE(slider->value(), slider->maximum());

    // The next launch gets a window that fits the screen.
    QVERIFY(m_window->close());
    m_window = std::make_unique<MainWindow>();
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QVERIFY2(m_window->width() <= std::max(available.width(), minimumWidth),
             qPrintable(QString::number(m_window->width())));
}

QTEST_MAIN(TestMainWindowReplay)
#include "tst_mainwindowreplay.moc"
