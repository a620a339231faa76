#include "cobs.h"

namespace hatpic::v2 {

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

std::optional<std::size_t> cobsDecode(std::span<const std::uint8_t> encoded,
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

} // namespace hatpic::v2
