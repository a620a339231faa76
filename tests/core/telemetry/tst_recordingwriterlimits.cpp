// RecordingWriter and readRecording against hostile conditions (issue 10, "Hostile input"): a disk
// that fills up, files that are not ours or not files, floods of events, sidecars that are
// devices, CR-only line ends. Real files on real filesystems (a 64 KiB tmpfs for the full disk).
#include "telemetry/recordingreader.h"
#include "telemetry/recordingwriter.h"
#include "testfiles.h"
#include "tmpfsmount.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace hatpic;
using namespace Qt::StringLiterals;
using hatpic::test::readAll;
using hatpic::test::writeFile;

namespace {

RecordingMetadata metadata()
{
    RecordingMetadata m;
    m.start = QDateTime(QDate(2024, 5, 17), QTime(9, 30, 15, 250), Qt::UTC);
    m.device.port = u"/dev/ttyUSB0"_s;
    m.source = u"tst_recorderlimits"_s;
    return m;
}

Sample sample(double t)
{
    Sample s;
    s.t_s = t;
    s.theta = double(0.05f);
    s.omega = 0.5;
    s.tau = double(-0.01f);
    s.tau_rec = double(-0.02f);
    s.tau_total = double(-0.02f);
    s.v_ref = 0.025;
    s.p_ref = 1.0 / 3.0;
    return s;
}

} // namespace

class TestRecordingWriterLimits : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void diskFillsUpMidRecording();
    void diskFullAtOpenChangesNothing();
    void refusedStartLeavesFilesUntouched();
    void foreignJsonIsNeverOverwritten();
    void deviceTargetsAreRefused_data();
    void deviceTargetsAreRefused();
    void eventFloodIsBounded();
    void metadataThatIsADeviceIsIgnored();
    void crOnlyLineEndsAreNamed();
};

void TestRecordingWriterLimits::diskFillsUpMidRecording()
{
    TmpfsMount fs(64);
    if (!fs.isValid())
        QSKIP("cannot mount a tmpfs (needs root)");
    const QString csv = fs.filePath(u"run.csv"_s);
    RecordingWriter rec;
    QVERIFY2(rec.open(csv, metadata()), qPrintable(rec.error()));
    rec.addEvent(u"K_max 0.4 → 0.6"_s);
    bool failed = false;
    for (int batch = 0; batch < 1000 && !failed; ++batch) {
        SampleBatch b;
        for (int i = 0; i < 64; ++i)
            b.append(sample(batch * 0.064 + i * 1e-3));
        failed = !rec.append(b) || !rec.flush();
        if (batch % 10 == 0)
            rec.addEvent(u"p_ref reset to 0"_s);
    }
    QVERIFY(failed);
    QVERIFY2(rec.error().contains(u"No space left on device"), qPrintable(rec.error()));
    const RecordingStatus status = rec.status();

    // Whole rows only, and every figure says how many there are.
    const QByteArray text = readAll(csv);
    QVERIFY(text.endsWith('\n'));
    const qsizetype rows = text.count('\n') - 1;
    QCOMPARE(quint64(rows), status.samples);
    QCOMPARE(status.bytes, qint64(text.size()));
    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording, qPrintable(read.error));
    QVERIFY2(read.warnings.isEmpty(), qPrintable(read.warnings.join(u'\n')));
    QCOMPARE(read.recording->samples.size(), rows);

    // The sidecar is the last good one (never a 0-byte file) and readable.
    const QByteArray json = readAll(recordingMetadataPath(csv));
    QVERIFY2(!json.isEmpty(), "the .json was emptied by the full disk");
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &error);
    QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(error.errorString()));
    QCOMPARE(doc.object().value(u"format").toString(), u"hatpic-recording"_s);
    QVERIFY(read.recording->hasMetadata);
}

void TestRecordingWriterLimits::diskFullAtOpenChangesNothing()
{
    TmpfsMount fs(64);
    if (!fs.isValid())
        QSKIP("cannot mount a tmpfs (needs root)");
    fs.fill();
    const QString csv = fs.filePath(u"full.csv"_s);
    RecordingWriter rec;
    QVERIFY(!rec.open(csv, metadata()));
    QVERIFY(!rec.isOpen());
    QVERIFY2(rec.error().contains(u"No space left on device") && rec.error().contains(u"full."_s),
             qPrintable(rec.error()));
    QVERIFY(!QFileInfo::exists(recordingMetadataPath(csv)));
    QVERIFY(!rec.append({sample(0)}));
}

void TestRecordingWriterLimits::refusedStartLeavesFilesUntouched()
{
    // k.json is a folder: the start fails, and the existing k.csv keeps its content.
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"k.csv"_s);
    QVERIFY(writeFile(csv, "precious data\n"));
    QVERIFY(QDir(dir.path()).mkdir(u"k.json"_s));
    RecordingWriter rec;
    QVERIFY(!rec.open(csv, metadata()));
    QVERIFY2(rec.error().contains(u"k.json") && rec.error().contains(u"not a regular file"),
             qPrintable(rec.error()));
    QCOMPARE(readAll(csv), QByteArray("precious data\n"));
}

