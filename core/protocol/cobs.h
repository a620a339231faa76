// Consistent Overhead Byte Stuffing (Cheshire & Baker), standard form: the framing of
// protocol v2 (protocol.md § 2). A frame on the wire is cobsEncode(packet) followed by 0x00.
//
// Plain C++20 shared by the host and the device core: no Qt, no OS calls, no allocation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace hatpic::v2 {

//! Largest encoding of `n` data bytes (one code byte per 254 data bytes, at least one).
constexpr std::size_t cobsMaxEncodedSize(std::size_t n)
{
    return n + n / 254 + 1;
}

//! Longest data one COBS block carries; up to this length the encoding is exactly one byte
//! longer than the data [bytes].
constexpr std::size_t kCobsBlockBytes = 254;

//! Encodes `data` into `out` (no delimiter appended). Returns the encoded length, or 0 when
//! `out` is too small (an encoding is never empty).
std::size_t cobsEncode(std::span<const std::uint8_t> data, std::span<std::uint8_t> out);

//! Encodes in place the data that `frame` holds from frame[1] on (frame[0] is free): the code
//! bytes go over frame[0] and over each zero, so `frame` ends up holding the same bytes
//! cobsEncode() writes. Returns frame.size(), or 0 when `frame` is empty or its data is longer
//! than kCobsBlockBytes.
std::size_t cobsEncodeInPlace(std::span<std::uint8_t> frame);

//! Decodes one frame body (without its delimiter) into `out`. `out` may be the same memory
//! as `encoded` (decoding in place never overtakes the input). Returns the decoded length, or
//! nullopt when the body is malformed (a 0x00 inside, a block running past the end) or `out`
//! is too small.
std::optional<std::size_t> cobsDecode(std::span<const std::uint8_t> encoded,
                                      std::span<std::uint8_t> out);

//! cobsDecode() of a body that holds no 0x00 byte (the bytes between two delimiters), which
//! it does not look for again. Same results as cobsDecode() for such a body.
std::optional<std::size_t> cobsDecodeBody(std::span<const std::uint8_t> encoded,
                                          std::span<std::uint8_t> out);

} // namespace hatpic::v2
