// readRecording (parsing a recording back): hand-written CSV read, malformed and oversized files
// refused with a reason, broken or hostile metadata only a warning, many events read in bounded
// time, mutated files never crash it, bytes parsed like the file, the metadata's parameters read
// as a profile's are. Writing: tst_recordingwriter.
#include "recordingfiles.h"
#include "telemetry/recordingformat.h"
#include "telemetry/recordingreader.h"
#include "telemetry/recordingwriter.h"

#include <QFile>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {} // namespace

class TestRecordingReader : public QObject
{
    Q_OBJECT

private Q_SLOTS:
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
};

void TestRecordingReader::readsHandWrittenCsv_data()
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

void TestRecordingReader::readsHandWrittenCsv()
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

void TestRecordingReader::refusesMalformedCsv_data()
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

void TestRecordingReader::refusesMalformedCsv()
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

void TestRecordingReader::refusesOversizedFile()
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

void TestRecordingReader::brokenMetadataIsAWarning()
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

void TestRecordingReader::hostileMetadataIsAWarning_data()
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

void TestRecordingReader::hostileMetadataIsAWarning()
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

void TestRecordingReader::manyMetadataEventsReadInBoundedTime()
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

void TestRecordingReader::neverCrashesOnMutatedFiles()
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

void TestRecordingReader::parseFromBytesReadsLikeTheFile()
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

void TestRecordingReader::metadataParametersReadAsAProfilesAre()
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

QTEST_GUILESS_MAIN(TestRecordingReader)
#include "tst_recordingreader.moc"
