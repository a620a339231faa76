// RecordingWriter: the CSV and JSON it writes (columns, rows, quoted events, the sidecar's
// content), rows on disk before close, a full disk at open and mid-recording, and what it
// writes read back whole by readRecording. Reading hand-written and hostile files:
// tst_recordingreader.
#include "recordingfiles.h"
#include "telemetry/recordingformat.h"
#include "telemetry/recordingreader.h"
#include "telemetry/recordingwriter.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <csignal>
#include <limits>
#include <sys/resource.h>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

QJsonObject readJson(const QString &path)
{
    return QJsonDocument::fromJson(readAll(path)).object();
}

//! The header the writer writes.
const QByteArray kWrittenHeader = "t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags,"
                                  "tau_fx,tau_pc,pc_reserve,event\n";

} // namespace

class TestRecordingWriter : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void columns();
    void metadataPathBesideCsv_data();
    void metadataPathBesideCsv();
    void headerAndRows();
    void eventsAreQuoted();
    void jsonContent();
    void flushPutsRowsOnDiskWithoutClose();
    void fullDiskAtOpen();
    void writeErrorMidRecording();
    void roundTrip();
    void passivityColumnsAndMetadataRoundTrip();
};

void TestRecordingWriter::columns()
{
    QCOMPARE(recordingColumns().join(u','),
             QStringLiteral(
                 "t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags,tau_fx,tau_pc,"
                 "pc_reserve,event"));
}

void TestRecordingWriter::metadataPathBesideCsv_data()
{
    QTest::addColumn<QString>("csv");
    QTest::addColumn<QString>("json");
    QTest::newRow("csv suffix") << "/tmp/a/run.csv"
                                << "/tmp/a/run.json";
    QTest::newRow("upper-case suffix") << "/tmp/a/run.CSV"
                                       << "/tmp/a/run.json";
    QTest::newRow("dots in name") << "/tmp/a/run.1.csv"
                                  << "/tmp/a/run.1.json";
    QTest::newRow("no suffix") << "/tmp/a/run"
                               << "/tmp/a/run.json";
}

void TestRecordingWriter::metadataPathBesideCsv()
{
    QFETCH(QString, csv);
    QFETCH(QString, json);
    QCOMPARE(recordingMetadataPath(csv), json);
}

void TestRecordingWriter::headerAndRows()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("r.csv"));
    RecordingWriter rec;
    QVERIFY2(rec.open(csv, metadata()), qPrintable(rec.error()));
    QVERIFY(rec.isOpen());
    Sample a = sample(0.001);
    Sample b = sample(1234.567891);
    b.omega = kNaN; // legacy: not measured
    b.tau = kNaN;
    b.flags = 0;
    b.v_ref = -1e-7;
    b.tau_fx = kNaN; // a device without effects
    QVERIFY(rec.append({a, b}));
    rec.close();
    QVERIFY(!rec.isOpen());
    const QByteArray text = readAll(csv);
    QCOMPARE(text, QByteArray(kWrittenHeader +
                              "0.001,0.05,0.5,-0.01,-0.02,0,-0.02,0.025,0.3333333333333333,258,0,"
                              "0,0,\n"
                              "1234.567891,0.05,,,-0.02,0,-0.02,-1e-07,0.3333333333333333,0,,0,"
                              "0,\n"));
    QCOMPARE(rec.status().samples, quint64(2));
    QCOMPARE(rec.status().bytes, qint64(text.size()));
    QCOMPARE(rec.status().seconds, 1234.567891 - 0.001);
    rec.close(); // twice is fine
}

void TestRecordingWriter::eventsAreQuoted()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("e.csv"));
    RecordingWriter rec;
    QVERIFY(rec.open(csv, metadata()));
    QVERIFY(rec.append({sample(0)}));
    rec.addEvent(QStringLiteral("K_max 0.4 → 0.6"));
    rec.addEvent(QStringLiteral("note \"soft\", then\nmore"));
    QVERIFY(rec.append({sample(0.001), sample(0.002)}));
    rec.close();
    const QList<QByteArray> lines = readAll(csv).split('\n');
    QCOMPARE(lines.size(), 5); // header, 3 rows, empty after the last '\n'
    QVERIFY(lines[1].endsWith(",258,0,0,0,"));
    QCOMPARE(lines[2].mid(lines[2].indexOf(",258,0,0,0,") + 11),
             QStringLiteral("\"K_max 0.4 → 0.6; note \"\"soft\"\", then more\"").toUtf8());
    QVERIFY(lines[3].endsWith(",258,0,0,0,"));
}

