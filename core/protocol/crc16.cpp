#include "crc16.h"

#include <array>
#include <cstddef>

namespace hatpic::v2 {

namespace {

constexpr int kSlices = 8; //!< bytes folded per step

//! kTables[0] is the byte-at-a-time table; kTables[k][v] is the CRC contribution of byte v
//! followed by k zero bytes, so that eight bytes fold into the register with eight independent
//! look-ups instead of a chain of eight (slicing-by-8; the CRC is linear in its input).
using Tables = std::array<std::array<std::uint16_t, 256>, kSlices>;

constexpr Tables makeTables()
{
    Tables t{};
    for (std::size_t i = 0; i < 256; ++i) {
        auto crc = static_cast<std::uint16_t>(i << 8);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 0x8000) ? static_cast<std::uint16_t>((crc << 1) ^ 0x1021)
                                 : static_cast<std::uint16_t>(crc << 1);
        t[0][i] = crc;
    }
    for (std::size_t k = 1; k < kSlices; ++k) {
        for (std::size_t i = 0; i < 256; ++i) {
            const std::uint16_t prev = t[k - 1][i];
            t[k][i] = static_cast<std::uint16_t>((prev << 8) ^ t[0][prev >> 8]);
        }
    }
    return t;
}

constexpr Tables kTables = makeTables();

} // namespace

std::uint16_t crc16(std::span<const std::uint8_t> data)
{
    std::uint32_t crc = 0xFFFF;
    const std::uint8_t *p = data.data();
    std::size_t n = data.size();
    for (; n >= kSlices; n -= kSlices, p += kSlices) {
        crc = kTables[7][(crc >> 8) ^ p[0]] ^ kTables[6][(crc & 0xFF) ^ p[1]] ^ kTables[5][p[2]] ^
              kTables[4][p[3]] ^ kTables[3][p[4]] ^ kTables[2][p[5]] ^ kTables[1][p[6]] ^
              kTables[0][p[7]];
    }
    for (; n > 0; --n, ++p)
        crc = ((crc << 8) & 0xFFFF) ^ kTables[0][(crc >> 8) ^ *p];
    return static_cast<std::uint16_t>(crc);
}

} // namespace hatpic::v2
