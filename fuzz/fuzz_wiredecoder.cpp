// v2::WireDecoder on arbitrary bytes: the host side (Direction::FromDevice) when built with
// HATPIC_FUZZ_FROM_DEVICE=1, the device side (FromHost) otherwise.
//
// Input: byte 0 seeds the chunking, the rest is the byte stream.
// Invariants:
// - the memory bound: pendingBytes() ≤ kMaxFrameBytes after every chunk;
// - chunking does not matter: the frames and stats equal those of one feed of the whole stream;
// - the stats account for every frame: stats.bytes is what was fed, frames + drops equals the
//   number of non-empty delimited runs (plus one for a trailing run that overflowed), and the
//   frames yielded are stats.frames plus the UnknownType and BadLength drops (Refused);
// - a decoded message re-encodes, and the re-encoding decodes to a message that re-encodes to
//   the very same bytes (byte comparison, since NaN != NaN); a Refused frame never encodes.
#include "fuzzcheck.h"
#include "protocol/framecodec.h"

#include <algorithm>
#include <vector>

using namespace hatpic::v2;

namespace {

#if HATPIC_FUZZ_FROM_DEVICE
constexpr Direction kDirection = Direction::FromDevice;
#else
constexpr Direction kDirection = Direction::FromHost;
#endif

struct Decoded
{
    std::vector<Frame> frames;
    DecoderStats stats;
};

std::size_t encode(const Frame &frame, FrameBuffer &out)
{
    return encodeFrame(frame.seq, frame.message, out);
}

void checkReencoding(const Frame &frame)
{
    FrameBuffer first;
    const std::size_t n = encode(frame, first);
    if (std::holds_alternative<Refused>(frame.message)) {
        FUZZ_CHECK(n == 0);
        return;
    }
    FUZZ_CHECK(n > 0 && n <= kMaxWireFrameBytes);
    FUZZ_CHECK(first[n - 1] == 0);
    FUZZ_CHECK(std::find(first.begin(), first.begin() + std::ptrdiff_t(n - 1), 0) ==
               first.begin() + std::ptrdiff_t(n - 1));
    WireDecoder again(kDirection);
    int count = 0;
    again.feed(std::span<const std::uint8_t>(first.data(), n), [&](const Frame &back) {
        ++count;
        FUZZ_CHECK(back.seq == frame.seq);
        FUZZ_CHECK(back.message.index() == frame.message.index());
        FrameBuffer second;
        const std::size_t m = encode(back, second);
        FUZZ_CHECK(m == n &&
                   std::equal(first.begin(), first.begin() + std::ptrdiff_t(n), second.begin()));
    });
    FUZZ_CHECK(count == 1);
    FUZZ_CHECK(again.stats().frames == 1 && again.stats().totalDropped() == 0);
}

bool sameFrames(const std::vector<Frame> &a, const std::vector<Frame> &b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        FrameBuffer x, y;
        const std::size_t n = encode(a[i], x);
        const std::size_t m = encode(b[i], y);
        if (a[i].seq != b[i].seq || a[i].message.index() != b[i].message.index() || n != m ||
            !std::equal(x.begin(), x.begin() + std::ptrdiff_t(n), y.begin()))
            return false;
        if (n == 0 && !(a[i] == b[i])) // Refused: compared as values
            return false;
    }
    return true;
}

//! Non-empty runs ended by a delimiter, plus one for a trailing run too long to be a frame.
std::uint64_t expectedOutcomes(std::span<const std::uint8_t> bytes)
{
    std::uint64_t outcomes = 0;
    std::size_t run = 0;
    for (const std::uint8_t b : bytes) {
        if (b == 0) {
            outcomes += run > 0 ? 1 : 0;
            run = 0;
        } else {
            ++run;
        }
    }
    return outcomes + (run > WireDecoder::kMaxFrameBytes ? 1 : 0);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    fuzzcheck::XorShift rng(data[0]);
    const std::span<const std::uint8_t> stream(data + 1, size - 1);

    Decoded chunked;
    WireDecoder decoder(kDirection);
    for (std::span<const std::uint8_t> rest = stream; !rest.empty();) {
        const std::size_t n = std::min(rest.size(), rng.chunk(rng.next() % 4 == 0 ? 512 : 16));
        decoder.feed(rest.first(n), [&](const Frame &frame) { chunked.frames.push_back(frame); });
        FUZZ_CHECK(decoder.pendingBytes() <= WireDecoder::kMaxFrameBytes);
        rest = rest.subspan(n);
    }
    chunked.stats = decoder.stats();

    Decoded whole;
    WireDecoder oneFeed(kDirection);
    oneFeed.feed(stream, [&](const Frame &frame) { whole.frames.push_back(frame); });
    whole.stats = oneFeed.stats();

    FUZZ_CHECK(chunked.stats == whole.stats);
    FUZZ_CHECK(sameFrames(chunked.frames, whole.frames));

    const DecoderStats &s = chunked.stats;
    FUZZ_CHECK(s.bytes == stream.size());
    FUZZ_CHECK(s.frames + s.totalDropped() == expectedOutcomes(stream));
    FUZZ_CHECK(chunked.frames.size() ==
               s.frames + s.dropped(DropReason::UnknownType) + s.dropped(DropReason::BadLength));
    std::uint64_t refused = 0;
    for (const Frame &frame : chunked.frames) {
        refused += std::holds_alternative<Refused>(frame.message) ? 1 : 0;
        checkReencoding(frame);
    }
    FUZZ_CHECK(refused == s.dropped(DropReason::UnknownType) + s.dropped(DropReason::BadLength));
    return 0;
}
