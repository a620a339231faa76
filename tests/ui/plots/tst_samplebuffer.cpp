// SampleBuffer: ring order, overwrite, bisection by time, clock restarts.
#include "plots/samplebuffer.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace hatpic;

namespace {

Sample makeSample(double t, double theta = 0)
{
    Sample s;
    s.t_s = t;
    s.theta = theta;
    s.tau = -theta;
    s.p_ref = 2 * theta;
    s.flags = static_cast<quint16>(std::lround(t * 10)) & 0xff;
    return s;
}

} // namespace

class TestSampleBuffer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void keepsOrderAndOverwritesOldest_data();
    void keepsOrderAndOverwritesOldest();
    void bisectsByTime_data();
    void bisectsByTime();
    void nearestPicksClosest();
    void shiftsRestartedClock();
    void dropsNonFiniteTimes();
    void generationChangesOnEveryChange();
    void copyIsIndependent();
    void roundTripsSample();
    void runsCoverIndicesInOrder();
};

void TestSampleBuffer::keepsOrderAndOverwritesOldest_data()
{
    QTest::addColumn<int>("capacity");
    QTest::addColumn<int>("count");
    QTest::newRow("empty") << 8 << 0;
    QTest::newRow("partly filled") << 8 << 5;
    QTest::newRow("exactly full") << 8 << 8;
    QTest::newRow("wrapped once") << 8 << 11;
    QTest::newRow("wrapped many times") << 7 << 100;
    QTest::newRow("capacity one") << 1 << 3;
}

void TestSampleBuffer::keepsOrderAndOverwritesOldest()
{
    QFETCH(int, capacity);
    QFETCH(int, count);
    SampleBuffer buffer(capacity);
    for (int i = 0; i < count; ++i)
        buffer.append(makeSample(i * 0.001, i));
    const int kept = std::min(capacity, count);
    QCOMPARE(buffer.size(), kept);
    QCOMPARE(buffer.capacity(), capacity);
    QCOMPARE(buffer.appendedCount(), quint64(count));
    QCOMPARE(buffer.overwrittenCount(), quint64(count - kept));
    for (int i = 0; i < kept; ++i) {
        const int original = count - kept + i;
        QCOMPARE(buffer.value(Channel::Theta, i), double(original));
        QCOMPARE(buffer.value(Channel::Tau, i), -double(original));
        QCOMPARE(buffer.time(i), original * 0.001);
    }
    if (kept > 0) {
        QCOMPARE(buffer.firstTime(), (count - kept) * 0.001);
        QCOMPARE(buffer.lastTime(), (count - 1) * 0.001);
    }
}

void TestSampleBuffer::bisectsByTime_data()
{
    QTest::addColumn<double>("t");
    QTest::addColumn<int>("lower");
    QTest::addColumn<int>("upper");
    // Buffer holds t = 0.1 … 1.0 (indices 0…9) after wrapping.
    QTest::newRow("before first") << 0.0 << 0 << 0;
    QTest::newRow("exactly first") << 0.1 << 0 << 1;
    QTest::newRow("between samples") << 0.45 << 4 << 4;
    QTest::newRow("exactly a sample") << 0.5 << 4 << 5;
    QTest::newRow("exactly last") << 1.0 << 9 << 10;
    QTest::newRow("after last") << 2.0 << 10 << 10;
}

void TestSampleBuffer::bisectsByTime()
{
    QFETCH(double, t);
    QFETCH(int, lower);
    QFETCH(int, upper);
    SampleBuffer buffer(10);
    for (int i = 0; i <= 10; ++i)
        buffer.append(makeSample(i / 10.0));
    QCOMPARE(buffer.lowerBound(t), lower);
    QCOMPARE(buffer.upperBound(t), upper);
}

void TestSampleBuffer::nearestPicksClosest()
{
    SampleBuffer buffer(16);
    QCOMPARE(buffer.nearest(1.0), -1);
    for (int i = 0; i < 5; ++i)
        buffer.append(makeSample(i));
    QCOMPARE(buffer.nearest(-3.0), 0);
    QCOMPARE(buffer.nearest(1.4), 1);
    QCOMPARE(buffer.nearest(1.6), 2);
    QCOMPARE(buffer.nearest(9.0), 4);
}

