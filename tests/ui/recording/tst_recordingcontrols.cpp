// RecordingControls: suggested name, the path seam, state from the session, formatting.
#include "recording/recordingcontrols.h"

#include <QAction>
#include <QDir>
#include <QLabel>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

using namespace hatpic;

class TestRecordingControls : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void suggestsTimestampedName();
    void dialogStartsInAnExistingFolder_data();
    void dialogStartsInAnExistingFolder();
    void startAndStop();
    void cancelledChooserStartsNothing();
    void showsFailure();
    void linkLossStaysInSight();
    void noteLastsUntilTheNextRecording();
    void formatsBytes_data();
    void formatsBytes();
    void formatsDuration_data();
    void formatsDuration();
};

void TestRecordingControls::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
}

void TestRecordingControls::suggestsTimestampedName()
{
    const QString path = RecordingControls::suggestedPath();
    QVERIFY(
        QRegularExpression(QStringLiteral("/hatpic-\\d{8}-\\d{6}\\.csv$")).match(path).hasMatch());
    QVERIFY(path.startsWith(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)));
    QVERIFY(RecordingControls::suggestedPath(QStringLiteral("/data/runs"))
                .startsWith(QStringLiteral("/data/runs/hatpic-")));
}

void TestRecordingControls::dialogStartsInAnExistingFolder_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("expected");
    const QString home = QDir::home().filePath(QStringLiteral("hatpic-1.csv"));
    QTest::newRow("existing folder kept") << QDir::temp().filePath(QStringLiteral("hatpic-1.csv"))
                                          << QDir::temp().filePath(QStringLiteral("hatpic-1.csv"));
    QTest::newRow("missing Documents falls back to home")
        << QStringLiteral("/nonexistent-hatpic/Documents/hatpic-1.csv") << home;
}

void TestRecordingControls::dialogStartsInAnExistingFolder()
{
    QFETCH(QString, path);
    QFETCH(QString, expected);
    QCOMPARE(RecordingControls::inExistingFolder(path), expected);
}

void TestRecordingControls::startAndStop()
{
    RecordingControls controls;
    QAction *record = controls.recordAction();
    QVERIFY(!record->isEnabled()); // not connected
    controls.setCanRecord(true);
    QVERIFY(record->isEnabled());
    controls.setPathChooser([](const QString &) { return QStringLiteral("/data/runs/trial"); });
    QSignalSpy start(&controls, &RecordingControls::startRequested);
    QSignalSpy stop(&controls, &RecordingControls::stopRequested);
    record->trigger();
    QCOMPARE(start.size(), 1);
    QCOMPARE(start.at(0).at(0).toString(), QStringLiteral("/data/runs/trial.csv"));
    QCOMPARE(controls.directory(), QStringLiteral("/data/runs"));
    QVERIFY(!record->isChecked()); // until the session says it records

    RecordingStatus status;
    status.active = true;
    status.path = QStringLiteral("/data/runs/trial.csv");
    status.seconds = 75.4;
    status.bytes = 2'500'000;
    status.samples = 75400;
    controls.setStatus(status);
    QVERIFY(record->isChecked());
    QCOMPARE(controls.statusText(), QStringLiteral("● 01:15 · 2.5 MB · 75400 samples"));
    controls.setCanRecord(false); // a recording can be stopped even when the link is lost
    QVERIFY(record->isEnabled());
    record->trigger();
    QCOMPARE(stop.size(), 1);
    QCOMPARE(start.size(), 1);

    status.active = false;
    controls.setStatus(status);
    QVERIFY(!record->isChecked());
    QVERIFY(controls.statusText().startsWith(QStringLiteral("Saved trial.csv")));
}

void TestRecordingControls::cancelledChooserStartsNothing()
{
    RecordingControls controls;
    controls.setCanRecord(true);
    controls.setPathChooser([](const QString &) { return QString(); });
    QSignalSpy start(&controls, &RecordingControls::startRequested);
    controls.recordAction()->trigger();
    QCOMPARE(start.size(), 0);
    QVERIFY(!controls.recordAction()->isChecked());
}

void TestRecordingControls::showsFailure()
{
    RecordingControls controls;
    RecordingStatus status;
    status.error = QStringLiteral("No space left on device");
    controls.setStatus(status);
    QCOMPARE(controls.statusText(), QStringLiteral("Recording stopped: No space left on device"));
}

