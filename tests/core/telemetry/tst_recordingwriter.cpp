// RecordingWriter (CSV + JSON writing) and readRecording (parsing back).
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
using namespace Qt::StringLiterals;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

RecordingMetadata metadata()
{
    RecordingMetadata m;
    m.start = QDateTime(QDate(2024, 5, 17), QTime(9, 30, 15, 250), Qt::UTC);
    m.device.protocol = WireProtocol::V2;
    m.device.port = QStringLiteral("/dev/ttyUSB0");
    m.device.baud = 921600;
    m.device.protocolVersion = 2;
    m.device.maxStreamHz = 1000;
    m.device.deviceId = 0x53494D31;
    m.device.tauLimit = 0.44;
    m.device.firmware = QStringLiteral("fw \"1.0\"");
    m.params.K_max = 0.6;
    m.host.v_max = 2;
    m.host.mode = ReferenceMode::Rotation;
    m.source = QStringLiteral("tst_recorder");
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
    s.tau_ext = 0;
    s.tau_total = double(-0.02f);
    s.v_ref = 0.025;
    s.p_ref = 1.0 / 3.0;
    s.flags = 0x0102;
    return s;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QJsonObject readJson(const QString &path)
{
    return QJsonDocument::fromJson(readAll(path)).object();
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

//! The header the writer writes.
const QByteArray kWrittenHeader = "t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags,"
                                  "tau_fx,tau_pc,pc_reserve,event\n";
//! The header of a recording made before tau_fx, tau_pc and pc_reserve existed: the hand-written
//! files below use it, so they also check that such recordings still read (without a word about
//! those).
const QByteArray kHeader =
    "t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags,event\n";

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
    void readsHandWrittenCsv_data();
    void readsHandWrittenCsv();
    void refusesMalformedCsv_data();
    void refusesMalformedCsv();
    void refusesOversizedFile();
    void brokenMetadataIsAWarning();
    void hostileMetadataIsAWarning_data();
    void hostileMetadataIsAWarning();
    void manyMetadataEventsReadInBoundedTime();
    void neverCrashesOnMutatedFiles();
    void parseFromBytesReadsLikeTheFile();
    void metadataParametersReadAsAProfilesAre();
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

void TestRecordingWriter::readsHandWrittenCsv_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<int>("samples");
    QTest::addColumn<QString>("warning");
    QTest::newRow("header only") << kHeader << 0 << QString();
    QTest::newRow("CRLF line ends and BOM")
        << QByteArray("\xEF\xBB\xBF" + QByteArray(kHeader).replace("\n", "\r\n") +
                      "0,0.1,,,,,,,,0,\r\n0.001,0.2,,,,,,,,0,\"x\"\r\n")
        << 2 << QString();
    QTest::newRow("no event column") << QByteArray("t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,"
                                                   "v_ref,p_ref,flags\n0,1,2,3,4,5,6,7,8,9\n")
                                     << 1 << QString();
    QTest::newRow("only t_s and theta")
        << QByteArray("t_s,theta\n0,1\n1,2\n") << 2 << QStringLiteral("column \"omega\" missing");
    QTest::newRow("extra column") << QByteArray("t_s,theta,colour\n0,1,red\n") << 1
                                  << QStringLiteral("unknown column");
    QTest::newRow("blank lines skipped")
        << QByteArray(kHeader + "\n0,1,,,,,,,,0,\n\n") << 1 << QString();
    QTest::newRow("cut-off last line") << QByteArray(kHeader + "0,1,,,,,,,,0,\n0.001,0.5,0.") << 1
                                       << QStringLiteral("line 3: incomplete last line");
    QTest::newRow("cut-off inside a quote")
        << QByteArray(kHeader + "0,1,,,,,,,,0,\n0.001,0.5,,,,,,,,0,\"K_max") << 1
        << QStringLiteral("incomplete last line");
    QTest::newRow("time goes back") << QByteArray(kHeader + "1,1,,,,,,,,0,\n0.5,1,,,,,,,,0,\n") << 2
                                    << QStringLiteral("line 3: t_s goes back");
    QTest::newRow("nan and inf words")
        << QByteArray(kHeader + "0,nan,inf,-inf,,,,,,0,\n") << 1 << QString();
    QTest::newRow("thousands of unknown columns: warnings bounded")
        << QByteArray("t_s,theta" + QByteArray(",x").repeated(4000) + "\n0,1" +
                      QByteArray(",").repeated(4000) + "\n")
        << 1 << QStringLiteral("(further warnings left out)");
    QTest::newRow("header only without line end") << kHeader.chopped(1) << 0 << QString();
    QTest::newRow("CR LF blank lines")
        << QByteArray(kHeader + "\r\n\r\n0,1,,,,,,,,0,\r\n\r\n") << 1 << QString();
}

void TestRecordingWriter::readsHandWrittenCsv()
{
    QFETCH(QByteArray, content);
    QFETCH(int, samples);
    QFETCH(QString, warning);
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("h.csv"));
    QVERIFY(writeFile(csv, content));
    const RecordingReadResult r = readRecording(csv);
    QVERIFY2(r.recording, qPrintable(r.error));
    QCOMPARE(r.recording->samples.size(), samples);
    QVERIFY(!r.recording->hasMetadata); // no .json beside it (hatpicctl stream --csv > file)
    if (warning.isEmpty()) {
        QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warnings.join(u'\n')));
    } else {
        QVERIFY2(r.warnings.join(u'\n').contains(warning), qPrintable(r.warnings.join(u'\n')));
    }
}

