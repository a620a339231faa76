// Decimator: pass-through, min/max per pixel column keeps every extreme, gaps, scaling.
#include "plots/decimator.h"
#include "plots/samplebuffer.h"

#include <QTest>

#include <algorithm>
#include <vector>

#include <cmath>
#include <limits>
#include <random>

using namespace hatpic;

namespace {

SampleBuffer rampBuffer(int count, double dt, qsizetype capacity = 0)
{
    SampleBuffer buffer(capacity > 0 ? capacity : count);
    for (int i = 0; i < count; ++i) {
        Sample s;
        s.t_s = i * dt;
        s.theta = i;
        buffer.append(s);
    }
    return buffer;
}

//! The decimation spelled out one sample at a time (column int((t − t0)/width), a bucket per
//! column and per stretch between gaps, min and max in time order), as the reference for the
//! Decimator's faster pass.
DecimationResult referenceRun(const SampleBuffer &buffer, Channel channel, double t0, double t1,
                              int pixels, double gap, double scale, QVector<QCPGraphData> &out)
{
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    DecimationResult result;
    out.clear();
    if (buffer.isEmpty() || !(t1 > t0))
        return result;
    const qsizetype first = buffer.lowerBound(t0);
    const qsizetype last = buffer.upperBound(t1);
    const qsizetype from = std::max<qsizetype>(first - 1, 0);
    const qsizetype to = std::min<qsizetype>(last + 1, buffer.size());
    result.rawCount = last - first;
    result.decimated = result.rawCount > 2 * qsizetype(pixels);
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    double prevT = 0;
    bool hasPrev = false;
    auto step = [&](double t) {
        if (hasPrev && t - prevT > gap)
            out.append(QCPGraphData((prevT + t) / 2, nan));
    };
    struct Point
    {
        double t, v;
    };
    std::vector<Point> bucket;
    int bucketColumn = -1;
    auto flush = [&] {
        if (bucket.empty())
            return;
        const Point *mn = nullptr;
        const Point *mx = nullptr;
        for (const Point &p : bucket) {
            if (std::isnan(p.v))
                continue;
            if (std::isfinite(p.v)) {
                lo = std::min(lo, p.v);
                hi = std::max(hi, p.v);
            }
            if (!mn || p.v < mn->v)
                mn = &p;
            if (!mx || p.v > mx->v)
                mx = &p;
        }
        if (!mn)
            out.append(QCPGraphData(bucket.front().t, nan));
        else if (mn->t == mx->t)
            out.append(QCPGraphData(mn->t, mn->v));
        else if (mn->t < mx->t)
            out << QCPGraphData(mn->t, mn->v) << QCPGraphData(mx->t, mx->v);
        else
            out << QCPGraphData(mx->t, mx->v) << QCPGraphData(mn->t, mn->v);
        bucket.clear();
        bucketColumn = -1;
    };
    const double width = (t1 - t0) / pixels;
    for (qsizetype i = from; i < to; ++i) {
        const double t = buffer.time(i);
        const double v = buffer.value(channel, i) * scale;
        const bool inside = i >= first && i < last;
        if (!result.decimated || !inside) {
            flush();
            step(t);
            out.append(QCPGraphData(t, v));
            if (inside && std::isfinite(v)) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
        } else {
            if (hasPrev && t - prevT > gap) {
                flush();
                step(t);
            }
            const int column = std::clamp(int((t - t0) / width), 0, pixels - 1);
            if (column != bucketColumn)
                flush();
            bucketColumn = column;
            bucket.push_back({t, v});
        }
        prevT = t;
        hasPrev = true;
    }
    flush();
    if (lo <= hi) {
        result.min = lo;
        result.max = hi;
        result.hasValues = true;
    }
    return result;
}

bool samePoints(const QVector<QCPGraphData> &a, const QVector<QCPGraphData> &b)
{
    if (a.size() != b.size())
        return false;
    for (qsizetype i = 0; i < a.size(); ++i) {
        const bool bothNaN = std::isnan(a[i].value) && std::isnan(b[i].value);
        if (a[i].key != b[i].key || (!bothNaN && a[i].value != b[i].value))
            return false;
    }
    return true;
}

int rounds()
{
    const int n = qEnvironmentVariableIntValue("HATPIC_TEST_ROUNDS");
    return n > 0 ? n : 20;
}

} // namespace

