// PlotFeed and the effects (effects.md): the operating point is the measured static torque
// τ_rec + τ_fx (τ_rec alone where τ_fx is unknown), the device's effect block reaches the views
// live, the recording's in replay, and no device means no effects.
#include "plots/plotfeed.h"
#include "plots/plotpanel.h"
#include "plots/replaycontroller.h"
#include "telemetry/recordingwriter.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>

using namespace hatpic;

namespace {

SampleBatch batch(double start, int count, double tauFx)
{
    SampleBatch out;
    for (int i = 0; i < count; ++i) {
        Sample s;
        s.t_s = start + i * 0.001;
        s.theta = 0.2 + i * 1e-4;
        s.tau_rec = -0.0625;
        s.tau_fx = tauFx;
        out.append(s);
    }
    return out;
}

EffectParams walls()
{
    EffectParams fx;
    fx.wall_min = -0.5;
    fx.wall_max = 0.5;
    fx.wall_stiffness = 3.0;
    return fx;
}

std::optional<EffectParams> shownEffects(const QSignalSpy &spy)
{
    return spy.constLast().at(0).value<DeviceTuning>().effects;
}

} // namespace

class TestPlotFeedEffects : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void operatingPointAddsTauFx();
    void liveEffectsReachTheViews();
    void replayShowsTheRecordingsEffects();
};

void TestPlotFeedEffects::operatingPointAddsTauFx()
{
    PlotPanel panel;
    PlotFeed feed(&panel);
    QSignalSpy point(&feed, &PlotFeed::operatingPoint);
    feed.appendLive(batch(1, 10, 0.015));
    QCOMPARE(point.constLast().at(1).toDouble(), -0.0625 + 0.015);
    // A device that does not send τ_fx: τ_rec alone, never NaN.
    feed.appendLive(batch(2, 10, std::numeric_limits<double>::quiet_NaN()));
    QCOMPARE(point.constLast().at(1).toDouble(), -0.0625);
}

void TestPlotFeedEffects::liveEffectsReachTheViews()
{
    PlotPanel panel;
    PlotFeed feed(&panel);
    QSignalSpy shown(&feed, &PlotFeed::deviceTuningShown);
    feed.setLiveDeviceTuning({DeviceParams{}, walls()});
    QCOMPARE(shown.size(), 1);
    QCOMPARE(shownEffects(shown), std::optional(walls()));
    QCOMPARE(shown.constLast().at(0).value<DeviceTuning>().params, std::optional(DeviceParams{}));
    // τ_fx's parts of the live samples from now on, with the device's block and θ0: a wall
    // 0.1 beyond wall_max, at rest: τ_wall = −3·0.1.
    Sample s;
    s.theta = 0.6;
    s.omega = 0;
    s.tau_fx = -0.3;
    feed.appendLive({s});
    const SampleBuffer &live = feed.liveBuffer();
    QVERIFY(std::abs(live.value(Channel::TauWall, live.size() - 1) + 0.3) < 1e-12);
    // The device goes: its effects go with it.
    feed.setLiveDeviceTuning({});
    QVERIFY(!shownEffects(shown));
    s.t_s = 1;
    feed.appendLive({s});
    QVERIFY(std::isnan(live.value(Channel::TauWall, live.size() - 1)));
    // Effects without the device's parameters (no θ0) count for nothing.
    feed.setLiveDeviceTuning({std::nullopt, walls()});
    QVERIFY(!shownEffects(shown));
    s.t_s = 2;
    feed.appendLive({s});
    QVERIFY(std::isnan(live.value(Channel::TauWall, live.size() - 1)));
}

void TestPlotFeedEffects::replayShowsTheRecordingsEffects()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("fx.csv"));
    {
        RecordingWriter writer;
        RecordingMetadata meta;
        meta.start = QDateTime::currentDateTimeUtc();
        meta.source = QStringLiteral("tst_plotfeedeffects");
        EffectParams recorded = walls();
        recorded.wall_max = 0.25;
        meta.effects = recorded;
        QVERIFY2(writer.open(path, meta), qPrintable(writer.error()));
        QVERIFY(writer.append(batch(10, 500, 0.02)));
        writer.close();
    }
    PlotPanel panel;
    PlotFeed feed(&panel);
    feed.setLiveDeviceTuning({DeviceParams{}, walls()});
    QSignalSpy shown(&feed, &PlotFeed::deviceTuningShown);
    QSignalSpy point(&feed, &PlotFeed::operatingPoint);
    QString error;
    QVERIFY2(feed.openRecording(path, &error), qPrintable(error));
    QVERIFY(shownEffects(shown));
    QCOMPARE(shownEffects(shown)->wall_max, 0.25);
    // The recording's τ_fx column: the point at the playhead is τ_rec + τ_fx.
    QVERIFY(!point.isEmpty());
    QVERIFY(std::abs(point.constLast().at(1).toDouble() - (-0.0625 + 0.02)) < 1e-9);
    // τ_fx's parts from the recording's block: θ ≤ 0.25 inside the walls, so τ_vib = τ_fx.
    const SampleBuffer &replayed = feed.replay()->buffer();
    QCOMPARE(replayed.value(Channel::TauWall, 0), 0.0);
    QVERIFY(std::abs(replayed.value(Channel::TauVib, 0) - 0.02) < 1e-9);
    // Live effects arriving meanwhile are kept, not shown; back to live shows them.
    const qsizetype before = shown.size();
    feed.setLiveDeviceTuning({DeviceParams{}, std::nullopt});
    QCOMPARE(shown.size(), before);
    feed.backToLive();
    QVERIFY(!shownEffects(shown));
}

QTEST_MAIN(TestPlotFeedEffects)
#include "tst_plotfeedeffects.moc"