void TestRecordingWriter::refusesMalformedCsv_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("error");
    QTest::newRow("empty file") << QByteArray() << QStringLiteral("empty: no header row");
    QTest::newRow("not a recording")
        << QByteArray("name,age\nbob,3\n") << QStringLiteral("line 1: not a HATPIC recording");
    QTest::newRow("duplicate column") << QByteArray("t_s,theta,theta\n")
                                      << QStringLiteral("line 1: column \"theta\" appears twice");
    QTest::newRow("too few fields") << QByteArray(kHeader + "0,1,,,,,,,,0,\n0,1,2\n")
                                    << QStringLiteral("line 3: expected 11 fields, found 3");
    QTest::newRow("too many fields")
        << QByteArray(kHeader + "0,1,,,,,,,,0,,,\n") << QStringLiteral("line 2: expected 11");
    QTest::newRow("not a number") << QByteArray(kHeader + "0,1,,,,,,,,0,\n0.1,abc,,,,,,,,0,\n")
                                  << QStringLiteral(
                                         "line 3: column theta: \"abc\" is not a number");
    QTest::newRow("number with trailing text")
        << QByteArray(kHeader + "0,1.5rad,,,,,,,,0,\n") << QStringLiteral("line 2: column theta");
    QTest::newRow("empty t_s") << QByteArray(kHeader + ",1,,,,,,,,0,\n")
                               << QStringLiteral("line 2: t_s must be a finite number");
    QTest::newRow("flags out of range")
        << QByteArray(kHeader + "0,1,,,,,,,,70000,\n") << QStringLiteral("line 2: column flags");
    QTest::newRow("negative flags")
        << QByteArray(kHeader + "0,1,,,,,,,,-1,\n") << QStringLiteral("line 2: column flags");
    QTest::newRow("unclosed quote mid-file")
        << QByteArray(kHeader + "0,1,,,,,,,,0,\"abc\n0.1,1,,,,,,,,0,\n")
        << QStringLiteral("line 2: a quoted field is not closed");
    QTest::newRow("text after quote") << QByteArray(kHeader + "0,1,,,,,,,,0,\"a\"b\n")
                                      << QStringLiteral("line 2: text follows a closing quote");
    QTest::newRow("over-long line")
        << QByteArray(kHeader + QByteArray(20000, '1') + "\n0,1,,,,,,,,0,\n")
        << QStringLiteral("line 2: longer than");
    QByteArray binary;
    for (int i = 0; i < 3000; ++i)
        binary.append(char((i * 37) & 0xFF));
    QTest::newRow("binary data") << binary << QStringLiteral("line ");
    QTest::newRow("over-long last line without line end")
        << QByteArray(kHeader + QByteArray(20000, '1')) << QStringLiteral("line 2: longer than");
    QTest::newRow("over-long header")
        << QByteArray("t_s,theta" + QByteArray(",x").repeated(5000) + "\n")
        << QStringLiteral("line 1: longer than");
    QTest::newRow("unclosed quote in header")
        << QByteArray("\"t_s,theta\n0,1\n") << QStringLiteral("line 1: a quoted field");
    QTest::newRow("NUL bytes in a number")
        << QByteArray(kHeader + QByteArray("0,1\0\0,,,,,,,,0,\n", 17))
        << QStringLiteral("line 2: column theta");
    QTest::newRow("BOM only") << QByteArray("\xEF\xBB\xBF") << QStringLiteral("no header row");
}

