// ReplayController: opens recordings, clamps and scrubs the playhead, plays at a speed,
// refuses broken files without leaving the current state.
#include "plots/replaycontroller.h"
#include "plots/samplebuffer.h"
#include "plots/samplecsvwriter.h"
#include "telemetry/recording.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace hatpic;

class TestReplayController : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void opensRecording();
    void opensStreamOutput();
    void clampsPosition_data();
    void clampsPosition();
    void playsAtSpeed_data();
    void playsAtSpeed();
    void refusesBrokenFiles_data();
    void refusesBrokenFiles();
    void closeLeavesReplay();

private:
    QString writeRecording(double start, double seconds, const QString &name);
    QTemporaryDir m_dir;
    QString m_path;
};

QString TestReplayController::writeRecording(double start, double seconds, const QString &name)
{
    SampleBuffer buffer(int(seconds * 1000) + 1);
    for (int i = 0; i <= int(seconds * 1000); ++i) {
        Sample s;
        s.t_s = start + i / 1000.0;
        s.theta = i * 1e-4;
        buffer.append(s);
    }
    const QString path = m_dir.filePath(name);
    SampleCsvWriter::write(buffer, start, start + seconds, path);
    return path;
}

void TestReplayController::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_path = writeRecording(10.0, 4.0, QStringLiteral("four-seconds.csv"));
}

void TestReplayController::opensRecording()
{
    ReplayController replay;
    QSignalSpy active(&replay, &ReplayController::activeChanged);
    QString error;
    QVERIFY2(replay.open(m_path, &error), qPrintable(error));
    QCOMPARE(active.size(), 1);
    QVERIFY(replay.isActive());
    QCOMPARE(replay.buffer().size(), 4001);
    QCOMPARE(replay.startTime(), 10.0);
    QCOMPARE(replay.endTime(), 14.0);
    QCOMPARE(replay.position(), 10.0);
    QVERIFY(!replay.recording().hasMetadata); // a bare CSV: defaults
    QCOMPARE(replay.currentSample()->t_s, 10.0);
}

void TestReplayController::opensStreamOutput()
{
    // What `hatpicctl stream` prints without --csv: no event column, no .json beside it.
    const QString path = m_dir.filePath(QStringLiteral("stream-stdout.csv"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags\n"
               "0,0.26,-0.85,-0.031,-0.039,0,-0.039,0.13,0,0\n"
               "0.001,0.262,-0.859,-0.0308,-0.0393,0,-0.0393,0.131,0.00013,2\n"
               "0.002,0.261,-0.86,-0.0307,-0.0392,0,-0.0392,0.130,0.00026,2\n");
    file.close();
    ReplayController replay;
    QString error;
    QVERIFY2(replay.open(path, &error), qPrintable(error));
    QCOMPARE(replay.buffer().size(), 3);
    QVERIFY(replay.recording().events.isEmpty());
    QCOMPARE(replay.buffer().value(Channel::TauRec, 1), -0.0393);
    QCOMPARE(replay.buffer().flags(2), quint16(2));
}

void TestReplayController::clampsPosition_data()
{
    QTest::addColumn<double>("requested");
    QTest::addColumn<double>("expected");
    QTest::addColumn<double>("sampleTime");
    QTest::newRow("before start") << 0.0 << 10.0 << 10.0;
    QTest::newRow("inside, between samples") << 12.3456 << 12.3456 << 12.345;
    QTest::newRow("after end") << 99.0 << 14.0 << 14.0;
}

void TestReplayController::clampsPosition()
{
    QFETCH(double, requested);
    QFETCH(double, expected);
    QFETCH(double, sampleTime);
    ReplayController replay;
    QVERIFY(replay.open(m_path));
    replay.setPosition(requested);
    QCOMPARE(replay.position(), expected);
    QCOMPARE(replay.currentSample()->t_s, sampleTime);
}

void TestReplayController::playsAtSpeed_data()
{
    QTest::addColumn<double>("speed");
    QTest::newRow("1x") << 1.0;
    QTest::newRow("5x") << 5.0;
}

void TestReplayController::playsAtSpeed()
{
    QFETCH(double, speed);
    ReplayController replay;
    QVERIFY(replay.open(m_path));
    replay.setSpeed(speed);
    QSignalSpy playing(&replay, &ReplayController::playingChanged);
    QElapsedTimer clock;
    clock.start();
    replay.play();
    QVERIFY(replay.isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(replay.position() >= 10.5, 10000);
    replay.pause();
    const double wall = clock.nsecsElapsed() / 1e9;
    const double advanced = replay.position() - 10.0;
    // Never faster than the speed asks (the timer only ever lags).
    QVERIFY2(advanced <= speed * wall + 1e-9,
             qPrintable(QStringLiteral("%1 s in %2 s").arg(advanced).arg(wall)));
    QCOMPARE(playing.size(), 2);

    // At the end it stops by itself; play() again starts over.
    replay.setPosition(13.99);
    replay.play();
    QTRY_VERIFY_WITH_TIMEOUT(!replay.isPlaying(), 10000);
    QCOMPARE(replay.position(), 14.0);
    replay.play();
    QVERIFY(replay.position() < 11.0);
}

void TestReplayController::refusesBrokenFiles_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::newRow("empty file") << QByteArray();
    QTest::newRow("no t_s column") << QByteArray("a,b\n1,2\n");
    QTest::newRow("header only") << QByteArray("t_s,theta\n");
    QTest::newRow("not a number") << QByteArray("t_s,theta\n0,abc\n1,2\n");
}

void TestReplayController::refusesBrokenFiles()
{
    QFETCH(QByteArray, content);
    ReplayController replay;
    QVERIFY(replay.open(m_path));
    replay.setPosition(12);
    const QString path = m_dir.filePath(QStringLiteral("broken.csv"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(content);
    file.close();
    QString error;
    QVERIFY(!replay.open(path, &error));
    QVERIFY(!error.isEmpty());
    // Nothing changed.
    QCOMPARE(replay.path(), m_path);
    QCOMPARE(replay.position(), 12.0);
    QCOMPARE(replay.buffer().size(), 4001);
}

void TestReplayController::closeLeavesReplay()
{
    ReplayController replay;
    QVERIFY(replay.open(m_path));
    replay.play();
    QSignalSpy active(&replay, &ReplayController::activeChanged);
    replay.close();
    QCOMPARE(active.size(), 1);
    QVERIFY(!replay.isActive());
    QVERIFY(!replay.isPlaying());
    QVERIFY(replay.buffer().isEmpty());
    replay.close(); // twice is harmless
    QCOMPARE(active.size(), 1);
}

QTEST_GUILESS_MAIN(TestReplayController)
#include "tst_replaycontroller.moc"
