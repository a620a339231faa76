// Seeded random tests of the v2 codec and decoder: round trips in random chunkings, bit
// flips, garbage, truncation, and the rate at which corrupted frames slip through the CRC.
//
// HATPIC_FUZZ_COUNT (default 10000) sets the number of messages per stream; the corruption
// rate test damages 100 times as many frames.
#include "v2testutil.h"

#include <QElapsedTimer>
#include <QTest>

#include <algorithm>
#include <array>
#include <cmath>

using namespace hatpic;
using namespace hatpic::v2;
using namespace v2test;

Q_DECLARE_METATYPE(hatpic::v2::Direction)

namespace {

constexpr double kCrcMissRate = 1.0 / 65536.0; //!< undetected-error rate of a 16-bit CRC
constexpr double kSignificance = 1e-9;         //!< false-alarm probability of a rate bound

//! Smallest k with P(X > k) ≤ alpha for X ~ Binomial(n, p).
quint64 binomialUpperBound(quint64 n, double p, double alpha)
{
    double pmf = std::exp(double(n) * std::log1p(-p)); // P(X = 0)
    double cdf = pmf;
    quint64 k = 0;
    while (1.0 - cdf > alpha && k < n) {
        pmf *= double(n - k) / double(k + 1) * p / (1.0 - p);
        cdf += pmf;
        ++k;
    }
    return k;
}

//! Feeds `stream` in random chunk sizes (1 byte … 4 KiB, mostly small) and checks the
//! decoder's memory bound after every chunk.
bool feedChunked(FrameDecoder &decoder, QByteArrayView stream, QRandomGenerator &rng,
                 QList<Frame> &out)
{
    while (!stream.isEmpty()) {
        qsizetype n = 0;
        switch (rng.bounded(8)) {
        case 0:
            n = 1;
            break;
        case 1:
            n = 1 + rng.bounded(4096);
            break;
        default:
            n = 1 + rng.bounded(64);
        }
        n = std::min(n, stream.size());
        decoder.feed(stream.first(n), out);
        stream = stream.sliced(n);
        if (decoder.pendingBytes() > FrameDecoder::kMaxFrameBytes)
            return false;
    }
    return true;
}

} // namespace