void TestRecordingWriter::jsonContent()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("j.csv"));
    const QString json = dir.filePath(QStringLiteral("j.json"));
    RecordingWriter rec;
    QVERIFY(rec.open(csv, metadata()));
    QJsonObject o = readJson(json);
    QCOMPARE(o.value(u"format").toString(), QStringLiteral("hatpic-recording"));
    QCOMPARE(o.value(u"version").toInt(), 1);
    QCOMPARE(o.value(u"closed").toBool(true), false);
    QCOMPARE(o.value(u"start").toString(), QStringLiteral("2024-05-17T09:30:15.250Z"));

    QVERIFY(rec.append({sample(0.5)}));
    rec.addEvent(QStringLiteral("v_max 1 → 2"));
    QVERIFY(rec.append({sample(0.75)}));
    QVERIFY(rec.flush()); // events changed: the metadata is rewritten
    o = readJson(json);
    QCOMPARE(o.value(u"events").toArray().size(), 1);
    rec.close();

    o = readJson(json);
    QCOMPARE(o.value(u"closed").toBool(), true);
    QCOMPARE(o.value(u"source").toString(), QStringLiteral("tst_recorder"));
    QCOMPARE(o.value(u"csv").toString(), QStringLiteral("j.csv"));
    QCOMPARE(o.value(u"protocol").toString(), QStringLiteral("v2"));
    QCOMPARE(o.value(u"samples").toInt(), 2);
    QCOMPARE(o.value(u"duration_s").toDouble(), 0.25);
    const QJsonObject device = o.value(u"device").toObject();
    QCOMPARE(device.value(u"port").toString(), QStringLiteral("/dev/ttyUSB0"));
    QCOMPARE(device.value(u"baud").toInt(), 921600);
    QCOMPARE(device.value(u"firmware").toString(), QStringLiteral("fw \"1.0\""));
    QCOMPARE(device.value(u"device_id").toDouble(), double(0x53494D31));
    const QJsonObject params = o.value(u"parameters").toObject();
    QCOMPARE(params.value(u"device").toObject().value(u"K_max").toDouble(), 0.6);
    QCOMPARE(params.value(u"device").toObject().value(u"D_adm").toDouble(), 1e-4);
    QCOMPARE(params.value(u"host").toObject().value(u"mode").toString(),
             QStringLiteral("rotation"));
    QCOMPARE(params.value(u"host").toObject().value(u"v_max").toDouble(), 2.0);
    const QJsonObject event = o.value(u"events").toArray().first().toObject();
    QCOMPARE(event.value(u"t_s").toDouble(), 0.75);
    QCOMPARE(event.value(u"text").toString(), QStringLiteral("v_max 1 → 2"));
    // Key order is the documented one, for people reading the file.
    const QByteArray text = readAll(json);
    QVERIFY(text.startsWith("{\n  \"format\": \"hatpic-recording\",\n  \"version\": 1,\n"));
}

void TestRecordingWriter::flushPutsRowsOnDiskWithoutClose()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("f.csv"));
    RecordingWriter rec;
    QVERIFY(rec.open(csv, metadata()));
    QCOMPARE(readAll(csv), kWrittenHeader); // the header is on disk at once
    QVERIFY(rec.append({sample(0.001)}));
    QCOMPARE(readAll(csv), kWrittenHeader); // rows wait for the next flush…
    QVERIFY(rec.flush());
    QVERIFY(readAll(csv).startsWith(
        QByteArray(kWrittenHeader + "0.001,"))); // …and are there without close()
    QVERIFY(rec.isOpen());
    // A large batch goes out without waiting for the flush.
    SampleBatch many;
    for (int i = 0; i < 5000; ++i)
        many.append(sample(0.002 + i * 1e-3));
    QVERIFY(rec.append(many));
    QVERIFY(readAll(csv).size() > 200 * 1024);
}

void TestRecordingWriter::fullDiskAtOpen()
{
    // /dev/full is not a file a recording may use (issue 10 #9); a really full disk is in
    // tst_recorderlimits (diskFullAtOpenChangesNothing, on a tmpfs).
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("full.csv"));
    QVERIFY(QFile::link(QStringLiteral("/dev/full"), csv));
    RecordingWriter rec;
    QVERIFY(!rec.open(csv, metadata()));
    QVERIFY(!rec.isOpen());
    QVERIFY2(rec.error().contains(csv) && rec.error().contains(u"not a regular file"),
             qPrintable(rec.error()));
    QCOMPARE(rec.status().error, rec.error());
    QVERIFY(!rec.status().active);
    QVERIFY(!rec.append({sample(0)}));
}

