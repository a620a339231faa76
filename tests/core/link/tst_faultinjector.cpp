// FaultInjector and FaultSpec: the spec's syntax and errors, seeded repetition, and that each
// fault does to real v2 frames what its counter says (checked with the real v2 decoder).
#include "link/faultinjector.h"
#include "protocol/v2codec.h"

#include <QTest>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

QByteArray telemetryFrame(int i)
{
    v2::Telemetry t;
    t.t_us = quint32(1000 * i);
    t.theta = float(i) * 0.001f;
    return v2::encodeFrame(quint8(i), t);
}

// `count` TELEMETRY frames, then run through the injector in chunks of `chunk` bytes at
// 1 ms per frame. Returns everything that came out.
QByteArray runStream(FaultInjector &injector, int count, int chunk = 7)
{
    QByteArray in;
    for (int i = 0; i < count; ++i)
        in += telemetryFrame(i);
    QByteArray out;
    const double perByte = 0.001 / double(telemetryFrame(0).size());
    for (qsizetype at = 0; at < in.size(); at += chunk)
        out += injector.toHost(
            QByteArrayView(in).sliced(at, std::min<qsizetype>(chunk, in.size() - at)),
            double(at) * perByte);
    out += injector.toHost({}, 1e9); // release whatever a delay still holds
    return out;
}

struct Decoded
{
    QList<v2::Frame> frames;
    v2::DecoderStats stats;
};

Decoded decode(const QByteArray &bytes)
{
    v2::FrameDecoder decoder(v2::Direction::FromDevice);
    Decoded d;
    decoder.feed(bytes, d.frames);
    d.stats = decoder.stats();
    return d;
}

FaultSpec spec(const QString &text)
{
    QString error;
    const auto parsed = FaultSpec::parse(text, &error);
    if (!parsed)
        qFatal("bad spec in test: %s", qPrintable(error));
    return *parsed;
}

} // namespace

