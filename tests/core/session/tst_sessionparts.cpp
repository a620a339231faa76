// The session's small parts on their own: LinkStatistics (seq gaps, decoder drops kept across
// links, rates) and the two streams (FeedbackStream: at once within its cap, kept alive,
// paused; PingProbe's RTT and its bound on unanswered probes).
#include "session/linkstatistics.h"
#include "session/samplelisteners.h"
#include "session/streams.h"

#include <QElapsedTimer>
#include <QTest>

#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

namespace hatpic {

class TestSessionParts : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void seqGapsCountModulo256();
    void decoderDropsAddUpAcrossLinks();
    void ratesCoverTheLastSecond();
    void feedbackGoesAtOnceWithinItsCap();
    void feedbackIsKeptAliveUnlessPaused();
    void feedbackIsFinite();
    void feedbackCarriesEveryKnob();
    void removedListenerIsNeverCalledAgain();
    void pingMeasuresTheRoundTrip();
    void busyPingWaitsAndUnansweredAreBounded();
};

void TestSessionParts::seqGapsCountModulo256()
{
    LinkStatistics s;
    QVERIFY(s.countTelemetry(250, 250'000));
    QVERIFY(s.countTelemetry(251, 251'000));
    QVERIFY(s.countTelemetry(2, 258'000)); // 252…255, 0, 1 missing
    LinkStats out = s.snapshot(nullptr, nullptr);
    QCOMPARE(out.frames, quint64(3));
    QCOMPARE(out.seqDrops, quint64(6));
    QVERIFY(!s.countTelemetry(2, 258'000)); // the same frame again: a duplicate, no sample
    QCOMPARE(s.snapshot(nullptr, nullptr).duplicates, quint64(1));
    QCOMPARE(s.snapshot(nullptr, nullptr).seqDrops, quint64(6));
    s.restartSeq(); // a new stream: no gap to the previous one
    QVERIFY(s.countTelemetry(100, 900'000));
    QCOMPARE(s.snapshot(nullptr, nullptr).seqDrops, quint64(6));
    s.clear();
    QCOMPARE(s.snapshot(nullptr, nullptr).frames, quint64(0));
}

void TestSessionParts::decoderDropsAddUpAcrossLinks()
{
    LinkStatistics s;
    v2::DecoderStats closed;
    closed.drops[0] = 2;
    s.absorb(closed);
    legacy::DecoderStats legacyClosed;
    legacyClosed.malformed = 3;
    s.absorb(legacyClosed);
    v2::DecoderStats live;
    live.drops[0] = 5;
    live.drops[1] = 1;
    legacy::DecoderStats legacyLive;
    legacyLive.malformed = 4;
    const LinkStats out = s.snapshot(&live, &legacyLive);
    QCOMPARE(out.decoderDrops[0], quint64(7));
    QCOMPARE(out.decoderDrops[1], quint64(1));
    QCOMPARE(out.totalDecoderDrops(), quint64(8));
    QCOMPARE(out.legacyMalformed, quint64(7));
    QCOMPARE(s.snapshot(nullptr, nullptr).totalDecoderDrops(), quint64(2));
}

void TestSessionParts::ratesCoverTheLastSecond()
{
    LinkStatistics s;
    constexpr qint64 kSecond = 1'000'000'000;
    s.tick(0);
    for (int i = 1; i <= 8; ++i) { // 100 frames and 1000 bytes per 250 ms
        for (int f = 0; f < 100; ++f)
            s.countFrame();
        s.countBytes(1000, i * kSecond / 4);
        s.tick(i * kSecond / 4);
    }
    const LinkStats out = s.snapshot(nullptr, nullptr);
    QCOMPARE(out.framesPerSecond, 400.0);
    QCOMPARE(out.bytesPerSecond, 4000.0);
    QCOMPARE(s.lastReceivedNs(), 2 * kSecond);
}

void TestSessionParts::feedbackGoesAtOnceWithinItsCap()
{
    QList<double> sent;
    FeedbackStream stream([&](const AxisTorques &tau) { sent.append(tau[0]); });
    stream.start(20);                   // at most one frame per 50 ms
    QCOMPARE(sent, QList<double>{0.0}); // once at once
    stream.setTauExt(0.05);             // within the 50 ms: waits for the rest of them
    stream.setTauExt(0.06);             // … and the newest value goes then
    QCOMPARE(sent.size(), 1);
    QTRY_COMPARE(sent.size(), 2);
    QCOMPARE(sent.last(), 0.06);
    stream.setTauExt(0.06); // no change: nothing new to send, now or later
    QCOMPARE(sent.size(), 2);

    stream.start(1000); // a millisecond's cap: a change goes out within the call
    QTest::qWait(5);
    const qsizetype before = sent.size();
    stream.setTauExt(-0.02);
    QCOMPARE(sent.size(), before + 1);
    QCOMPARE(sent.last(), -0.02);
    stream.stop();
}

void TestSessionParts::feedbackIsKeptAliveUnlessPaused()
{
    QList<double> sent;
    FeedbackStream stream([&](const AxisTorques &tau) { sent.append(tau[0]); });
    stream.setTauExt(0.05);
    stream.start(1000);
    QCOMPARE(sent.size(), 1);
    // Nothing changes, yet the device hears the torque again every kKeepAliveMs.
    QTRY_VERIFY_WITH_TIMEOUT(sent.size() >= 3, 20 * FeedbackStream::kKeepAliveMs);
    QCOMPARE(sent.last(), 0.05);
    stream.setPaused(true);
    const qsizetype paused = sent.size();
    QTest::qWait(2 * FeedbackStream::kKeepAliveMs);
    QCOMPARE(sent.size(), paused);
    stream.setPaused(false);
    QTRY_VERIFY(sent.size() > paused);
    stream.stop();
    const qsizetype stopped = sent.size();
    stream.setTauExt(0.07); // stopped: kept for the next start, not sent
    QTest::qWait(2 * FeedbackStream::kKeepAliveMs);
    QCOMPARE(sent.size(), stopped);

    stream.start(0); // no feedback at all
    QTest::qWait(2 * FeedbackStream::kKeepAliveMs);
    QCOMPARE(sent.size(), stopped);
    stream.start(100);
    QCOMPARE(sent.last(), 0.07);
}

void TestSessionParts::feedbackIsFinite()
{
    FeedbackStream stream([](const AxisTorques &) {});
    stream.setTauExt(std::numeric_limits<double>::quiet_NaN());
    QCOMPARE(stream.tauExt(), 0.0);
    stream.setTauExt(-std::numeric_limits<double>::infinity());
    QCOMPARE(stream.tauExt(), 0.0);
    stream.setTauExt(-0.1);
    QCOMPARE(stream.tauExt(), -0.1);
    // Every knob's, each made finite on its own.
    stream.setTorques({0.01, std::numeric_limits<double>::quiet_NaN(), -0.03, 0.04});
    QCOMPARE(stream.torques(), (AxisTorques{0.01, 0.0, -0.03, 0.04}));
}

void TestSessionParts::feedbackCarriesEveryKnob()
{
    // Knob 1's setter leaves the others' torques alone; a change to any knob is sent.
    QList<AxisTorques> sent;
    FeedbackStream stream([&](const AxisTorques &tau) { sent.append(tau); });
    stream.start(1000); // sends once at once: within a millisecond, a change would wait
    QTest::qWait(5);
    stream.setTorques({0.0, 0.02, 0.0, -0.04});
    QCOMPARE(sent.size(), 2);
    QCOMPARE(sent.last(), (AxisTorques{0.0, 0.02, 0.0, -0.04}));
    QTest::qWait(5);
    stream.setTauExt(0.1);
    QCOMPARE(sent.last(), (AxisTorques{0.1, 0.02, 0.0, -0.04}));
    QTest::qWait(5);
    const qsizetype before = sent.size();
    stream.setTorques({0.1, 0.02, 0.03, -0.04}); // knob 3 alone changed
    QCOMPARE(sent.size(), before + 1);
    QCOMPARE(sent.last()[2], 0.03);
    stream.stop();
}

void TestSessionParts::removedListenerIsNeverCalledAgain()
{
    // A listener busy on the session thread when another thread removes it: remove() returns
    // only once that call has ended, so the listener may be destroyed right after.
    struct Slow : SampleListener
    {
        std::atomic<bool> entered{false};
        std::atomic<bool> left{false};
        std::atomic<int> calls{0};
        void sampleDecoded(const Sample &) override
        {
            ++calls;
            entered = true;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            left = true;
        }
    } slow;
    SampleListeners listeners;
    listeners.add(&slow);
    std::thread session([&] { listeners.dispatch(Sample{}); });
    while (!slow.entered)
        std::this_thread::yield();
    listeners.remove(&slow);
    QVERIFY(slow.left); // waited for the call in progress
    session.join();
    listeners.dispatch(Sample{});
    QCOMPARE(slow.calls.load(), 1);
}

void TestSessionParts::pingMeasuresTheRoundTrip()
{
    QElapsedTimer clock;
    clock.start();
    QList<quint32> tokens;
    PingProbe probe(clock, [&](quint32 token) {
        tokens.append(token);
        return true;
    });
    probe.start();
    QCOMPARE(tokens.size(), 1);
    QTest::qWait(20);
    probe.onPong(tokens.first());
    QCOMPARE(probe.rtt().count(), quint64(1));
    QVERIFY(probe.rtt().last() >= 15);
    probe.onPong(tokens.first()); // answered once only
    probe.onPong(12345);          // never sent
    QCOMPARE(probe.rtt().count(), quint64(1));
    probe.clear();
    QVERIFY(probe.rtt().isEmpty());
}

void TestSessionParts::busyPingWaitsAndUnansweredAreBounded()
{
    QElapsedTimer clock;
    clock.start();
    bool busy = true;
    QList<quint32> tokens;
    PingProbe probe(clock, [&](quint32 token) {
        if (busy)
            return false;
        tokens.append(token);
        return true;
    });
    probe.start();
    QVERIFY(tokens.isEmpty()); // a command waits: no PING in between
    busy = false;
    probe.stop();
    for (int i = 0; i < PingProbe::kMaxPendingPings + 5; ++i)
        probe.start(); // each start pings at once
    QCOMPARE(tokens.size(), PingProbe::kMaxPendingPings + 5);
    QCOMPARE(tokens.first(), quint32(1)); // the refused probe used no token
    // The oldest five were forgotten; the newest are still waiting for their PONG.
    probe.onPong(tokens.first());
    QVERIFY(probe.rtt().isEmpty());
    probe.onPong(tokens.last());
    QCOMPARE(probe.rtt().count(), quint64(1));
}

} // namespace hatpic

QTEST_GUILESS_MAIN(hatpic::TestSessionParts)
#include "tst_sessionparts.moc"
