// Recordings of a multi-axis device (the IMU branch's board): the further axes' columns and the
// tilt's, written and read back; a single knob's files keep their columns.
#include "recordingfiles.h"
#include "telemetry/recording.h"
#include "telemetry/recordingreader.h"
#include "telemetry/samplecolumns.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>
#include <memory>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

RecordingMetadata fourAxes()
{
    RecordingMetadata m = metadata();
    m.device.protocol = WireProtocol::Legacy;
    m.device.axes = 4;
    m.device.tilt = true;
    return m;
}

//! A sample whose every further-axis value is its own: axis n, quantity j → n + j/10 + t.
Sample fourAxisSample(double t, int axes = 4)
{
    Sample s = sample(t);
    auto board = std::make_shared<BoardSample>();
    board->axes = axes;
    for (std::size_t k = 0; k < board->more.size(); ++k) {
        for (std::size_t j = 0; j < kAxisColumns.size(); ++j)
            board->more[k].*kAxisColumns[j].value = double(k + 2) + double(j) / 10 + t;
    }
    board->more[2].omega = kNaN; // unknown, as the legacy frames leave it
    board->roll = 0.25 + t;
    board->pitch = -0.125;
    s.board = std::move(board);
    return s;
}

QJsonObject readJson(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

} // namespace

