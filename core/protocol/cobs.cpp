#include "cobs.h"

#include <bit>
#include <cstring>
#include <type_traits>

namespace hatpic::v2 {

namespace {

//! Calls `f(i)` for each i with data[i] == 0, in order. Looks at a machine word at a time:
//! a frame's few zeros are found without a branch per byte.
template<typename F> void forEachZero(const std::uint8_t *data, std::size_t n, F &&f)
{
    std::size_t i = 0;
    if constexpr (std::endian::native == std::endian::little) {
        using Word = std::conditional_t<sizeof(void *) >= 8, std::uint64_t, std::uint32_t>;
        constexpr Word k7F = static_cast<Word>(0x7F7F7F7F7F7F7F7FULL);
        for (; i + sizeof(Word) <= n; i += sizeof(Word)) {
            Word w;
            std::memcpy(&w, data + i, sizeof(Word));
            // The top bit of each byte that is zero, and of no other (no carry between bytes).
            Word zeros = static_cast<Word>(~(((w & k7F) + k7F) | w | k7F));
            while (zeros != 0) {
                f(i + static_cast<std::size_t>(std::countr_zero(zeros)) / 8);
                zeros &= zeros - 1;
            }
        }
    }
    for (; i < n; ++i) {
        if (data[i] == 0)
            f(i);
    }
}

//! Byte-by-byte decoding: every case, including full blocks (code 0xFF).
std::optional<std::size_t> decodeBytes(std::span<const std::uint8_t> encoded,
                                       std::span<std::uint8_t> out)
{
    std::size_t n = 0;
    std::size_t i = 0;
    while (i < encoded.size()) {
        const std::uint8_t code = encoded[i];
        if (code == 0)
            return std::nullopt; // a delimiter cannot occur inside a frame body
        const std::size_t end = i + code;
        if (end > encoded.size())
            return std::nullopt; // the block claims more bytes than the frame holds
        for (std::size_t k = i + 1; k < end; ++k) {
            if (encoded[k] == 0 || n >= out.size())
                return std::nullopt;
            out[n++] = encoded[k];
        }
        i = end;
        if (code != 0xFF && i < encoded.size()) {
            if (n >= out.size())
                return std::nullopt;
            out[n++] = 0;
        }
    }
    return n;
}

} // namespace

std::size_t cobsEncode(std::span<const std::uint8_t> data, std::span<std::uint8_t> out)
{
    if (out.size() < cobsMaxEncodedSize(data.size()))
        return 0;
    std::size_t codeIndex = 0;
    std::size_t n = 1; // out[0] is the first block's code byte, written when the block ends
    std::uint8_t code = 1;
    for (std::size_t i = 0; i < data.size(); ++i) {
        const std::uint8_t byte = data[i];
        if (byte == 0) {
            out[codeIndex] = code;
            codeIndex = n++;
            code = 1;
            continue;
        }
        out[n++] = byte;
        ++code;
        // A full block (254 data bytes) carries no implied zero. A new block is opened only
        // when more data follows, so a packet ending in a full block gets no trailing 0x01.
        if (code == 0xFF && i + 1 < data.size()) {
            out[codeIndex] = code;
            codeIndex = n++;
            code = 1;
        }
    }
    out[codeIndex] = code;
    return n;
}

std::size_t cobsEncodeInPlace(std::span<std::uint8_t> frame)
{
    if (frame.empty() || frame.size() - 1 > kCobsBlockBytes)
        return 0;
    // Without a full block every zero becomes the distance to the next zero (or to the end),
    // and frame[0] the distance to the first one.
    std::uint8_t *p = frame.data();
    std::size_t code = 0; // where the open block's code byte goes
    forEachZero(p + 1, frame.size() - 1, [&](std::size_t i) {
        const std::size_t at = i + 1;
        p[code] = static_cast<std::uint8_t>(at - code);
        code = at;
    });
    p[code] = static_cast<std::uint8_t>(frame.size() - code);
    return frame.size();
}

std::optional<std::size_t> cobsDecode(std::span<const std::uint8_t> encoded,
                                      std::span<std::uint8_t> out)
{
    if (std::memchr(encoded.data(), 0, encoded.size()) != nullptr)
        return std::nullopt; // a delimiter cannot occur inside a frame body
    return cobsDecodeBody(encoded, out);
}

std::optional<std::size_t> cobsDecodeBody(std::span<const std::uint8_t> encoded,
                                          std::span<std::uint8_t> out)
{
    const std::size_t n = encoded.size();
    if (n == 0)
        return 0;
    // Follow the chain of code bytes. Without a full block (code 0xFF, which the byte-by-byte
    // path handles) the data is the body without its first byte, with a zero at each later
    // code byte, and the chain must end exactly at the end of the body.
    std::size_t at = 0;
    while (at < n) {
        const std::uint8_t code = encoded[at];
        if (code == 0)
            return std::nullopt;
        if (code == 0xFF)
            return decodeBytes(encoded, out);
        at += code;
    }
    if (at != n || out.size() < n - 1)
        return std::nullopt; // a block runs past the end, or no room
    const std::uint8_t first = encoded[0];
    std::memmove(out.data(), encoded.data() + 1, n - 1); // may overlap: in place
    for (at = first; at < n;) {
        const std::uint8_t code = out[at - 1]; // encoded[at], moved down by one
        out[at - 1] = 0;
        at += code;
    }
    return n - 1;
}

} // namespace hatpic::v2