class TestDecimator : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void passesFewSamplesThrough_data();
    void passesFewSamplesThrough();
    void boundsPointsPerPixel_data();
    void boundsPointsPerPixel();
    void keepsEveryColumnExtreme();
    void keepsSingleSpike();
    void breaksLineAtGaps_data();
    void breaksLineAtGaps();
    void scalesValuesAndRange();
    void allNaNChannelHasNoRange();
    void matchesReference();
    void emptyInputs_data();
    void emptyInputs();
};

void TestDecimator::passesFewSamplesThrough_data()
{
    QTest::addColumn<double>("t0");
    QTest::addColumn<double>("t1");
    QTest::addColumn<int>("firstIndex");
    QTest::addColumn<int>("lastIndex");
    // 100 samples at 10 ms: t = 0 … 0.99.
    QTest::newRow("whole buffer") << -1.0 << 2.0 << 0 << 99;
    QTest::newRow("middle adds one neighbour each side") << 0.2 << 0.3 << 19 << 31;
    QTest::newRow("starts inside the data") << 0.5 << 5.0 << 49 << 99;
}

void TestDecimator::passesFewSamplesThrough()
{
    QFETCH(double, t0);
    QFETCH(double, t1);
    QFETCH(int, firstIndex);
    QFETCH(int, lastIndex);
    const SampleBuffer buffer = rampBuffer(100, 0.01);
    QVector<QCPGraphData> out;
    const DecimationResult r = Decimator(1000).run(buffer, Channel::Theta, t0, t1, 1.0, out);
    QVERIFY(!r.decimated);
    QCOMPARE(out.size(), lastIndex - firstIndex + 1);
    for (int i = 0; i < out.size(); ++i) {
        QCOMPARE(out[i].key, buffer.time(firstIndex + i));
        QCOMPARE(out[i].value, double(firstIndex + i));
    }
}

void TestDecimator::boundsPointsPerPixel_data()
{
    QTest::addColumn<int>("samples");
    QTest::addColumn<int>("pixels");
    QTest::newRow("60 s at 1 kHz on 800 px") << 60000 << 800;
    QTest::newRow("10 s at 1 kHz on 1900 px") << 10000 << 1900;
    QTest::newRow("just over twice the pixels") << 2001 << 1000;
}

void TestDecimator::boundsPointsPerPixel()
{
    QFETCH(int, samples);
    QFETCH(int, pixels);
    const SampleBuffer buffer = rampBuffer(samples, 0.001);
    QVector<QCPGraphData> out;
    const DecimationResult r =
        Decimator(pixels).run(buffer, Channel::Theta, 0, samples * 0.001, 1.0, out);
    QVERIFY(r.decimated);
    QCOMPARE(r.rawCount, samples);
    QVERIFY2(out.size() <= 2 * pixels + 2, qPrintable(QString::number(out.size())));
    for (int i = 1; i < out.size(); ++i)
        QVERIFY(out[i].key >= out[i - 1].key);
    QCOMPARE(r.min, 0.0);
    QCOMPARE(r.max, double(samples - 1));
}

