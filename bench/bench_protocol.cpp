// bench_protocol [--frames N]
//
// Protocol v2's frame codec on this machine (docs/performance.md, "The wire codec"):
//   decode, device core: WireDecoder (the fixed-buffer decoder the device core and the host
//           share) fed a stream of TELEMETRY frames (31 bytes, the host's traffic) and of
//           SET_FEEDBACK frames (11 bytes, the device's) in 64-byte chunks;
//   encode, device core: encodeFrame() of a TELEMETRY frame into the caller's buffer;
//   host's Qt adaptor: FrameDecoder::feed into a reused QList<Frame>, and encodeFrame()
//           returning a QByteArray.
// Prints ns of CPU time per frame (best of 5 runs), frames per second of one core, and the
// heap allocations per frame (counted by this program's operator new).
#include "benchclock.h"

#include "protocol/framecodec.h"
#include "protocol/v2codec.h"

#include <QByteArray>
#include <QList>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

using namespace hatpic;

namespace {

std::atomic<std::uint64_t> g_allocations{0};

} // namespace

// Counts every heap allocation of the program (operator new and QByteArray both end in these);
// the figures take the difference around a run.
extern "C" {
void *__libc_malloc(std::size_t size);
void *__libc_calloc(std::size_t n, std::size_t size);
void *__libc_realloc(void *p, std::size_t size);

void *malloc(std::size_t size) noexcept
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    return __libc_malloc(size);
}
void *calloc(std::size_t n, std::size_t size) noexcept
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    return __libc_calloc(n, size);
}
void *realloc(void *p, std::size_t size) noexcept
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    return __libc_realloc(p, size);
}
}

namespace {

constexpr std::size_t kChunk = 64; //!< bytes per feed() call

//! Telemetry that looks like a session: a knob moving slowly, torques around zero, some
//! exact zeros (τ_ext without feedback), so COBS sees the zero bytes it sees on the wire.
std::vector<v2::Telemetry> telemetry(std::size_t n)
{
    std::mt19937 rng(42);
    std::normal_distribution<float> noise(0.0f, 0.01f);
    std::vector<v2::Telemetry> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        v2::Telemetry &t = out[i];
        t.t_us = std::uint32_t(1000 * i);
        t.theta = 0.3f * std::sin(float(i) * 1e-3f) + noise(rng);
        t.omega = 0.3f * std::cos(float(i) * 1e-3f) + noise(rng);
        t.tau = noise(rng);
        t.tau_rec = -0.5f * t.theta;
        t.tau_ext = (i / 500) % 2 ? noise(rng) : 0.0f;
        t.flags = std::uint8_t(std::abs(t.theta) < 0.02f ? v2::kFlagDeadZone : v2::kFlagNotch);
    }
    return out;
}

//! The frames one after another, as a link carries them.
template<typename Messages> std::vector<std::uint8_t> wire(const Messages &messages)
{
    std::vector<std::uint8_t> bytes;
    v2::FrameBuffer frame;
    std::uint8_t seq = 0;
    for (const auto &m : messages) {
        const std::size_t n = v2::encodeFrame(seq++, m, frame);
        bytes.insert(bytes.end(), frame.begin(), frame.begin() + std::ptrdiff_t(n));
    }
    return bytes;
}

struct Figure
{
    double ns = 0;            //!< CPU time per frame [ns]
    double allocations = 0;   //!< heap allocations per frame
    std::uint64_t frames = 0; //!< frames the last run yielded (checked against the input)
};

void print(const char *what, const Figure &f, std::size_t bytesPerFrame)
{
    std::printf("%-44s %7.1f ns/frame  %6.2f M frames/s  %6.0f MB/s  %5.2f allocations/frame\n",
                what, f.ns, 1e3 / f.ns, double(bytesPerFrame) * 1e3 / f.ns, f.allocations);
}

//! Feeds `bytes` in 64-byte chunks to a fresh WireDecoder `passes` times.
Figure decodeWire(const std::vector<std::uint8_t> &bytes, v2::Direction direction,
                  std::size_t frames, long passes)
{
    Figure f;
    volatile std::uint32_t sink = 0;
    const std::uint64_t a0 = g_allocations.load();
    f.ns = benchclock::bestNsPer(long(frames) * passes, [&](long) {
        v2::WireDecoder decoder(direction);
        std::uint32_t sum = 0;
        for (long p = 0; p < passes; ++p) {
            for (std::size_t at = 0; at < bytes.size(); at += kChunk) {
                const std::size_t n = std::min(kChunk, bytes.size() - at);
                decoder.feed({bytes.data() + at, n}, [&sum](const v2::Frame &frame) {
                    sum += frame.seq + std::uint32_t(frame.message.index());
                });
            }
        }
        f.frames = decoder.stats().frames;
        sink = sink + sum;
    });
    f.allocations = double(g_allocations.load() - a0) / double(5 * frames * std::size_t(passes));
    return f;
}