void TestRecordingWriter::refusesMalformedCsv()
{
    QFETCH(QByteArray, content);
    QFETCH(QString, error);
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("m.csv"));
    QVERIFY(writeFile(csv, content));
    const RecordingReadResult r = readRecording(csv);
    QVERIFY(!r.recording);
    QVERIFY2(r.error.contains(error), qPrintable(r.error));
}

void TestRecordingWriter::refusesOversizedFile()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("big.csv"));
    QVERIFY(writeFile(csv, QByteArray(kHeader + "0,1,,,,,,,,0,\n")));
    const RecordingReadResult r = readRecording(csv, 20);
    QVERIFY(!r.recording);
    QVERIFY2(r.error.contains(u"more than the limit of 20 bytes"), qPrintable(r.error));
    const RecordingReadResult missing = readRecording(dir.filePath(QStringLiteral("nope.csv")));
    QVERIFY(!missing.recording);
    QVERIFY(missing.error.contains(u"Cannot open"));
}

void TestRecordingWriter::brokenMetadataIsAWarning()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("b.csv"));
    QVERIFY(writeFile(csv, QByteArray(kHeader + "0,1,,,,,,,,0,\n")));
    QVERIFY(writeFile(recordingMetadataPath(csv), "{ \"format\": \"hatpic-recording\", "));
    const RecordingReadResult r = readRecording(csv);
    QVERIFY2(r.recording, qPrintable(r.error));
    QVERIFY(!r.recording->hasMetadata);
    QVERIFY2(r.warnings.join(u'\n').contains(u"not valid JSON"),
             qPrintable(r.warnings.join(u'\n')));
}

void TestRecordingWriter::hostileMetadataIsAWarning_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("warning");
    QByteArray binary;
    for (int i = 0; i < 4000; ++i)
        binary.append(char((i * 101 + 7) & 0xFF));
    QTest::newRow("binary junk") << binary << QStringLiteral("not valid JSON");
    QTest::newRow("array, not an object") << QByteArray("[1,2,3]") << QStringLiteral("not valid");
    QTest::newRow("deeply nested") << QByteArray(100000, '[') << QStringLiteral("not valid JSON");
    QTest::newRow("other format tag")
        << QByteArray("{\"format\": \"something-else\"}") << QStringLiteral("not HATPIC");
    QTest::newRow("over 16 MiB") << QByteArray(16 * 1024 * 1024 + 1, ' ')
                                 << QStringLiteral("too large");
}