void TestDecimator::keepsEveryColumnExtreme()
{
    // Seeded random signals: in every pixel column the drawn min and max equal the raw ones.
    std::mt19937_64 rng(20240611);
    std::normal_distribution<double> noise(0.0, 1.0);
    for (int round = 0; round < rounds(); ++round) {
        const int samples = 5000 + int(rng() % 20000);
        const int pixels = 100 + int(rng() % 900);
        SampleBuffer buffer(samples);
        double value = 0;
        for (int i = 0; i < samples; ++i) {
            value += noise(rng);
            Sample s;
            s.t_s = i * 0.001;
            s.tau = value;
            buffer.append(s);
        }
        const double t0 = 0.0005;
        const double t1 = (samples - 1) * 0.001;
        QVector<QCPGraphData> out;
        const Decimator decimator(pixels);
        decimator.run(buffer, Channel::Tau, t0, t1, 1.0, out);
        const double width = (t1 - t0) / pixels;
        auto column = [&](double t) { return std::clamp(int((t - t0) / width), 0, pixels - 1); };
        std::vector<double> rawMin(pixels, 1e300), rawMax(pixels, -1e300);
        for (qsizetype i = buffer.lowerBound(t0); i < buffer.upperBound(t1); ++i) {
            const int c = column(buffer.time(i));
            rawMin[c] = std::min(rawMin[c], buffer.value(Channel::Tau, i));
            rawMax[c] = std::max(rawMax[c], buffer.value(Channel::Tau, i));
        }
        std::vector<double> outMin(pixels, 1e300), outMax(pixels, -1e300);
        for (const QCPGraphData &p : out) {
            if (p.key < t0 || p.key > t1)
                continue; // the neighbours outside the range
            const int c = column(p.key);
            outMin[c] = std::min(outMin[c], p.value);
            outMax[c] = std::max(outMax[c], p.value);
        }
        for (int c = 0; c < pixels; ++c) {
            QCOMPARE(outMin[c], rawMin[c]);
            QCOMPARE(outMax[c], rawMax[c]);
        }
    }
}

void TestDecimator::keepsSingleSpike()
{
    SampleBuffer buffer(60000);
    for (int i = 0; i < 60000; ++i) {
        Sample s;
        s.t_s = i * 0.001;
        s.tau_total = i == 31234 ? 0.44 : 0.0;
        buffer.append(s);
    }
    QVector<QCPGraphData> out;
    const DecimationResult r = Decimator(400).run(buffer, Channel::TauTotal, 0, 60, 1.0, out);
    QCOMPARE(r.max, 0.44);
    const auto spike = std::find_if(out.cbegin(), out.cend(),
                                    [](const QCPGraphData &p) { return p.value == 0.44; });
    QVERIFY(spike != out.cend());
    QCOMPARE(spike->key, buffer.time(31234));
}

void TestDecimator::breaksLineAtGaps_data()
{
    QTest::addColumn<int>("samples");
    QTest::addColumn<int>("pixels");
    QTest::newRow("pass-through") << 200 << 1000;
    QTest::newRow("decimated") << 20000 << 200;
}

void TestDecimator::breaksLineAtGaps()
{
    QFETCH(int, samples);
    QFETCH(int, pixels);
    SampleBuffer buffer(samples);
    for (int i = 0; i < samples; ++i) {
        Sample s;
        s.t_s = i * 0.001 + (i >= samples / 2 ? 1.0 : 0.0); // 1 s link loss half way
        s.theta = 1;
        buffer.append(s);
    }
    QVector<QCPGraphData> out;
    Decimator(pixels).run(buffer, Channel::Theta, 0, buffer.lastTime(), 1.0, out);
    const auto nans = std::count_if(out.cbegin(), out.cend(),
                                    [](const QCPGraphData &p) { return std::isnan(p.value); });
    QCOMPARE(nans, 1);
    const auto gap = std::find_if(out.cbegin(), out.cend(),
                                  [](const QCPGraphData &p) { return std::isnan(p.value); });
    const double before = buffer.time(samples / 2 - 1);
    const double after = buffer.time(samples / 2);
    QVERIFY(gap->key > before && gap->key < after);
}

void TestDecimator::scalesValuesAndRange()
{
    SampleBuffer buffer(10);
    for (int i = 0; i < 10; ++i) {
        Sample s;
        s.t_s = i;
        s.theta = i * 0.1;
        buffer.append(s);
    }
    QVector<QCPGraphData> out;
    const DecimationResult r = Decimator(100).run(buffer, Channel::Theta, 2, 5, 10.0, out);
    QVERIFY(r.hasValues);
    QCOMPARE(r.min, 2.0);
    QCOMPARE(r.max, 5.0);
    QCOMPARE(out.first().value, 1.0); // the neighbour before the range, scaled
    QCOMPARE(out.last().value, 6.0);
}

