// The sample column table (samplecolumns.h): the header, the one row writer, the one number
// format, and the recording's writer and reader, which all read the table.
#include "telemetry/numbertext.h"
#include "telemetry/recordingreader.h"
#include "telemetry/recordingwriter.h"
#include "telemetry/samplecolumns.h"

#include <QFile>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace hatpic;

namespace {

QString nameOf(const SampleColumn &column)
{
    return QString::fromUtf8(column.name.data(), static_cast<qsizetype>(column.name.size()));
}

//! A sample whose every column holds its own value, so a column written or read in the wrong
//! place shows. Quantities are doubles that are not floats (double digits), flags 0x0102.
Sample distinctSample()
{
    Sample s;
    double v = 1.0 / 3.0;
    for (const SampleColumn &column : kSampleColumns) {
        if (!column.isFlags())
            s.*column.value = v;
        v += 1.0;
    }
    s.flags = 0x0102;
    return s;
}

} // namespace

class TestSampleColumns : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void tableIsWellFormed();
    void headerIsTheTable();
    void recordingColumnsAreTheTableAndEvent();
    void rowFollowsTheTable();
    void numberText_data();
    void numberText();
    void rowNumbersUseTheOneFormat();
    void recordingHeaderAndRowsAreTheTables();
    void readerFindsColumnsByTheirTableName();
};

void TestSampleColumns::tableIsWellFormed()
{
    QSet<QString> names;
    int flagsColumns = 0;
    for (const SampleColumn &column : kSampleColumns) {
        QVERIFY2(!column.name.empty() && !column.meaning.empty(), qPrintable(nameOf(column)));
        QCOMPARE(column.unit.empty(), column.isFlags()); // every quantity has its SI unit
        names.insert(nameOf(column));
        flagsColumns += column.isFlags() ? 1 : 0;
    }
    QCOMPARE(names.size(), qsizetype(kSampleColumns.size()));
    QCOMPARE(flagsColumns, 1);
    QCOMPARE(sampleColumnIndex("t_s"), std::size_t(0));
    QCOMPARE(sampleColumnIndex("p_ref"), kFirstQuantityColumn + kQuantityColumnCount - 1);
    QCOMPARE(sampleColumnIndex("no such column"), kSampleColumns.size());
    for (std::size_t i = 0; i < kQuantityColumnCount; ++i)
        QVERIFY(!kSampleColumns[kFirstQuantityColumn + i].isFlags());
}

void TestSampleColumns::headerIsTheTable()
{
    QStringList names;
    for (const SampleColumn &column : kSampleColumns)
        names << nameOf(column);
    QCOMPARE(QString::fromLatin1(sampleCsvHeader()), names.join(u','));
    // The documented header (docs/cli.md, docs/recording.md), in the order of today's files.
    QCOMPARE(sampleCsvHeader(),
             QByteArray("t_s,theta,omega,tau,tau_rec,tau_ext,tau_total,v_ref,p_ref,flags,tau_fx,"
                        "tau_pc,pc_reserve"));
}

void TestSampleColumns::recordingColumnsAreTheTableAndEvent()
{
    const QStringList columns = recordingColumns();
    QCOMPARE(columns.size(), qsizetype(kSampleColumns.size()) + 1);
    QCOMPARE(columns.mid(0, columns.size() - 1).join(u','), QString::fromLatin1(sampleCsvHeader()));
    QCOMPARE(columns.last(), QStringLiteral("event"));
}

void TestSampleColumns::rowFollowsTheTable()
{
    const Sample s = distinctSample();
    QByteArray row;
    appendSampleCsvRow(row, s);
    const QList<QByteArray> fields = row.split(',');
    QCOMPARE(fields.size(), qsizetype(kSampleColumns.size()));
    for (std::size_t i = 0; i < kSampleColumns.size(); ++i) {
        const SampleColumn &column = kSampleColumns[i];
        const QByteArray field = fields[static_cast<qsizetype>(i)];
        if (column.isFlags())
            QCOMPARE(field, QByteArray("258"));
        else
            QCOMPARE(field.toDouble(), s.*column.value);
    }
}