void TestRecordingWriter::hostileMetadataIsAWarning()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, warning);
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("j.csv"));
    QVERIFY(writeFile(csv, QByteArray(kHeader + "0,1,,,,,,,,0,\n")));
    QVERIFY(writeFile(recordingMetadataPath(csv), json));
    const RecordingReadResult r = readRecording(csv);
    QVERIFY2(r.recording, qPrintable(r.error));
    QCOMPARE(r.recording->samples.size(), 1);
    QVERIFY(!r.recording->hasMetadata);
    QVERIFY2(r.warnings.join(u'\n').contains(warning), qPrintable(r.warnings.join(u'\n')));
}

void TestRecordingWriter::manyMetadataEventsReadInBoundedTime()
{
    // A .json under the size limit can list hundreds of thousands of events; merging them with
    // the CSV's events must not compare every pair (that took minutes).
    constexpr int kEvents = 300000;
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("e.csv"));
    QVERIFY(writeFile(csv, QByteArray(kHeader + "0,1,,,,,,,,0,\"e0\"\n")));
    QByteArray json = "{\"format\":\"hatpic-recording\",\"version\":1,\"events\":[";
    for (int i = 0; i < kEvents; ++i) {
        if (i > 0)
            json += ',';
        json +=
            "{\"t_s\":" + QByteArray::number(i) + ",\"text\":\"e" + QByteArray::number(i) + "\"}";
    }
    json += "]}";
    QVERIFY(json.size() < 16 * 1024 * 1024);
    QVERIFY(writeFile(recordingMetadataPath(csv), json));
    // No timing assertion (speed is for bench/): a merge that compared every pair would run
    // for many minutes and trip the suite's ctest timeout instead.
    const RecordingReadResult r = readRecording(csv);
    QVERIFY2(r.recording, qPrintable(r.error));
    QVERIFY(r.recording->hasMetadata);
    // "e0" at 0 s is in both: listed once. A replay holds at most kMaxReadEvents, and says so.
    QCOMPARE(r.recording->events.size(), recording::kMaxReadEvents);
    QCOMPARE(r.recording->events.last().text,
             u"e" + QString::number(recording::kMaxReadEvents - 1));
    QVERIFY2(r.warnings.constFirst().endsWith(u"events after the first 50000 are not shown: a "
                                              u"replay holds at most that many."),
             qPrintable(r.warnings.join(u'\n')));
}

void TestRecordingWriter::neverCrashesOnMutatedFiles()
{
    // Seeded mutations of a valid recording: every read ends in a recording or an error.
    // Raise the count with HATPIC_FUZZ_ROUNDS.
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("z.csv"));
    RecordingWriter rec;
    QVERIFY(rec.open(csv, metadata()));
    SampleBatch batch;
    for (int i = 0; i < 50; ++i)
        batch.append(sample(i * 1e-3));
    rec.addEvent(QStringLiteral("K_max 0.4 → 0.6"));
    QVERIFY(rec.append(batch));
    rec.close();
    const QByteArray original = readAll(csv);
    const int rounds = qEnvironmentVariableIsSet("HATPIC_FUZZ_ROUNDS")
                           ? qEnvironmentVariableIntValue("HATPIC_FUZZ_ROUNDS")
                           : 300;
    QRandomGenerator rng(1234);
    int accepted = 0;
    for (int round = 0; round < rounds; ++round) {
        QByteArray bytes = original;
        const int edits = 1 + int(rng.bounded(8));
        for (int e = 0; e < edits; ++e) {
            const int pos = int(rng.bounded(int(bytes.size())));
            switch (rng.bounded(3)) {
            case 0:
                bytes[pos] = char(rng.bounded(256));
                break;
            case 1:
                bytes.remove(pos, int(rng.bounded(20)));
                break;
            default:
                bytes.insert(pos, QByteArray(int(rng.bounded(5)), char(rng.bounded(256))));
            }
        }
        QVERIFY(writeFile(csv, bytes));
        const RecordingReadResult r = readRecording(csv);
        QVERIFY(r.recording.has_value() != !r.error.isEmpty());
        accepted += r.recording ? 1 : 0;
    }
    QVERIFY(accepted > 0 && accepted < rounds); // both outcomes were exercised
}