class TestFaultInjector : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void parsesTheIssuesExample()
    {
        const FaultSpec s =
            spec(u"drop=0.01,corrupt=0.005,dup=0.002,delay=0.01:20ms,cut=30s:2s,hdrop=0.1"_s);
        QCOMPARE(s.toHost.drop, 0.01);
        QCOMPARE(s.toHost.corrupt, 0.005);
        QCOMPARE(s.toHost.dup, 0.002);
        QCOMPARE(s.toHost.delay, 0.01);
        QCOMPARE(s.toHost.delaySeconds, 0.02);
        QCOMPARE(s.cuts.size(), std::size_t(1));
        QCOMPARE(s.cuts[0].at, 30.0);
        QCOMPARE(s.cuts[0].seconds, 2.0);
        QCOMPARE(s.toDevice.drop, 0.1);
        QCOMPARE(s.toString(),
                 u"drop=0.01,corrupt=0.005,dup=0.002,delay=0.01:20ms,cut=30s:2s,hdrop=0.1"_s);
        QCOMPARE(spec(s.toString()), s);
        QVERIFY(!s.isEmpty());
        QVERIFY(spec(u"drop=0"_s).isEmpty());
        QCOMPARE(spec(u"cut=1s:500ms,cut=3s:0.5s"_s).cuts.size(), std::size_t(2));
    }

    void refusesBadSpecsNamingFieldRuleAndValue_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QStringList>("mentions");
        QTest::newRow("probability above 1")
            << u"drop=1.5"_s << QStringList{u"drop"_s, u"0 to 1"_s, u"1.5"_s};
        QTest::newRow("negative") << u"hcorrupt=-0.1"_s
                                  << QStringList{u"hcorrupt"_s, u"0 to 1"_s, u"-0.1"_s};
        QTest::newRow("not a number") << u"dup=lots"_s << QStringList{u"dup"_s, u"lots"_s};
        QTest::newRow("unknown name")
            << u"explode=0.1"_s << QStringList{u"explode"_s, u"the names are"_s};
        QTest::newRow("no unit") << u"delay=0.1:20"_s
                                 << QStringList{u"delay"_s, u"unit"_s, u"\"20\""_s};
        QTest::newRow("delay without duration")
            << u"delay=0.1"_s << QStringList{u"delay"_s, u"probability:duration"_s, u"0.1"_s};
        QTest::newRow("delay too long")
            << u"hdelay=0.1:11s"_s << QStringList{u"hdelay"_s, u"at most 10"_s, u"11s"_s};
        QTest::newRow("cut length zero")
            << u"cut=3s:0s"_s << QStringList{u"cut"_s, u"above 0"_s, u"0s"_s};
        QTest::newRow("cut without length")
            << u"cut=3s"_s << QStringList{u"cut"_s, u"start:length"_s, u"3s"_s};
        QTest::newRow("twice") << u"drop=0.1,drop=0.2"_s
                               << QStringList{u"drop"_s, u"once"_s, u"0.2"_s};
        QTest::newRow("no value") << u"drop"_s << QStringList{u"name=value"_s, u"drop"_s};
        QTest::newRow("empty item") << u"drop=0.1,"_s << QStringList{u"name=value"_s};
        QTest::newRow("empty") << u" "_s << QStringList{u"empty"_s};
        QTest::newRow("infinite") << u"corrupt=inf"_s << QStringList{u"corrupt"_s, u"inf"_s};
    }
    void refusesBadSpecsNamingFieldRuleAndValue()
    {
        QFETCH(QString, text);
        QFETCH(QStringList, mentions);
        QString error;
        QVERIFY(!FaultSpec::parse(text, &error));
        for (const QString &m : std::as_const(mentions))
            QVERIFY2(error.contains(m), qPrintable(error + u" lacks "_s + m));
    }

    void noFaultPassesEveryByteAsItCame()
    {
        FaultInjector injector(spec(u"hdrop=1"_s), 1, FaultInjector::Framing::V2);
        QByteArray in;
        for (int i = 0; i < 50; ++i)
            in += telemetryFrame(i);
        QCOMPARE(runStream(injector, 50), in);
        QCOMPARE(injector.toHostCounts().frames, quint64(50));
        QCOMPARE(injector.toHostCounts().lost(), quint64(0));
    }

    void sameSeedSameRunOtherSeedOtherRun()
    {
        const FaultSpec s = spec(u"drop=0.05,corrupt=0.05,dup=0.05,delay=0.05:3ms"_s);
        FaultInjector a(s, 7, FaultInjector::Framing::V2);
        FaultInjector b(s, 7, FaultInjector::Framing::V2);
        FaultInjector c(s, 8, FaultInjector::Framing::V2);
        const QByteArray outA = runStream(a, 2000);
        QCOMPARE(runStream(b, 2000, 13), outA); // other chunking, same fates
        QCOMPARE(b.toHostCounts(), a.toHostCounts());
        QVERIFY(runStream(c, 2000) != outA);
    }

    void countsMatchWhatTheDecoderSees()
    {
        const int n = 20000;
        FaultInjector injector(spec(u"drop=0.01,corrupt=0.005,dup=0.002,delay=0.01:20ms"_s), 3,
                               FaultInjector::Framing::V2);
        const Decoded d = decode(runStream(injector, n));
        const FaultCounts &c = injector.toHostCounts();
        QCOMPARE(c.frames, quint64(n));
        // Roughly the probabilities asked for (binomial, several standard deviations wide).
        QVERIFY2(c.dropped > 140 && c.dropped < 260, qPrintable(QString::number(c.dropped)));
        QVERIFY(c.corrupted > 60 && c.corrupted < 140);
        QVERIFY(c.duplicated > 15 && c.duplicated < 65);
        QVERIFY(c.delayed > 140 && c.delayed < 260);
        // Every corrupted frame is caught by the CRC, and nothing else is dropped.
        QCOMPARE(d.stats.dropped(v2::DropReason::Crc), c.corrupted);
        QCOMPARE(d.stats.totalDropped(), c.corrupted);
        QCOMPARE(quint64(d.frames.size()), n - c.dropped - c.corrupted + c.duplicated);
        // Whatever decodes is a frame that was sent, intact and in order (a delay holds the
        // line); the gaps are the frames dropped or corrupted, the repeats those duplicated.
        qint64 previous = -1;
        quint64 gaps = 0, repeats = 0;
        for (const v2::Frame &frame : std::as_const(d.frames)) {
            const auto &t = std::get<v2::Telemetry>(frame.message);
            const qint64 index = t.t_us / 1000;
            QCOMPARE(v2::encodeFrame(frame.seq, t), telemetryFrame(int(index)));
            QVERIFY(index >= previous);
            if (index == previous)
                ++repeats;
            else
                gaps += quint64(index - previous - 1);
            previous = index;
        }
        gaps += quint64(n - 1 - previous);
        QCOMPARE(gaps, c.dropped + c.corrupted);
        QCOMPARE(repeats, c.duplicated);
        QCOMPARE(c.streamDuplicated, c.duplicated);
        QCOMPARE(c.streamLost, c.dropped);
        QCOMPARE(c.streamCorrupted, c.corrupted);
        QCOMPARE(injector.toHostSeen(), c); // everything released by now
    }

    void delayHoldsTheLineAndReleasesOnTime()
    {
        FaultInjector injector(spec(u"delay=1:20ms"_s), 1, FaultInjector::Framing::V2);
        const QByteArray one = telemetryFrame(1);
        QVERIFY(injector.toHost(one, 1.0).isEmpty());
        QVERIFY(injector.toHost(telemetryFrame(2), 1.001).isEmpty());
        QVERIFY(injector.toHost({}, 1.019).isEmpty());
        QCOMPARE(injector.toHost({}, 1.0205), one); // the second waits for its own 20 ms
        QCOMPARE(injector.toHost({}, 1.021), telemetryFrame(2));
        QCOMPARE(injector.toHostCounts().delayed, quint64(2));
    }

    void cutLosesBothDirectionsForItsTime()
    {
        FaultInjector injector(spec(u"cut=1s:500ms"_s), 1, FaultInjector::Framing::V2);
        QCOMPARE(injector.toHost(telemetryFrame(1), 0.999), telemetryFrame(1));
        QVERIFY(injector.toHost(telemetryFrame(2), 1.0).isEmpty());
        QVERIFY(injector.toDevice(telemetryFrame(3), 1.2).isEmpty());
        QVERIFY(injector.toHost(QByteArray(1, '\0'), 1.3).isEmpty());
        QCOMPARE(injector.toHost(telemetryFrame(4), 1.5), telemetryFrame(4));
        QCOMPARE(injector.toHostCounts().cut, quint64(1));
        QCOMPARE(injector.toHostCounts().streamLost, quint64(1));
        QCOMPARE(injector.toDeviceCounts().cut, quint64(1));
        QVERIFY(injector.cutAt(1.25));
        QVERIFY(!injector.cutAt(1.5));
    }

    void seenCountsALossOnlyWhenTheNextFramePasses()
    {
        FaultInjector injector(spec(u"hdrop=1"_s), 1, FaultInjector::Framing::V2);
        QVERIFY(injector.toDevice(telemetryFrame(1), 0).isEmpty());
        QCOMPARE(injector.toDeviceCounts().dropped, quint64(1));
        QCOMPARE(injector.toDeviceSeen().dropped, quint64(0));
        FaultInjector passing(spec(u"drop=0.5"_s), 11, FaultInjector::Framing::V2);
        quint64 delivered = 0;
        for (int i = 0; i < 200; ++i) {
            if (!passing.toHost(telemetryFrame(i), 0).isEmpty()) {
                ++delivered;
                QCOMPARE(passing.toHostSeen().dropped, passing.toHostCounts().dropped);
            }
        }
        QVERIFY(delivered > 50 && delivered < 150);
    }

    void onlyTelemetryIsAStreamFrame()
    {
        FaultInjector injector(spec(u"drop=1"_s), 1, FaultInjector::Framing::V2);
        injector.toHost(v2::encodeFrame(5, v2::Ack{5, v2::AckStatus::Ok, 0}), 0);
        injector.toHost(telemetryFrame(9), 0);
        QCOMPARE(injector.toHostCounts().dropped, quint64(2));
        QCOMPARE(injector.toHostCounts().streamLost, quint64(1));
    }

    void corruptionNeverMakesADelimiterOrAValidFrame()
    {
        // Frames full of bytes with a single bit set: the flip must still never yield 0x00.
        FaultInjector injector(spec(u"corrupt=1"_s), 5, FaultInjector::Framing::V2);
        for (int i = 0; i < 3000; ++i) {
            v2::Telemetry t;
            t.t_us = 0x01010101u << (i % 8);
            t.theta = 0;
            const QByteArray frame = v2::encodeFrame(quint8(1 << (i % 8)), t);
            const QByteArray out = injector.toHost(frame, 0);
            QCOMPARE(out.size(), frame.size());
            QCOMPARE(out.count('\0'), 1);
            QVERIFY(out.endsWith('\0'));
            const Decoded d = decode(out);
            QCOMPARE(d.frames.size(), 0);
            QCOMPARE(d.stats.dropped(v2::DropReason::Crc), std::uint64_t(1));
        }
        QCOMPARE(injector.toHostCounts().corrupted, quint64(3000));
    }

    void legacyFramesEndAtNewline()
    {
        FaultInjector injector(spec(u"drop=1"_s), 1, FaultInjector::Framing::Legacy);
        QVERIFY(injector.toHost("ia1b2c3d4o\r\nia5b6", 0).isEmpty());
        QCOMPARE(injector.toHostCounts().dropped, quint64(1));
        QVERIFY(injector.toHost("c7d8o\r\n", 0).isEmpty());
        QCOMPARE(injector.toHostCounts().streamLost, quint64(2));
    }

    void aRunWithoutDelimiterPassesUntouchedAndBounded()
    {
        FaultInjector injector(spec(u"drop=1"_s), 1, FaultInjector::Framing::V2);
        const QByteArray junk(FaultInjector::kMaxFrameBytes + 1, 'x');
        QCOMPARE(injector.toHost(junk, 0), junk);
        QCOMPARE(injector.toHostCounts().unframed, quint64(junk.size()));
        QCOMPARE(injector.toHostCounts().frames, quint64(0));
    }
};

QTEST_GUILESS_MAIN(TestFaultInjector)
#include "tst_faultinjector.moc"