void TestRecordingWriterLimits::foreignJsonIsNeverOverwritten()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"mine.csv"_s);
    const QString json = dir.filePath(u"mine.json"_s);
    const QByteArray profile = R"({"format": "hatpic-profile", "version": 1})";
    QVERIFY(writeFile(json, profile));
    RecordingWriter rec;
    QVERIFY(!rec.open(csv, metadata()));
    QVERIFY2(rec.error().contains(json) && rec.error().contains(u"untouched"),
             qPrintable(rec.error()));
    QCOMPARE(readAll(json), profile);
    QVERIFY(!QFileInfo::exists(csv));

    // An earlier recording's metadata is ours to replace.
    QVERIFY(QFile::remove(json));
    {
        RecordingWriter first;
        QVERIFY(first.open(csv, metadata()));
    }
    QVERIFY2(rec.open(csv, metadata()), qPrintable(rec.error()));
}

void TestRecordingWriterLimits::deviceTargetsAreRefused_data()
{
    QTest::addColumn<QString>("target");
    QTest::newRow("/dev/null") << u"/dev/null"_s;
    QTest::newRow("/dev/full") << u"/dev/full"_s;
    QTest::newRow("a folder") << u"."_s;
}

void TestRecordingWriterLimits::deviceTargetsAreRefused()
{
    // Through a link in a temporary folder, so a failure cannot create /dev/null.json.
    QFETCH(QString, target);
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"out.csv"_s);
    QVERIFY(QFile::link(target == u"."_s ? dir.path() : target, csv));
    RecordingWriter rec;
    QVERIFY(!rec.open(csv, metadata()));
    QVERIFY2(rec.error().contains(u"not a regular file"), qPrintable(rec.error()));
    QVERIFY(!QFileInfo::exists(dir.filePath(u"out.json"_s)));
}

void TestRecordingWriterLimits::eventFloodIsBounded()
{
    // A device flooding PARAMS: 2000 events per second for 3 s. Every row stays readable, the
    // rate is bounded, and what was left out is counted.
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"flood.csv"_s);
    RecordingWriter rec;
    QVERIFY(rec.open(csv, metadata()));
    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < 3000; ++i) {
        rec.addEvent(u"K_max 0.4 → 0.6000000238418579; K_min 0.15 → 0.2 (read back)"_s);
        rec.addEvent(u"K_max 0.6000000238418579 → 0.4; K_min 0.2 → 0.15 (read back)"_s);
        QVERIFY(rec.append({sample(i * 1e-3)}));
        if (i % 500 == 0)
            QVERIFY(rec.flush());
    }
    rec.close();
    QVERIFY2(clock.elapsed() < 10000, qPrintable(QString::number(clock.elapsed())));
    const RecordingStatus status = rec.status();
    QVERIFY2(status.eventsDropped >= 6000 - 4 * RecordingWriter::kMaxEventsPerSecond,
             qPrintable(QString::number(status.eventsDropped)));

    const RecordingReadResult read = readRecording(csv);
    QVERIFY2(read.recording, qPrintable(read.error));
    QCOMPARE(read.recording->samples.size(), 3000);
    for (const QByteArray &line : readAll(csv).split('\n'))
        QVERIFY(line.size() <= 2 * RecordingWriter::kMaxEventTextPerRow);
    const QByteArray json = readAll(recordingMetadataPath(csv));
    QVERIFY2(json.size() < 512 * 1024, qPrintable(QString::number(json.size())));
    const QJsonObject o = QJsonDocument::fromJson(json).object();
    QCOMPARE(quint64(o.value(u"events_dropped").toDouble()), status.eventsDropped);
    QVERIFY(read.recording->events.first().text.contains(u"K_max 0.4 → 0.6"));
    QVERIFY(read.recording->events.size() <= 3 * (RecordingWriter::kMaxEventsPerSecond + 1));
    QVERIFY(std::any_of(
        read.recording->events.cbegin(), read.recording->events.cend(),
        [](const RecordingEvent &e) { return e.text.contains(u"more events not recorded"); }));
}

void TestRecordingWriterLimits::metadataThatIsADeviceIsIgnored()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"zero.csv"_s);
    QVERIFY(writeFile(csv, "t_s,theta\n0,0.1\n"));
    QVERIFY(QFile::link(u"/dev/zero"_s, dir.filePath(u"zero.json"_s)));
    QElapsedTimer clock;
    clock.start();
    const RecordingReadResult read = readRecording(csv);
    QVERIFY(clock.elapsed() < 5000);
    QVERIFY2(read.recording, qPrintable(read.error));
    QVERIFY(!read.recording->hasMetadata);
    QVERIFY2(read.warnings.join(u' ').contains(u"not a regular file"),
             qPrintable(read.warnings.join(u' ')));

    // A pipe as the CSV is refused without blocking.
    const QString fifo = dir.filePath(u"pipe.csv"_s);
    QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    const RecordingReadResult pipe = readRecording(fifo);
    QVERIFY(!pipe.recording);
    QVERIFY2(pipe.error.contains(u"not a regular file"), qPrintable(pipe.error));
}

void TestRecordingWriterLimits::crOnlyLineEndsAreNamed()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(u"mac.csv"_s);
    QVERIFY(writeFile(csv, "t_s,theta,omega\r0,0.1,0\r0.001,0.2,0\r"));
    const RecordingReadResult read = readRecording(csv);
    QVERIFY(!read.recording);
    QVERIFY2(read.error.contains(u"CR-only"), qPrintable(read.error));
}

QTEST_GUILESS_MAIN(TestRecordingWriterLimits)
#include "tst_recordingwriterlimits.moc"