class TestRecordingAxes : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void extraColumnsAreNamedPerAxis()
    {
        QVERIFY(extraSampleColumns(1, false).isEmpty());
        QCOMPARE(extraSampleColumns(1, true), (QList<QByteArray>{"roll", "pitch"}));
        const QList<QByteArray> four = extraSampleColumns(4, true);
        QCOMPARE(four.size(), 3 * 8 + 2);
        QCOMPARE(four.first(), QByteArray("theta_2"));
        QCOMPARE(four[8], QByteArray("theta_3"));
        QCOMPARE(four[23], QByteArray("p_ref_4"));
        QCOMPARE(four.last(), QByteArray("pitch"));
        QCOMPARE(extraSampleColumns(9, false).size(), 3 * 8); // at most kMaxAxes
        QCOMPARE(recordingColumns(4, true).last(), u"event"_s);
        QCOMPARE(recordingColumns(4, true).size(), recordingColumns().size() + 26);
    }

    void fieldsFollowTheColumns()
    {
        const Sample s = fourAxisSample(0, 2); // fewer axes than the file: the rest are empty
        QByteArray row;
        appendExtraCsvFields(row, s, 3, true);
        const QList<QByteArray> fields = row.mid(1).split(',');
        QCOMPARE(fields.size(), 2 * 8 + 2);
        QCOMPARE(fields[0], QByteArray("2"));   // theta_2
        QCOMPARE(fields[1], QByteArray("2.1")); // omega_2
        QVERIFY(fields[8].isEmpty());           // theta_3: the sample has no axis 3
        QCOMPARE(fields[16], QByteArray("0.25"));
        QCOMPARE(fields[17], QByteArray("-0.125"));
        QByteArray none;
        appendExtraCsvFields(none, s, 1, false);
        QVERIFY(none.isEmpty());
    }

    void fourAxesRoundTrip()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath(u"imu.csv"_s);
        RecordingWriter writer;
        QVERIFY2(writer.open(csv, fourAxes()), qPrintable(writer.error()));
        SampleBatch written;
        for (int i = 0; i < 50; ++i)
            written.append(fourAxisSample(i * 0.2));
        QVERIFY(writer.append(written));
        writer.close();

        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray header = file.readLine().trimmed();
        QCOMPARE(header, recordingColumns(4, true).join(u',').toUtf8());
        QVERIFY(header.contains(",pc_reserve,theta_2,omega_2,") && header.endsWith(",pitch,event"));
        const QJsonObject device = readJson(recordingMetadataPath(csv)).value(u"device").toObject();
        QCOMPARE(device.value(u"axes").toInt(), 4);
        QCOMPARE(device.value(u"tilt").toBool(), true);

        const RecordingReadResult r = readRecording(csv);
        QVERIFY2(r.recording, qPrintable(r.error));
        QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warnings.join(u'\n')));
        QCOMPARE(r.recording->metadata.device.axes, quint8(4));
        QVERIFY(r.recording->metadata.device.tilt);
        QCOMPARE(r.recording->samples.size(), written.size());
        for (qsizetype i = 0; i < written.size(); ++i) {
            const Sample &in = written[i];
            const Sample &out = r.recording->samples[i];
            QCOMPARE(out.axes(), 4);
            QCOMPARE(float(out.theta), float(in.theta)); // knob 1: as any recording writes it
            for (int n = 2; n <= 4; ++n) {
                for (const AxisColumn &column : kAxisColumns) {
                    const double a = in.axis(n)->*column.value;
                    const double b = out.axis(n)->*column.value;
                    QVERIFY2((std::isnan(a) && std::isnan(b)) || a == b,
                             qPrintable(u"axis %1 %2"_s.arg(n).arg(QString::fromLatin1(
                                 column.name.data(), qsizetype(column.name.size())))));
                }
            }
            QCOMPARE(out.roll(), in.roll());
            QCOMPARE(out.pitch(), in.pitch());
        }
    }

    void aSingleKnobKeepsItsFile()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath(u"one.csv"_s);
        RecordingWriter writer;
        QVERIFY(writer.open(csv, metadata()));
        QVERIFY(writer.append({sample(0), sample(0.001)}));
        writer.close();
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readLine().trimmed(), recordingColumns().join(u',').toUtf8());
        const QJsonObject device = readJson(recordingMetadataPath(csv)).value(u"device").toObject();
        QVERIFY(!device.contains(u"axes") && !device.contains(u"tilt"));
        const RecordingReadResult r = readRecording(csv);
        QVERIFY(r.recording);
        QCOMPARE(r.recording->metadata.device.axes, quint8(1));
        QCOMPARE(r.recording->samples.last().axes(), 1);
        QVERIFY(!r.recording->samples.last().board); // a single knob's sample carries no more
        QVERIFY(std::isnan(r.recording->samples.last().roll()));
    }

    void readerTakesAFileWithSomeAxesOnly()
    {
        // Written by hand or by another tool: axis 2's angle and the roll only.
        QTemporaryDir dir;
        const QString csv = dir.filePath(u"some.csv"_s);
        QVERIFY(writeFile(csv, "t_s,theta,theta_2,roll,event\n0,0.1,0.2,0.3,\n0.2,0.1,x,0.3,\n"));
        RecordingReadResult r = readRecording(csv);
        QVERIFY(!r.recording);
        QVERIFY2(r.error.contains(u"line 3: column theta_2: \"x\" is not a number"_s),
                 qPrintable(r.error));
        QVERIFY(writeFile(csv, "t_s,theta,theta_2,roll,theta_2\n0,0.1,0.2,0.3,0.2\n"));
        r = readRecording(csv);
        QVERIFY2(r.error.contains(u"\"theta_2\" appears twice"_s), qPrintable(r.error));
        QVERIFY(writeFile(csv, "t_s,theta,theta_2,roll,event\n0,0.1,0.2,0.3,\n"));
        r = readRecording(csv);
        QVERIFY2(r.recording, qPrintable(r.error));
        const Sample s = r.recording->samples.first();
        QCOMPARE(s.axes(), 2);
        QCOMPARE(s.axis(2)->theta, 0.2);
        QVERIFY(std::isnan(s.axis(2)->omega));
        QVERIFY(!s.axis(3));
        QCOMPARE(s.roll(), 0.3);
        QVERIFY(std::isnan(s.pitch()));
    }
};

QTEST_GUILESS_MAIN(TestRecordingAxes)
#include "tst_recordingaxes.moc"