void TestRecordingWriter::writeErrorMidRecording()
{
    // A file-size limit makes writes fail part-way (EFBIG), as a full disk would.
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("limited.csv"));
    struct rlimit saved = {};
    QCOMPARE(::getrlimit(RLIMIT_FSIZE, &saved), 0);
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    struct rlimit limited = saved;
    limited.rlim_cur = 64 * 1024;
    QCOMPARE(::setrlimit(RLIMIT_FSIZE, &limited), 0);

    RecordingWriter rec;
    const bool opened = rec.open(csv, metadata());
    bool failed = false;
    for (int batch = 0; opened && batch < 100 && !failed; ++batch) {
        SampleBatch b;
        for (int i = 0; i < 64; ++i)
            b.append(sample(batch * 0.064 + i * 1e-3));
        failed = !rec.append(b) || !rec.flush();
    }
    const QString error = rec.error();
    const bool openAfter = rec.isOpen();
    rec.close();
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previousHandler);

    QVERIFY(opened);
    QVERIFY(failed);
    QVERIFY(!openAfter);
    QVERIFY2(error.contains(u"File too large") && error.contains(csv), qPrintable(error));
    // What was written stays readable; the metadata says why it ended.
    const RecordingReadResult r = readRecording(csv);
    QVERIFY2(r.recording, qPrintable(r.error));
    QVERIFY(r.recording->samples.size() > 100);
    const QJsonObject o = readJson(recordingMetadataPath(csv));
    QCOMPARE(o.value(u"closed").toBool(), true);
    QVERIFY(o.value(u"error").toString().contains(u"File too large"));
}

void TestRecordingWriter::roundTrip()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("rt.csv"));
    // The count can be raised: HATPIC_ROUNDTRIP_SAMPLES=1000000.
    const int count = qEnvironmentVariableIsSet("HATPIC_ROUNDTRIP_SAMPLES")
                          ? qEnvironmentVariableIntValue("HATPIC_ROUNDTRIP_SAMPLES")
                          : 20000;
    QRandomGenerator rng(42);
    auto f32 = [&](double scale) { return double(float((rng.generateDouble() - 0.5) * scale)); };
    SampleBatch written;
    double t = 0;
    for (int i = 0; i < count; ++i) {
        Sample s;
        t += 1e-3;
        s.t_s = std::round(t * 1e6) * 1e-6; // the session clock counts whole µs
        s.theta = f32(6);
        s.omega = i % 7 ? f32(40) : kNaN;
        s.tau = i % 7 ? f32(1) : kNaN;
        s.tau_rec = f32(1);
        s.tau_ext = f32(1);
        s.tau_total = std::clamp(s.tau_rec + s.tau_ext, -0.44, 0.44); // double arithmetic
        s.v_ref = (rng.generateDouble() - 0.5) * 2;
        s.p_ref = (rng.generateDouble() - 0.5) * 1e3;
        s.flags = static_cast<quint16>(rng.bounded(0x400));
        written.append(s);
    }
    RecordingWriter rec;
    QVERIFY(rec.open(csv, metadata()));
    QList<RecordingEvent> events;
    for (int i = 0; i < count; i += 64) {
        if (i % 640 == 0 && i > 0) {
            const QString text = u"event " % QString::number(i) % u", \"quoted\"";
            rec.addEvent(text);
            events.append({written[i].t_s, text});
        }
        QVERIFY(rec.append(written.mid(i, 64)));
    }
    rec.close();

    const RecordingReadResult r = readRecording(csv);
    QVERIFY2(r.recording, qPrintable(r.error));
    QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warnings.join(u'\n')));
    const Recording &back = *r.recording;
    QVERIFY(back.hasMetadata);
    QCOMPARE(back.metadata.start, metadata().start);
    QCOMPARE(back.metadata.source, metadata().source);
    QCOMPARE(back.metadata.params, metadata().params);
    QCOMPARE(back.metadata.host, metadata().host);
    QCOMPARE(back.metadata.device.firmware, metadata().device.firmware);
    QCOMPARE(back.metadata.device.deviceId, metadata().device.deviceId);
    QCOMPARE(back.samples.size(), written.size());
    auto same = [](double a, double b, bool asFloat) {
        if (std::isnan(a) || std::isnan(b))
            return std::isnan(a) && std::isnan(b);
        return asFloat ? float(a) == float(b) : a == b;
    };
    for (qsizetype i = 0; i < written.size(); ++i) {
        const Sample &w = written[i];
        const Sample &b = back.samples[i];
        QVERIFY(same(w.t_s, b.t_s, false));
        // f32 telemetry is written with the float's shortest digits: exact as a float.
        QVERIFY(same(w.theta, b.theta, true));
        QVERIFY(same(w.omega, b.omega, true));
        QVERIFY(same(w.tau, b.tau, true));
        QVERIFY(same(w.tau_rec, b.tau_rec, true));
        QVERIFY(same(w.tau_ext, b.tau_ext, true));
        // Host-computed doubles are exact (unless they happen to be floats).
        QVERIFY(same(w.tau_total, b.tau_total, double(float(w.tau_total)) == w.tau_total));
        QVERIFY(same(w.v_ref, b.v_ref, false));
        QVERIFY(same(w.p_ref, b.p_ref, false));
        QCOMPARE(b.flags, w.flags);
    }
    QCOMPARE(back.events.size(), events.size());
    for (qsizetype i = 0; i < events.size(); ++i) {
        QCOMPARE(back.events[i].t_s, events[i].t_s);
        QCOMPARE(back.events[i].text, events[i].text);
    }
}

