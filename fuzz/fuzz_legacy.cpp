// legacy::Decoder (the published firmware's ASCII protocol) on arbitrary bytes.
//
// Input: byte 0 seeds the chunking, the rest is the byte stream.
// Invariants:
// - memory is bounded: pendingBytes() ≤ kMaxFrameBytes + kMaxLineBytes after every chunk;
// - chunking does not matter: frames, text lines and stats equal those of one feed;
// - stats.bytes is what was fed, stats.frames the frames returned; text lines are at most
//   kMaxLineBytes long;
// - every frame has fields within ±kFieldLimit, and its encoding decodes to the same frame.
#include "fuzzcheck.h"
#include "protocol/legacy.h"

#include <algorithm>
#include <cstdlib>

using namespace hatpic::legacy;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    fuzzcheck::XorShift rng(data[0]);
    const QByteArrayView stream(reinterpret_cast<const char *>(data + 1), qsizetype(size - 1));

    Decoder chunked;
    QList<Frame> frames;
    QStringList text;
    for (QByteArrayView rest = stream; !rest.isEmpty();) {
        const qsizetype n = std::min(rest.size(), qsizetype(rng.chunk(rng.next() % 4 ? 8 : 300)));
        chunked.feed(rest.first(n), frames, &text);
        FUZZ_CHECK(chunked.pendingBytes() <= Decoder::kMaxFrameBytes + Decoder::kMaxLineBytes);
        rest = rest.sliced(n);
    }

    Decoder whole;
    QList<Frame> wholeFrames;
    QStringList wholeText;
    whole.feed(stream, wholeFrames, &wholeText);
    FUZZ_CHECK(whole.stats() == chunked.stats());
    FUZZ_CHECK(wholeFrames == frames);
    FUZZ_CHECK(wholeText == text);

    const DecoderStats &s = chunked.stats();
    FUZZ_CHECK(s.bytes == quint64(stream.size()));
    FUZZ_CHECK(s.frames == quint64(frames.size()));
    FUZZ_CHECK(s.tiltFrames == quint64(std::count_if(frames.cbegin(), frames.cend(),
                                                     [](const Frame &f) { return bool(f.tilt); })));
    for (const QString &line : std::as_const(text))
        FUZZ_CHECK(line.size() <= Decoder::kMaxLineBytes);
    for (const Frame &f : std::as_const(frames)) {
        for (const int v : f.fields())
            FUZZ_CHECK(std::abs(v) <= kFieldLimit);
        if (f.tilt)
            FUZZ_CHECK(std::abs(f.tilt->roll) <= kFieldLimit &&
                       std::abs(f.tilt->pitch) <= kFieldLimit);
        Decoder again;
        QList<Frame> back;
        again.feed(QByteArray(encodeFrame(f) + "\r\n"), back);
        FUZZ_CHECK(back.size() == 1 && back.first() == f);
        FUZZ_CHECK(again.stats().malformed == 0 && again.stats().textLines == 0);
    }
    return 0;
}