void TestSampleBuffer::shiftsRestartedClock()
{
    SampleBuffer buffer(100);
    for (int i = 0; i < 10; ++i)
        buffer.append(makeSample(5.0 + i * 0.01));
    const double before = buffer.lastTime();
    buffer.append(makeSample(0.0)); // a new session restarts its clock at 0
    buffer.append(makeSample(0.01));
    QCOMPARE(buffer.restartCount(), quint64(1));
    QCOMPARE(buffer.size(), 12);
    QCOMPARE(buffer.time(10), before + SampleBuffer::kRestartGap);
    QVERIFY(qFuzzyCompare(buffer.time(11), before + SampleBuffer::kRestartGap + 0.01));
    for (int i = 1; i < buffer.size(); ++i)
        QVERIFY(buffer.time(i) >= buffer.time(i - 1));
}

void TestSampleBuffer::dropsNonFiniteTimes()
{
    SampleBuffer buffer(4);
    buffer.append(makeSample(std::numeric_limits<double>::quiet_NaN()));
    buffer.append(makeSample(std::numeric_limits<double>::infinity()));
    QCOMPARE(buffer.size(), 0);
    Sample legacy = makeSample(1.0);
    legacy.tau = std::numeric_limits<double>::quiet_NaN(); // legacy carries no τ: kept as NaN
    buffer.append(legacy);
    QCOMPARE(buffer.size(), 1);
    QVERIFY(std::isnan(buffer.value(Channel::Tau, 0)));
}

void TestSampleBuffer::generationChangesOnEveryChange()
{
    SampleBuffer buffer(4);
    const quint64 g0 = buffer.generation();
    buffer.append(makeSample(0));
    const quint64 g1 = buffer.generation();
    QVERIFY(g1 != g0);
    buffer.append(SampleBatch{makeSample(1), makeSample(2)});
    const quint64 g2 = buffer.generation();
    QVERIFY(g2 != g1);
    buffer.clear();
    QVERIFY(buffer.generation() != g2);
    QVERIFY(buffer.isEmpty());
}

void TestSampleBuffer::copyIsIndependent()
{
    SampleBuffer buffer(4);
    buffer.append(makeSample(0, 1));
    SampleBuffer copy = buffer;
    buffer.append(makeSample(1, 2));
    QCOMPARE(copy.size(), 1);
    QCOMPARE(buffer.size(), 2);
    QCOMPARE(copy.value(Channel::Theta, 0), 1.0);
}

void TestSampleBuffer::roundTripsSample()
{
    SampleBuffer buffer(2);
    Sample s = makeSample(1.25, 0.3);
    s.omega = 1.5;
    s.tau_rec = -0.1;
    s.tau_ext = 0.05;
    s.tau_total = -0.05;
    s.v_ref = 0.15;
    s.tau_fx = -0.0375;
    s.flags = 0x0203;
    buffer.append(s);
    const Sample back = buffer.sample(0);
    QCOMPARE(back.t_s, s.t_s);
    for (Channel channel : kAllChannels)
        QCOMPARE(channelValue(back, channel), channelValue(s, channel));
    QCOMPARE(back.tau_fx, -0.0375);
    QCOMPARE(back.flags, s.flags);
    // A device that does not send τ_fx: unknown (NaN) in, unknown out, never 0.
    Sample legacy = makeSample(1.5, 0.1);
    legacy.tau_fx = std::numeric_limits<double>::quiet_NaN();
    buffer.append(legacy);
    QVERIFY(std::isnan(buffer.value(Channel::TauFx, 1)));
    QVERIFY(std::isnan(buffer.sample(1).tau_fx));
    QCOMPARE(buffer.value(Channel::TauFx, 0), -0.0375);
}

void TestSampleBuffer::runsCoverIndicesInOrder()
{
    // Before and after the ring wraps: the runs' slots hold the samples at their indices.
    for (const int appended : {5, 10, 17, 23}) {
        SampleBuffer buffer(10);
        for (int i = 0; i < appended; ++i)
            buffer.append(makeSample(i * 0.1, i));
        for (qsizetype first = 0; first <= buffer.size(); ++first) {
            for (qsizetype last = first; last <= buffer.size(); ++last) {
                qsizetype next = first;
                for (const SampleBuffer::Run &run : buffer.runs(first, last)) {
                    if (run.count == 0)
                        continue;
                    QCOMPARE(run.index, next);
                    QVERIFY(run.slot >= 0 && run.slot + run.count <= buffer.capacity());
                    for (qsizetype k = 0; k < run.count; ++k) {
                        QCOMPARE(buffer.timeSlots()[run.slot + k], buffer.time(next + k));
                        QCOMPARE(buffer.valueSlots(Channel::Theta)[run.slot + k],
                                 buffer.value(Channel::Theta, next + k));
                    }
                    next += run.count;
                }
                QCOMPARE(next, last);
            }
        }
    }
}

QTEST_GUILESS_MAIN(TestSampleBuffer)
#include "tst_samplebuffer.moc"