void TestRecordingWriter::passivityColumnsAndMetadataRoundTrip()
{
    // τ_pc and R as the device sent them (floats), the controller's block in the metadata; a
    // device without the capability (NaN) writes empty fields that read back as NaN.
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("pc.csv"));
    RecordingMetadata meta = metadata();
    meta.passivity = PassivityParams{.pc_damping_max = 0.25, .pc_reserve_max = 0.0078125};
    RecordingWriter rec;
    QVERIFY2(rec.open(csv, meta), qPrintable(rec.error()));
    Sample damped = sample(0.001);
    damped.tau_pc = double(-0.0125f);
    damped.pc_reserve = 0;
    Sample unknown = sample(0.002);
    unknown.tau_pc = kNaN;
    unknown.pc_reserve = kNaN;
    QVERIFY(rec.append({damped, unknown}));
    rec.close();
    const QList<QByteArray> lines = readAll(csv).split('\n');
    QVERIFY2(lines[1].endsWith(",258,0,-0.0125,0,"), lines[1].constData());
    QVERIFY2(lines[2].endsWith(",258,0,,,"), lines[2].constData());
    const QJsonObject passivity = readJson(dir.filePath(QStringLiteral("pc.json")))
                                      .value(u"parameters")
                                      .toObject()
                                      .value(u"passivity")
                                      .toObject();
    QCOMPARE(passivity.value(u"pc_damping_max").toDouble(), 0.25);

    const RecordingReadResult r = readRecording(csv);
    QVERIFY2(r.recording, qPrintable(r.error));
    QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warnings.join(u'\n')));
    const QList<Sample> &rows = r.recording->samples;
    QCOMPARE(rows.size(), 2);
    QCOMPARE(float(rows[0].tau_pc), -0.0125f); // the float's shortest decimal, read back
    QCOMPARE(rows[0].pc_reserve, 0.0);
    QVERIFY(std::isnan(rows[1].tau_pc) && std::isnan(rows[1].pc_reserve));
    QVERIFY(r.recording->metadata.passivity);
    QVERIFY(*r.recording->metadata.passivity == meta.passivity);
    // Older metadata has no block: none is claimed.
    const RecordingReadResult old =
        parseRecording(kHeader + "0,1,,,,,,,,0,\n", R"({"format": "hatpic-recording",
            "version": 1, "parameters": {}})",
                       QStringLiteral("old.csv"));
    QVERIFY2(old.recording, qPrintable(old.error));
    QVERIFY(!old.recording->metadata.passivity);
    QVERIFY(std::isnan(old.recording->samples.first().tau_pc));
    const QString said = old.warnings.join(u'\n'); // of the missing parameters, not of these
    QVERIFY2(!said.contains(u"passivity"_s) && !said.contains(u"tau_pc"_s) &&
                 !said.contains(u"pc_reserve"_s),
             qPrintable(said));
}

QTEST_GUILESS_MAIN(TestRecordingWriter)
#include "tst_recordingwriter.moc"
