// fw::StsPacketParser (the STS3032 reply parser) on arbitrary bytes.
//
// Input: the byte stream, pushed one byte at a time; after each reported packet, next() drains
// the packets already buffered.
// Invariants:
// - every reported packet is well formed: FF FF, an id other than FF, LEN = params + 2 within
//   2 … kMaxParams + 2, and a checksum that matches (the parser never yields a bad one);
// - it agrees with a reference scan over the whole input written from servo.md's rules
//   (same packets, same counters);
// - bytes are accounted for: packet bytes + skipped bytes + pending = bytes pushed, and the
//   parser never holds more than kMaxPacketBytes.
#include "firmware/sts3032.h"
#include "fuzzcheck.h"

#include <algorithm>
#include <vector>

using namespace hatpic::fw;

namespace {

struct Reference
{
    std::vector<std::vector<std::uint8_t>> packets;
    std::uint32_t badChecksum = 0;
    std::uint32_t badLength = 0;
    std::uint32_t skipped = 0;
    std::size_t pending = 0;
};

//! The rules of servo.md § 1 applied to the whole input at once.
Reference referenceScan(std::span<const std::uint8_t> in)
{
    Reference r;
    std::size_t p = 0;
    const std::size_t n = in.size();
    while (p < n) {
        const bool badHeader =
            in[p] != 0xFF || (p + 1 < n && in[p + 1] != 0xFF) || (p + 2 < n && in[p + 2] == 0xFF);
        if (badHeader) {
            ++r.skipped;
            ++p;
            continue;
        }
        if (p + 4 > n)
            break;
        const std::size_t len = in[p + 3];
        if (len < 2 || len > sts::kMaxParams + 2) {
            ++r.badLength;
            ++r.skipped;
            ++p;
            continue;
        }
        if (p + len + 4 > n)
            break;
        unsigned sum = 0;
        for (std::size_t i = p + 2; i < p + len + 3; ++i)
            sum += in[i];
        if (static_cast<std::uint8_t>(~sum) != in[p + len + 3]) {
            ++r.badChecksum;
            ++r.skipped;
            ++p;
            continue;
        }
        r.packets.emplace_back(in.begin() + std::ptrdiff_t(p),
                               in.begin() + std::ptrdiff_t(p + len + 4));
        p += len + 4;
    }
    r.pending = n - p;
    return r;
}

void checkPacket(const StsPacketParser &parser)
{
    const std::span<const std::uint8_t> bytes = parser.packetBytes();
    const StsPacket packet = parser.packet();
    FUZZ_CHECK(bytes.size() >= sts::kPacketOverhead && bytes.size() <= sts::kMaxPacketBytes);
    FUZZ_CHECK(bytes[0] == 0xFF && bytes[1] == 0xFF && bytes[2] != 0xFF);
    FUZZ_CHECK(bytes[3] == packet.params.size() + 2);
    FUZZ_CHECK(packet.params.size() <= sts::kMaxParams);
    FUZZ_CHECK(packet.id == bytes[2] && packet.code == bytes[4]);
    FUZZ_CHECK(bytes.size() == packet.params.size() + sts::kPacketOverhead);
    FUZZ_CHECK(sts::checksum(packet.id, packet.code, packet.params) == bytes.back());
    FUZZ_CHECK(parser.missing() == 0);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::span<const std::uint8_t> in(data, size);
    StsPacketParser parser;
    std::vector<std::vector<std::uint8_t>> packets;
    std::size_t packetBytes = 0;
    for (const std::uint8_t byte : in) {
        for (bool have = parser.push(byte); have; have = parser.next()) {
            checkPacket(parser);
            const auto bytes = parser.packetBytes();
            packets.emplace_back(bytes.begin(), bytes.end());
            packetBytes += bytes.size();
        }
        FUZZ_CHECK(parser.pending() < sts::kMaxPacketBytes);
    }
    const Reference ref = referenceScan(in);
    const StsPacketParser::Stats &s = parser.stats();
    FUZZ_CHECK(packets == ref.packets);
    FUZZ_CHECK(s.packets == packets.size());
    FUZZ_CHECK(s.badChecksum == ref.badChecksum && s.badLength == ref.badLength);
    FUZZ_CHECK(s.skippedBytes == ref.skipped);
    FUZZ_CHECK(parser.pending() == ref.pending);
    FUZZ_CHECK(packetBytes + s.skippedBytes + parser.pending() == size);
    return 0;
}