void TestSampleColumns::numberText_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("text");
    QTest::newRow("float: its shortest digits") << double(0.05f) << "0.05";
    QTest::newRow("float, negative") << double(-0.0061359233f) << "-0.0061359233";
    QTest::newRow("double: its shortest digits") << 1.0 / 3.0 << "0.3333333333333333";
    QTest::newRow("double near a float") << 0.05 << "0.05";
    QTest::newRow("whole number") << 258.0 << "258";
    QTest::newRow("small") << -1e-7 << "-1e-07";
    QTest::newRow("negative zero") << -0.0 << "0";
    QTest::newRow("nan") << std::numeric_limits<double>::quiet_NaN() << "nan";
    QTest::newRow("inf") << -std::numeric_limits<double>::infinity() << "-inf";
}

void TestSampleColumns::numberText()
{
    QFETCH(double, value);
    QFETCH(QString, text);
    QCOMPARE(compactNumberText(value), text);
    if (std::isfinite(value) && value != 0) {
        // Reads back as the value, or, for float digits, as the float it was.
        const double back = text.toDouble();
        QVERIFY(back == value || static_cast<float>(back) == static_cast<float>(value));
    }
}

void TestSampleColumns::rowNumbersUseTheOneFormat()
{
    Sample s;
    s.t_s = 1234.567891;
    s.theta = double(0.05f);
    s.omega = std::numeric_limits<double>::quiet_NaN(); // not carried: an empty field
    s.tau = -0.0;
    s.tau_rec = double(-0.02f);
    s.tau_ext = 0;
    s.tau_total = double(-0.02f);
    s.v_ref = -1e-7;
    s.p_ref = 1.0 / 3.0;
    s.flags = 0x0201;
    s.tau_fx = double(0.0625f);
    s.tau_pc = double(-0.0125f);
    s.pc_reserve = double(0.02f);
    QByteArray row;
    appendSampleCsvRow(row, s);
    QCOMPARE(row,
             QByteArray("1234.567891,0.05,,0,-0.02,0,-0.02,-1e-07,0.3333333333333333,513,0.0625,"
                        "-0.0125,0.02"));
    s.tau_fx = std::numeric_limits<double>::quiet_NaN(); // a device without effects
    s.tau_pc = std::numeric_limits<double>::quiet_NaN(); // …nor the passivity controller
    s.pc_reserve = std::numeric_limits<double>::quiet_NaN();
    row.clear();
    appendSampleCsvRow(row, s);
    QVERIFY(row.endsWith(",513,,,"));
}

void TestSampleColumns::recordingHeaderAndRowsAreTheTables()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("r.csv"));
    RecordingWriter writer;
    QVERIFY2(writer.open(csv, RecordingMetadata{}), qPrintable(writer.error()));
    const Sample s = distinctSample();
    QVERIFY(writer.append({s}));
    writer.close();
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QByteArray row;
    appendSampleCsvRow(row, s);
    QCOMPARE(file.readAll(), sampleCsvHeader() + ",event\n" + row + ",\n");
}

void TestSampleColumns::readerFindsColumnsByTheirTableName()
{
    // The columns in reverse order: the reader maps each by its name in the table.
    const Sample s = distinctSample();
    QByteArray row;
    appendSampleCsvRow(row, s);
    QList<QByteArray> names = sampleCsvHeader().split(',');
    QList<QByteArray> fields = row.split(',');
    std::reverse(names.begin(), names.end());
    std::reverse(fields.begin(), fields.end());
    const RecordingReadResult read =
        parseRecording(names.join(',') + '\n' + fields.join(',') + '\n', std::nullopt);
    QVERIFY2(read.recording, qPrintable(read.error));
    QVERIFY2(read.warnings.isEmpty(), qPrintable(read.warnings.join(u'\n')));
    QCOMPARE(read.recording->samples.size(), 1);
    const Sample back = read.recording->samples.first();
    for (const SampleColumn &column : kSampleColumns) {
        if (column.isFlags())
            QCOMPARE(back.flags, s.flags);
        else
            QCOMPARE(back.*column.value, s.*column.value);
    }
}

QTEST_GUILESS_MAIN(TestSampleColumns)
#include "tst_samplecolumns.moc"