Figure decodeQt(const std::vector<std::uint8_t> &bytes, std::size_t frames, long passes)
{
    Figure f;
    volatile std::uint32_t sink = 0;
    const std::uint64_t a0 = g_allocations.load();
    QList<v2::Frame> out;
    out.reserve(16);
    f.ns = benchclock::bestNsPer(long(frames) * passes, [&](long) {
        v2::FrameDecoder decoder(v2::Direction::FromDevice);
        std::uint32_t sum = 0;
        std::uint64_t yielded = 0;
        for (long p = 0; p < passes; ++p) {
            for (std::size_t at = 0; at < bytes.size(); at += kChunk) {
                const std::size_t n = std::min(kChunk, bytes.size() - at);
                out.clear(); // keeps its capacity, as the session's list does
                decoder.feed(
                    QByteArrayView(reinterpret_cast<const char *>(bytes.data() + at), qsizetype(n)),
                    out);
                for (const v2::Frame &frame : std::as_const(out))
                    sum += frame.seq;
                yielded += std::uint64_t(out.size());
            }
        }
        f.frames = yielded;
        sink = sink + sum;
    });
    f.allocations = double(g_allocations.load() - a0) / double(5 * frames * std::size_t(passes));
    return f;
}

Figure encodeWire(const std::vector<v2::Telemetry> &messages, long passes)
{
    Figure f;
    volatile std::uint32_t sink = 0;
    v2::FrameBuffer buffer;
    const std::uint64_t a0 = g_allocations.load();
    f.ns = benchclock::bestNsPer(long(messages.size()) * passes, [&](long) {
        std::uint32_t sum = 0;
        std::uint8_t seq = 0;
        for (long p = 0; p < passes; ++p) {
            for (const v2::Telemetry &m : messages)
                sum += std::uint32_t(v2::encodeFrame(seq++, m, buffer)) + buffer[5];
        }
        sink = sink + sum;
    });
    f.frames = messages.size();
    f.allocations =
        double(g_allocations.load() - a0) / double(5 * messages.size() * std::size_t(passes));
    return f;
}

Figure encodeQt(const std::vector<v2::Telemetry> &messages, long passes)
{
    Figure f;
    volatile std::uint32_t sink = 0;
    const std::uint64_t a0 = g_allocations.load();
    f.ns = benchclock::bestNsPer(long(messages.size()) * passes, [&](long) {
        std::uint32_t sum = 0;
        std::uint8_t seq = 0;
        for (long p = 0; p < passes; ++p) {
            for (const v2::Telemetry &m : messages)
                sum += std::uint32_t(v2::encodeFrame(seq++, m).size());
        }
        sink = sink + sum;
    });
    f.frames = messages.size();
    f.allocations =
        double(g_allocations.load() - a0) / double(5 * messages.size() * std::size_t(passes));
    return f;
}

bool check(const char *what, std::uint64_t got, std::uint64_t want)
{
    if (got == want)
        return true;
    std::fprintf(stderr, "bench_protocol: %s yielded %llu frames, expected %llu\n", what,
                 static_cast<unsigned long long>(got), static_cast<unsigned long long>(want));
    return false;
}

} // namespace

int main(int argc, char **argv)
{
    long passes = 100;
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::strcmp(argv[i], "--passes") == 0)
            passes = std::max(1L, std::atol(argv[i + 1]));
    }
    constexpr std::size_t kFrames = 4096;
    const std::vector<v2::Telemetry> tm = telemetry(kFrames);
    const std::vector<std::uint8_t> tmWire = wire(tm);
    std::vector<v2::SetFeedback> fb(kFrames);
    for (std::size_t i = 0; i < kFrames; ++i)
        fb[i].tauExt = i % 3 ? 0.01f * float(i % 17) : 0.0f;
    const std::vector<std::uint8_t> fbWire = wire(fb);
    const std::size_t tmBytes = tmWire.size() / kFrames;
    const std::size_t fbBytes = fbWire.size() / kFrames;

    std::printf("protocol v2 codec: %zu frames x %ld passes per run, %zu-byte chunks, "
                "CPU time of this thread, best of 5\n",
                kFrames, passes, kChunk);
    bool ok = true;
    const Figure dTm = decodeWire(tmWire, v2::Direction::FromDevice, kFrames, passes);
    ok &= check("decode TELEMETRY", dTm.frames, kFrames * std::uint64_t(passes));
    print("decode TELEMETRY, WireDecoder", dTm, tmBytes);
    const Figure dFb = decodeWire(fbWire, v2::Direction::FromHost, kFrames, passes);
    ok &= check("decode SET_FEEDBACK", dFb.frames, kFrames * std::uint64_t(passes));
    print("decode SET_FEEDBACK, WireDecoder", dFb, fbBytes);
    print("encode TELEMETRY, encodeFrame into a buffer", encodeWire(tm, passes), tmBytes);
    const Figure qd = decodeQt(tmWire, kFrames, passes / 4 + 1);
    ok &= check("Qt decode", qd.frames, kFrames * std::uint64_t(passes / 4 + 1));
    print("decode TELEMETRY, Qt FrameDecoder -> QList", qd, tmBytes);
    print("encode TELEMETRY, Qt encodeFrame -> QByteArray", encodeQt(tm, passes / 4 + 1), tmBytes);
    return ok ? 0 : 1;
}