void TestRecordingWriter::parseFromBytesReadsLikeTheFile()
{
    // parseRecording (what fuzz_recording drives) is the reader readRecording uses: the same
    // bytes give the same recording, error and warnings, with and without the .json.
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("p.csv"));
    RecordingWriter rec;
    QVERIFY(rec.open(csv, metadata()));
    SampleBatch batch;
    for (int i = 0; i < 20; ++i)
        batch.append(sample(i * 1e-3));
    rec.addEvent(QStringLiteral("K_max 0.4 → 0.6"));
    QVERIFY(rec.append(batch));
    rec.close();
    const QByteArray good = readAll(csv);
    const QByteArray json = readAll(recordingMetadataPath(csv));
    const QByteArray cutOff = good + "0.5,1";
    const QByteArray bad = good + "1,2,3\n";
    for (const QByteArray &bytes : {good, cutOff, bad}) {
        for (const bool withJson : {true, false}) {
            QVERIFY(writeFile(csv, bytes));
            if (!withJson)
                QVERIFY(QFile::remove(recordingMetadataPath(csv)));
            const RecordingReadResult fromFile = readRecording(csv);
            const RecordingReadResult fromBytes =
                parseRecording(bytes, withJson ? std::optional(json) : std::nullopt, csv);
            QCOMPARE(fromBytes.error, fromFile.error);
            QCOMPARE(fromBytes.warnings, fromFile.warnings);
            QCOMPARE(fromBytes.recording.has_value(), fromFile.recording.has_value());
            if (fromFile.recording) {
                QCOMPARE(fromBytes.recording->hasMetadata, withJson);
                QCOMPARE(fromBytes.recording->samples.size(), fromFile.recording->samples.size());
                QCOMPARE(fromBytes.recording->events.size(), fromFile.recording->events.size());
                QCOMPARE(fromBytes.recording->metadata.source, fromFile.recording->metadata.source);
            }
            if (!withJson)
                QVERIFY(writeFile(recordingMetadataPath(csv), json));
        }
    }
}

void TestRecordingWriter::metadataParametersReadAsAProfilesAre()
{
    // parameters.device and parameters.host are read by the profile's code (paramsjson.h): a
    // field missing or not of its type keeps its default, with a warning naming it.
    const QByteArray csv = kHeader + "0,1,,,,,,,,0,\n";
    const QByteArray json = R"({"format": "hatpic-recording", "version": 1,
        "parameters": {
            "device": {"D_adm": 0.0002, "M_adm": 0.02, "K_min": "soft", "K_max": 0.5, "N": 0.1,
                       "Q_dz": 0.02},
            "host": {"mode": "rotation", "v_max": 3.0, "ref_deadzone": "yes", "tau_limit": 0.3}
        }})";
    const RecordingReadResult r = parseRecording(csv, json, QStringLiteral("m.csv"));
    QVERIFY2(r.recording, qPrintable(r.error));
    const RecordingMetadata &m = r.recording->metadata;
    QCOMPARE(m.params.D_adm, 0.0002);
    QCOMPARE(m.params.K_max, 0.5);
    QCOMPARE(m.params.K_min, DeviceParams{}.K_min);
    QCOMPARE(m.params.theta0, DeviceParams{}.theta0);
    QCOMPARE(m.host.mode, ReferenceMode::Rotation);
    QCOMPARE(m.host.v_max, 3.0);
    QCOMPARE(m.host.ref_deadzone, HostParams{}.ref_deadzone);
    QCOMPARE(m.host.tau_limit, 0.3);
    QCOMPARE(r.warnings,
             QStringList({u"./m.json: parameters.device.K_min: must be a number, got \"soft\"; the "
                          u"default is used."_s,
                          u"./m.json: parameters.device.theta0: missing, must be a number; the "
                          u"default is used."_s,
                          u"./m.json: parameters.host.ref_deadzone: must be true or false, got "
                          u"\"yes\"; the default is used."_s}));
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
