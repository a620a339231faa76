// SampleCsvWriter: the recording's columns, the visible range only, and a file readRecording
// accepts with the same values (NaN as an empty field).
#include "plots/samplebuffer.h"
#include "plots/samplecsvwriter.h"
#include "telemetry/recordingreader.h"
#include "telemetry/samplecolumns.h"

#include <QFile>

#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>

using namespace hatpic;

class TestSampleCsvWriter : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void rowsAreTheColumnTablesRows();
    void channelsAreTheTablesQuantities();
    void writesRangeThatReadsBack_data();
    void writesRangeThatReadsBack();
    void reportsUnwritablePath();
};

void TestSampleCsvWriter::rowsAreTheColumnTablesRows()
{
    // The export writes each row with the one row writer (the number format of recordings:
    // float digits for floats, −0 as 0, NaN empty), then an empty event.
    SampleBuffer buffer(3);
    Sample s;
    s.theta = double(0.05f);
    s.omega = std::numeric_limits<double>::quiet_NaN();
    s.tau = -0.0;
    s.p_ref = 1.0 / 3.0;
    s.flags = 0x0201;
    for (int i = 0; i < 3; ++i) {
        s.t_s = i * 0.001;
        // τ_fx, τ_pc and R from a device that sends them, then unknown (one that does not).
        const double unknown = std::numeric_limits<double>::quiet_NaN();
        s.tau_fx = i < 2 ? 0.0125 : unknown;
        s.tau_pc = i < 2 ? -0.0625 : unknown;
        s.pc_reserve = i < 2 ? 0.015625 : unknown; // no channel shows it: the buffer keeps it
        buffer.append(s);
    }
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rows.csv"));
    QCOMPARE(SampleCsvWriter::write(buffer, 0, 1, path), qsizetype(3));
    QByteArray expected = sampleCsvHeader() + ",event\n";
    for (qsizetype i = 0; i < buffer.size(); ++i) {
        appendSampleCsvRow(expected, buffer.sample(i));
        expected += ",\n";
    }
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    QCOMPARE(text, expected);
    // The buffer keeps tau_fx, tau_pc and pc_reserve: their values where the device sent them,
    // empty where it did not.
    QVERIFY(
        text.contains("\n0.001,0.05,,0,0,0,0,0,0.3333333333333333,513,0.0125,-0.0625,0.015625,\n"));
    QVERIFY(text.contains("\n0.002,0.05,,0,0,0,0,0,0.3333333333333333,513,,,,\n"));
}

void TestSampleCsvWriter::channelsAreTheTablesQuantities()
{
    // The plots' channels are the table's quantity columns, in order, then tau_fx and tau_pc
    // (after the flags), with their values.
    Sample s;
    double v = 0.5;
    for (const SampleColumn &column : kSampleColumns) {
        if (!column.isFlags())
            s.*column.value = v;
        v += 1;
    }
    for (Channel channel : kAllChannels) {
        if (!isSampleChannel(channel)) { // τ_fx's parts: computed, no column, not in a Sample
            QVERIFY(std::isnan(channelValue(s, channel)));
            continue;
        }
        const std::size_t column = channel == Channel::TauFx ? sampleColumnIndex("tau_fx")
                                   : channel == Channel::TauPc
                                       ? sampleColumnIndex("tau_pc")
                                       : kFirstQuantityColumn + std::size_t(channelIndex(channel));
        QVERIFY(channelColumn(channel).name == kSampleColumns[column].name);
        QCOMPARE(channelValue(s, channel), 0.5 + double(column));
    }
    QVERIFY(channelColumn(Channel::Theta).name == "theta");
    QVERIFY(channelColumn(Channel::PRef).name == "p_ref");
    QVERIFY(isAngleChannel(Channel::Omega));
    QVERIFY(!isAngleChannel(Channel::VRef));
}

void TestSampleCsvWriter::writesRangeThatReadsBack_data()
{
    QTest::addColumn<double>("t0");
    QTest::addColumn<double>("t1");
    QTest::addColumn<int>("rows");
    // 1000 samples, t = 0.000 … 0.999.
    QTest::newRow("everything") << -1.0 << 5.0 << 1000;
    QTest::newRow("inclusive bounds") << 0.25 << 0.5 << 251;
    QTest::newRow("nothing") << 2.0 << 3.0 << 0;
}

void TestSampleCsvWriter::writesRangeThatReadsBack()
{
    QFETCH(double, t0);
    QFETCH(double, t1);
    QFETCH(int, rows);
    SampleBuffer buffer(1000);
    for (int i = 0; i < 1000; ++i) {
        Sample s;
        s.t_s = i / 1000.0;
        s.theta = std::sin(i * 0.01) / 3;
        s.omega = i % 7 == 0 ? std::numeric_limits<double>::quiet_NaN() : 1.0 / (i + 1);
        s.tau = -s.theta * 0.1;
        s.tau_rec = 0.1 / 3;
        s.tau_ext = 1e-7 * i;
        s.tau_total = s.tau_rec + s.tau_ext;
        s.v_ref = 0.3;
        s.p_ref = i * 1e-3;
        s.flags = static_cast<quint16>(i & 0x0307);
        buffer.append(s);
    }
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("view.csv"));
    QString error;
    QCOMPARE(SampleCsvWriter::write(buffer, t0, t1, path, &error), qsizetype(rows));
    const RecordingReadResult result = readRecording(path);
    QVERIFY2(result.recording.has_value(), qPrintable(result.error));
    const QList<Sample> &samples = result.recording->samples;
    QCOMPARE(samples.size(), rows);
    const qsizetype first = buffer.lowerBound(t0);
    for (int k = 0; k < samples.size(); ++k) {
        const Sample expected = buffer.sample(first + k);
        QCOMPARE(samples[k].t_s, expected.t_s);
        for (Channel channel : kAllChannels) {
            const double want = channelValue(expected, channel);
            const double got = channelValue(samples[k], channel);
            if (std::isnan(want))
                QVERIFY(std::isnan(got));
            else
                QCOMPARE(got, want); // round-trip digits: exact
        }
        QCOMPARE(samples[k].flags, expected.flags);
    }
}

void TestSampleCsvWriter::reportsUnwritablePath()
{
    SampleBuffer buffer(4);
    QString error;
    QCOMPARE(SampleCsvWriter::write(buffer, 0, 1, QStringLiteral("/nonexistent-dir/x.csv"), &error),
             qsizetype(-1));
    QVERIFY(!error.isEmpty());
}

QTEST_GUILESS_MAIN(TestSampleCsvWriter)
#include "tst_samplecsvwriter.moc"