void TestDecimator::allNaNChannelHasNoRange()
{
    SampleBuffer buffer(5000);
    for (int i = 0; i < 5000; ++i) {
        Sample s;
        s.t_s = i * 0.001;
        s.omega = std::numeric_limits<double>::quiet_NaN(); // legacy devices have no ω
        buffer.append(s);
    }
    QVector<QCPGraphData> out;
    const DecimationResult r = Decimator(100).run(buffer, Channel::Omega, 0, 5, 1.0, out);
    QVERIFY(!r.hasValues);
    QVERIFY(!out.isEmpty());
    for (const QCPGraphData &p : out)
        QVERIFY(std::isnan(p.value));
}

void TestDecimator::matchesReference()
{
    // Seeded random buffers that wrap around their ring, with gaps, NaN and ±Inf runs, large
    // clock values, random views and scales: the Decimator draws exactly what the
    // one-sample-at-a-time reference draws.
    std::mt19937_64 rng(777);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (int round = 0; round < 10 * rounds(); ++round) {
        const qsizetype capacity = 500 + qsizetype(rng() % 20000);
        const qsizetype count = capacity / 2 + qsizetype(rng() % (2 * capacity));
        const double offset = rng() % 4 == 0 ? 1e6 * unit(rng) : 0.0;
        SampleBuffer buffer(capacity);
        double t = offset;
        double value = 0;
        for (qsizetype i = 0; i < count; ++i) {
            t += rng() % 500 == 0 ? 0.3 + unit(rng) : (rng() % 50 == 0 ? 0.0 : 0.001);
            value += unit(rng) - 0.5;
            Sample s;
            s.t_s = t;
            const auto kind = rng() % 1000;
            s.tau = kind == 0 ? inf : kind == 1 ? -inf : kind < 5 ? std::nan("") : value;
            buffer.append(s);
        }
        const double span = buffer.lastTime() - buffer.firstTime();
        const double t0 = buffer.firstTime() + span * unit(rng) * 0.5 - 0.1;
        const double t1 = t0 + span * unit(rng) + 0.01;
        const int pixels = 1 + int(rng() % 1500);
        const double scale = rng() % 2 ? 1.0 : 180.0 / 3.141592653589793;
        QVector<QCPGraphData> got;
        QVector<QCPGraphData> want;
        const DecimationResult r = Decimator(pixels).run(buffer, Channel::Tau, t0, t1, scale, got);
        const DecimationResult w =
            referenceRun(buffer, Channel::Tau, t0, t1, pixels, Decimator::kDefaultGap, scale, want);
        QVERIFY2(samePoints(got, want), qPrintable(QStringLiteral("round %1: %2 vs %3 points")
                                                       .arg(round)
                                                       .arg(got.size())
                                                       .arg(want.size())));
        QCOMPARE(r.rawCount, w.rawCount);
        QCOMPARE(r.decimated, w.decimated);
        QCOMPARE(r.hasValues, w.hasValues);
        QCOMPARE(r.min, w.min);
        QCOMPARE(r.max, w.max);
    }
}

void TestDecimator::emptyInputs_data()
{
    QTest::addColumn<int>("samples");
    QTest::addColumn<double>("t0");
    QTest::addColumn<double>("t1");
    QTest::newRow("empty buffer") << 0 << 0.0 << 1.0;
    QTest::newRow("reversed range") << 10 << 1.0 << 0.0;
    QTest::newRow("empty range") << 10 << 0.5 << 0.5;
}

void TestDecimator::emptyInputs()
{
    QFETCH(int, samples);
    QFETCH(double, t0);
    QFETCH(double, t1);
    const SampleBuffer buffer = rampBuffer(samples, 0.1, 16);
    QVector<QCPGraphData> out{QCPGraphData(1, 1)};
    const DecimationResult r = Decimator(100).run(buffer, Channel::Theta, t0, t1, 1.0, out);
    QVERIFY(out.isEmpty());
    QCOMPARE(r.rawCount, 0);
    QVERIFY(!r.hasValues);
}

QTEST_GUILESS_MAIN(TestDecimator)
#include "tst_decimator.moc"