//! The text the user reads beside the record button.
QString labelText(const RecordingControls &controls)
{
    return controls.findChild<QLabel *>(QStringLiteral("recordingStatus"))->text();
}

void TestRecordingControls::linkLossStaysInSight()
{
    RecordingControls controls;
    controls.setCanRecord(true);
    RecordingStatus status;
    status.active = true;
    status.path = QStringLiteral("/data/run.csv");
    status.seconds = 12;
    status.bytes = 3400;
    status.samples = 2400;
    status.waiting = true;
    status.gaps = 1;
    controls.setStatus(status);
    // While the device is away: still recording, and saying what it waits for.
    QVERIFY(controls.recordAction()->isChecked());
    QCOMPARE(controls.recordAction()->text(), QStringLiteral("Stop &recording"));
    QCOMPARE(labelText(controls),
             QStringLiteral("● 00:12 · 3.4 kB · 2400 samples · waiting for the device"));
    QVERIFY(controls.findChild<QLabel *>(QStringLiteral("recordingStatus"))
                ->toolTip()
                .contains(QStringLiteral("goes on in the same file when the device is back")));
    // Back: the gap count stays beside the figures for the rest of the recording…
    status.waiting = false;
    status.seconds = 20;
    controls.setStatus(status);
    QCOMPARE(labelText(controls), QStringLiteral("● 00:20 · 3.4 kB · 2400 samples · 1 gap"));
    QVERIFY(controls.findChild<QLabel *>(QStringLiteral("recordingStatus"))
                ->toolTip()
                .contains(QStringLiteral("Link losses during this recording: 1")));
    // …and after it: "Saved" alone would read as a clean recording.
    status.active = false;
    status.gaps = 2;
    controls.setStatus(status);
    QCOMPARE(labelText(controls), QStringLiteral("Saved run.csv (3.4 kB) · 2 gaps"));
}

void TestRecordingControls::noteLastsUntilTheNextRecording()
{
    RecordingControls controls;
    controls.setCanRecord(true);
    RecordingStatus status;
    status.path = QStringLiteral("/data/run.csv");
    status.bytes = 812;
    status.gaps = 1;
    controls.setStatus(status);
    const QString note =
        QStringLiteral("Recording ended at the link loss: a different device answered.");
    controls.setNote(note);
    QCOMPARE(labelText(controls), QStringLiteral("Saved run.csv (812 B) · 1 gap — ") + note);
    // Progress of nothing (a repeated final status) does not clear it; only a new recording.
    controls.setStatus(status);
    QVERIFY(labelText(controls).endsWith(note));
    status.active = true;
    status.gaps = 0;
    status.samples = 5;
    controls.setStatus(status);
    QVERIFY(controls.note().isEmpty());
    QVERIFY(!labelText(controls).contains(note));
}

void TestRecordingControls::formatsBytes_data()
{
    QTest::addColumn<qint64>("bytes");
    QTest::addColumn<QString>("text");
    QTest::newRow("bytes") << qint64(812) << QStringLiteral("812 B");
    QTest::newRow("kilobytes") << qint64(3400) << QStringLiteral("3.4 kB");
    QTest::newRow("megabytes") << qint64(12'100'000) << QStringLiteral("12.1 MB");
    QTest::newRow("gigabytes") << qint64(2'500'000'000) << QStringLiteral("2.50 GB");
}

void TestRecordingControls::formatsBytes()
{
    QFETCH(qint64, bytes);
    QFETCH(QString, text);
    QCOMPARE(RecordingControls::formatBytes(bytes), text);
}

void TestRecordingControls::formatsDuration_data()
{
    QTest::addColumn<double>("seconds");
    QTest::addColumn<QString>("text");
    QTest::newRow("seconds") << 7.9 << QStringLiteral("00:07");
    QTest::newRow("minutes") << 723.0 << QStringLiteral("12:03");
    QTest::newRow("hours") << 3723.0 << QStringLiteral("1:02:03");
    QTest::newRow("negative clamps") << -3.0 << QStringLiteral("00:00");
}

void TestRecordingControls::formatsDuration()
{
    QFETCH(double, seconds);
    QFETCH(QString, text);
    QCOMPARE(RecordingControls::formatDuration(seconds), text);
}

QTEST_MAIN(TestRecordingControls)
#include "tst_recordingcontrols.moc"
