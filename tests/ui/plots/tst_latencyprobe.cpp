// LatencyProbe: arrival → painted frame, only for samples drawn before the paint, bounded;
// and in a real PlotPanel, live samples are measured once they were painted.
#include "plots/latencyprobe.h"
#include "plots/plotpanel.h"
#include "plots/samplebuffer.h"

#include <QTest>

using namespace hatpic;

namespace {

constexpr qint64 kMs = 1'000'000;

SampleBatch arrivals(std::initializer_list<qint64> ns)
{
    SampleBatch batch;
    for (const qint64 t : ns) {
        Sample s;
        s.arrival_ns = t;
        batch.append(s);
    }
    return batch;
}

} // namespace

class TestLatencyProbe : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void measuresOnlyWhatWasDrawnBeforeThePaint()
    {
        LatencyProbe probe;
        probe.arrived(arrivals({100 * kMs, 110 * kMs}));
        probe.painted(115 * kMs); // a paint before they were drawn shows the old buffer
        QCOMPARE(probe.summary().count, 0u);
        probe.drawn();
        probe.arrived(arrivals({118 * kMs})); // after the draw: waits for the next one
        probe.painted(120 * kMs);
        LatencyProbe::Summary s = probe.summary();
        QCOMPARE(s.count, 2u); // 20 ms and 10 ms
        QCOMPARE(s.maxMs, 20.0);
        QCOMPARE(s.medianMs, 10.5); // rank 1 of 2: the bin [10, 10.5) ms, by its upper edge
        probe.drawn();
        probe.painted(130 * kMs); // 12 ms
        s = probe.summary();
        QCOMPARE(s.count, 3u);
        QCOMPARE(s.medianMs, 12.5);
    }

    void ignoresSamplesWithoutArrival()
    {
        LatencyProbe probe;
        probe.arrived(arrivals({0, 0, 5 * kMs}));
        probe.drawn();
        probe.painted(6 * kMs);
        QCOMPARE(probe.summary().count, 1u);
    }

    void percentilesFromTheHistogram()
    {
        LatencyProbe probe;
        SampleBatch batch;
        for (int i = 1; i <= 100; ++i) // latencies 1 … 100 ms
            batch.append(arrivals({(1000 - i) * kMs}));
        probe.arrived(batch);
        probe.drawn();
        probe.painted(1000 * kMs);
        const LatencyProbe::Summary s = probe.summary();
        QCOMPARE(s.count, 100u);
        QCOMPARE(s.medianMs, 50.5);
        QCOMPARE(s.p95Ms, 95.5);
        QCOMPARE(s.maxMs, 100.0);
        probe.resetSummary();
        QCOMPARE(probe.summary().count, 0u);
    }

    void longLatenciesLandInTheLastBin()
    {
        LatencyProbe probe;
        probe.arrived(arrivals({0 + 1, 1}));
        probe.drawn();
        probe.painted(5000 * kMs + 1); // 5 s: beyond the histogram
        const LatencyProbe::Summary s = probe.summary();
        QCOMPARE(s.medianMs, 5000.0);
        QCOMPARE(s.maxMs, 5000.0);
    }

    void boundedWhileNothingIsPainted()
    {
        LatencyProbe probe;
        SampleBatch batch = arrivals({1});
        for (std::size_t i = 0; i < LatencyProbe::kMaxWaiting + 10; ++i)
            probe.arrived(batch);
        QCOMPARE(probe.summary().dropped, 10u);
        probe.discard(); // paused: none of them will be shown
        QCOMPARE(probe.summary().dropped, LatencyProbe::kMaxWaiting + 10);
        probe.drawn();
        probe.painted(2);
        QCOMPARE(probe.summary().count, 0u);
    }

    void plotPanelMeasuresPaintedLiveSamples()
    {
        SampleBuffer buffer;
        PlotPanel panel;
        panel.resize(800, 600);
        panel.setSource(&buffer);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        SampleBatch batch;
        const qint64 arrival = sampleClockNs();
        for (int i = 0; i < 10; ++i) {
            Sample s;
            s.t_s = i * 1e-3;
            s.arrival_ns = arrival;
            batch.append(s);
        }
        buffer.append(batch);
        panel.noteArrivals(batch);
        QTRY_COMPARE(panel.latency().count, 10u); // the panel's timer draws, then it paints
        QVERIFY(panel.latency().maxMs >= 0);
        QVERIFY(panel.latency().maxMs < 60'000);
    }
};

QTEST_MAIN(TestLatencyProbe)
#include "tst_latencyprobe.moc"
