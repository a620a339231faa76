// SampleCsvWriter: the recording's columns, the visible range only, and a file readRecording
// accepts with the same values (NaN as an empty field).
#include "plots/samplebuffer.h"
#include "plots/samplecsvwriter.h"
#include "telemetry/recordingreader.h"

#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>

using namespace hatpic;

class TestSampleCsvWriter : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void headerIsRecordingHeader();
    void writesRangeThatReadsBack_data();
    void writesRangeThatReadsBack();
    void reportsUnwritablePath();
};

void TestSampleCsvWriter::headerIsRecordingHeader()
{
    QCOMPARE(SampleCsvWriter::header(), recordingColumns().join(u','));
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