class TestV2Fuzz : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void directions_data()
    {
        QTest::addColumn<Direction>("receiver");
        QTest::addColumn<quint32>("seed");
        QTest::newRow("device to host") << Direction::FromDevice << 0x5EED0001u;
        QTest::newRow("host to device") << Direction::FromHost << 0x5EED0002u;
    }

    //! Random messages back to back, random chunking: the same sequence comes out, no drops.
    void randomStreamRoundTrip_data() { directions_data(); }
    void randomStreamRoundTrip()
    {
        QFETCH(Direction, receiver);
        QFETCH(quint32, seed);
        QRandomGenerator rng(seed);
        const int count = fuzzCount();

        QList<Frame> expected;
        expected.reserve(count);
        QByteArray stream;
        for (int i = 0; i < count; ++i) {
            Frame f{quint8(rng.bounded(256)), randomMessage(rng, receiver)};
            const QByteArray wire = encodeFrame(f.seq, f.message);
            QVERIFY(!wire.isEmpty());
            stream += wire;
            expected.append(std::move(f));
        }

        FrameDecoder decoder(receiver);
        QList<Frame> out;
        QVERIFY(feedChunked(decoder, stream, rng, out));
        QCOMPARE(out.size(), expected.size());
        for (int i = 0; i < count; ++i)
            QCOMPARE(out[i], expected[i]);
        QCOMPARE(decoder.stats().frames, quint64(count));
        QCOMPARE(decoder.stats().totalDropped(), quint64(0));
        QCOMPARE(decoder.stats().bytes, quint64(stream.size()));
        QCOMPARE(decoder.pendingBytes(), 0);
    }

    //! Every single-bit flip of every byte of an encoded frame is rejected: nothing but the
    //! intact frame that follows comes out (and that one too is lost only when the flip hit
    //! the delimiter, merging both frames).
    void singleBitFlipsRejected_data() { directions_data(); }
    void singleBitFlipsRejected()
    {
        QFETCH(Direction, receiver);
        QFETCH(quint32, seed);
        QRandomGenerator rng(seed ^ 0xF11Fu);

        QList<QByteArray> wires;
        for (int i = 0; i < 120; ++i)
            wires.append(encodeFrame(quint8(rng.bounded(256)), randomMessage(rng, receiver)));
        const Frame sentinel = receiver == Direction::FromHost ? Frame{0x5A, Ping{0x01020304}}
                                                               : Frame{0x5A, Pong{0x01020304}};
        const QByteArray sentinelWire = encodeFrame(sentinel.seq, sentinel.message);

        quint64 flips = 0;
        quint64 reachedCrc = 0;
        for (const QByteArray &wire : std::as_const(wires)) {
            for (qsizetype i = 0; i < wire.size(); ++i) {
                for (int bit = 0; bit < 8; ++bit) {
                    QByteArray damaged = wire;
                    damaged[i] = char(damaged[i] ^ (1 << bit));
                    damaged += sentinelWire;
                    FrameDecoder decoder(receiver);
                    QList<Frame> out;
                    decoder.feed(damaged, out);
                    ++flips;
                    reachedCrc += decoder.stats().dropped(DropReason::Crc);
                    const bool delimiterHit = i == wire.size() - 1;
                    const QList<Frame> expected =
                        delimiterHit ? QList<Frame>{} : QList<Frame>{sentinel};
                    if (delimiterHit && out == QList<Frame>{sentinel})
                        continue; // the merged frame failed, the sentinel survived anyway
                    QVERIFY2(out == expected,
                             qPrintable(QStringLiteral("frame %1 byte %2 bit %3: %4 frames out")
                                            .arg(QString::fromLatin1(wire.toHex(' ')))
                                            .arg(i)
                                            .arg(bit)
                                            .arg(out.size())));
                }
            }
        }
        qInfo("%llu single-bit flips, %llu reached the CRC check, all rejected", flips, reachedCrc);
    }

    //! Damages many frames at random places (several bytes each) and measures how many the
    //! decoder still accepts. A 16-bit CRC lets about 1 in 65536 random errors through; the
    //! count must stay under the binomial upper bound for that rate.
    void corruptionAcceptanceRate_data()
    {
        QTest::addColumn<bool>("damagePacket");
        QTest::newRow("wire bytes replaced") << false;
        QTest::newRow("packet bytes replaced, COBS intact") << true;
    }
    void corruptionAcceptanceRate()
    {
        QFETCH(bool, damagePacket);
        QRandomGenerator rng(damagePacket ? 0xBAD0001u : 0xBAD0002u);
        const quint64 trials = quint64(fuzzCount()) * 100;

        // A pool of good packets of both directions (the receiver below knows only one
        // direction; the other gives UNKNOWN_TYPE refusals, which count as accepted by the CRC).
        QList<QByteArray> packets;
        for (int i = 0; i < 4096; ++i) {
            const Direction side = i % 2 ? Direction::FromDevice : Direction::FromHost;
            const QByteArray wire = encodeFrame(quint8(rng.bounded(256)), randomMessage(rng, side));
            QByteArray packet;
            QVERIFY(cobsDecode(QByteArrayView(wire).chopped(1), packet));
            packets.append(damagePacket ? packet : wire.chopped(1));
        }

        QElapsedTimer timer;
        timer.start();
        FrameDecoder decoder(Direction::FromDevice);
        QList<Frame> out;
        for (quint64 t = 0; t < trials; ++t) {
            QByteArray bytes = packets[rng.bounded(int(packets.size()))];
            // 2…6 distinct bytes, each changed (so the frame always differs from the original).
            const int damage = std::min(2 + int(rng.bounded(5)), int(bytes.size()));
            std::array<qsizetype, 6> positions{};
            for (int k = 0; k < damage; ++k) {
                qsizetype pos = 0;
                do
                    pos = rng.bounded(int(bytes.size()));
                while (std::find(positions.begin(), positions.begin() + k, pos) !=
                       positions.begin() + k);
                positions[std::size_t(k)] = pos;
                char value = 0;
                do {
                    // On the wire a replacement byte is never a delimiter (that would split
                    // the frame, which the stream test covers).
                    value = char(damagePacket ? rng.bounded(256) : 1 + rng.bounded(255));
                } while (value == bytes[pos]);
                bytes[pos] = value;
            }
            QByteArray wire = damagePacket ? cobsEncode(bytes) : bytes;
            wire.append('\0');
            decoder.feed(wire, out);
            if (out.size() > 1024)
                out.clear();
        }
        const DecoderStats &s = decoder.stats();
        const quint64 accepted =
            s.frames + s.dropped(DropReason::UnknownType) + s.dropped(DropReason::BadLength);
        QCOMPARE(s.frames + s.totalDropped(), trials); // every damaged frame is accounted for
        QCOMPARE(s.dropped(DropReason::Overflow), quint64(0));
        if (damagePacket) {
            // Intact COBS and length: every frame reaches the CRC check.
            QCOMPARE(s.dropped(DropReason::Cobs) + s.dropped(DropReason::Short), quint64(0));
        }
        const quint64 bound = binomialUpperBound(trials, kCrcMissRate, kSignificance);
        qInfo("%llu damaged frames: %llu accepted (rate %.3g, 1/65536 = %.3g, bound %llu); "
              "dropped: COBS %llu, short %llu, CRC %llu; %lld ms",
              trials, accepted, double(accepted) / double(trials), kCrcMissRate, bound,
              quint64(s.dropped(DropReason::Cobs)), quint64(s.dropped(DropReason::Short)),
              quint64(s.dropped(DropReason::Crc)), timer.elapsed());
        QVERIFY2(accepted <= bound,
                 qPrintable(QStringLiteral("%1 of %2 damaged frames accepted, bound %3")
                                .arg(accepted)
                                .arg(trials)
                                .arg(bound)));
    }

    //! A stream with bit flips, truncated frames, inserted and deleted bytes and garbage
    //! (with and without delimiters, short and over-long): the decoder never loses more than
    //! the frames up to the next delimiter — every intact frame that follows a 0x00 is
    //! decoded, in order — and its buffer stays bounded.
    void damagedStreamResynchronises_data() { directions_data(); }
    void damagedStreamResynchronises()
    {
        QFETCH(Direction, receiver);
        QFETCH(quint32, seed);
        QRandomGenerator rng(seed ^ 0xDA4A6Eu);
        const int count = fuzzCount();

        const auto garbage = [&rng](int length, bool allowZero) {
            QByteArray g(length, Qt::Uninitialized);
            for (char &c : g)
                c = char(allowZero ? rng.bounded(256) : 1 + rng.bounded(255));
            return g;
        };

        QByteArray stream;
        QList<Frame> expected;
        int damagedCount = 0;
        for (int i = 0; i < count; ++i) {
            const Frame f{quint8(i), randomMessage(rng, receiver)};
            QByteArray wire = encodeFrame(f.seq, f.message);
            bool intact = false;
            switch (rng.bounded(20)) {
            case 0:
            case 1: { // one bit flipped anywhere, delimiter included
                const qsizetype pos = rng.bounded(int(wire.size()));
                wire[pos] = char(wire[pos] ^ (1 << rng.bounded(8)));
                break;
            }
            // Truncation and deletion always take a body byte: a frame that lost only its
            // delimiter is intact and decodes when a later garbage or extra 0x00 ends it.
            // Deletion spares the first byte, or a frame cut to its first byte followed by a
            // frame that lost its (equal) first byte would put together an intact frame.
            case 2:
            case 3: // truncated: the tail (at least the last CRC byte) and the delimiter lost
                wire.truncate(rng.bounded(int(wire.size()) - 1));
                break;
            case 4: // one body byte after the first deleted
                wire.remove(1 + rng.bounded(int(wire.size()) - 2), 1);
                break;
            case 5: // one random byte (not a delimiter) inserted before the delimiter
                wire.insert(rng.bounded(int(wire.size())), char(1 + rng.bounded(255)));
                break;
            case 6: // short garbage, may contain delimiters, then the intact frame
                stream += garbage(int(rng.bounded(64)), true);
                intact = true;
                break;
            case 7: // over-long garbage without delimiter, then the intact frame
                stream += garbage(257 + int(rng.bounded(1000)), false);
                intact = true;
                break;
            case 8: // an extra delimiter before the frame
                stream += '\0';
                intact = true;
                break;
            default:
                intact = true;
            }
            if (!intact)
                ++damagedCount;
            if (intact && (stream.isEmpty() || stream.back() == '\0'))
                expected.append(f);
            stream += wire;
        }

        FrameDecoder decoder(receiver);
        QList<Frame> out;
        QVERIFY(feedChunked(decoder, stream, rng, out));

        // Expected frames must appear in order; anything else is a damaged frame or garbage
        // that slipped through the CRC.
        qsizetype next = 0;
        quint64 extras = 0;
        for (const Frame &f : std::as_const(out)) {
            if (next < expected.size() && f == expected[next])
                ++next;
            else
                ++extras;
        }
        QVERIFY2(
            next == expected.size(),
            qPrintable(
                QStringLiteral("expected frame %1 of %2 missing").arg(next).arg(expected.size())));
        const quint64 junkFrames = decoder.stats().totalDropped() + extras;
        const quint64 bound = binomialUpperBound(junkFrames, kCrcMissRate, kSignificance);
        qInfo("%d frames, %d damaged, %lld intact after a delimiter, %llu frames dropped, "
              "%llu extra accepted (bound %llu)",
              count, damagedCount, qlonglong(expected.size()),
              quint64(decoder.stats().totalDropped()), extras, bound);
        QVERIFY(extras <= bound);
    }

    //! Pure garbage of any zero density: never crashes, stays bounded, and a good frame after
    //! the next delimiter is decoded.
    void garbageThenGoodFrame_data()
    {
        QTest::addColumn<Direction>("receiver");
        QTest::addColumn<int>("zeroOneIn");
        for (const auto &[name, direction] : {std::pair{"device to host", Direction::FromDevice},
                                              std::pair{"host to device", Direction::FromHost}}) {
            for (const int z : {0, 2, 8, 256, 100000})
                QTest::addRow("%s, zero one in %d", name, z) << direction << z;
        }
    }
    void garbageThenGoodFrame()
    {
        QFETCH(Direction, receiver);
        QFETCH(int, zeroOneIn);
        QRandomGenerator rng(quint32(zeroOneIn) * 7919u + quint32(receiver));
        QByteArray g(1 << 20, Qt::Uninitialized);
        for (char &c : g)
            c = zeroOneIn && rng.bounded(zeroOneIn) == 0 ? '\0' : char(1 + rng.bounded(255));
        FrameDecoder decoder(receiver);
        QList<Frame> out;
        QVERIFY(feedChunked(decoder, g, rng, out));
        out.clear();
        const Frame good = receiver == Direction::FromHost ? Frame{1, Hello{}} : Frame{1, Pong{42}};
        decoder.feed(QByteArray(1, '\0'), out);
        decoder.feed(encodeFrame(good.seq, good.message), out);
        QCOMPARE(out, QList<Frame>{good});
    }
};

QTEST_GUILESS_MAIN(TestV2Fuzz)
#include "tst_v2fuzz.moc"
