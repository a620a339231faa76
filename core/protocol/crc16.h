// CRC-16/CCITT-FALSE, the checksum of every protocol v2 packet (protocol.md § 2).
//
// Plain C++20 shared by the host and the device core: no Qt, no OS calls, no allocation.
#pragma once

#include <cstdint>
#include <span>

namespace hatpic::v2 {

//! Poly 0x1021, init 0xFFFF, no reflection, xorout 0; "123456789" gives 0x29B1.
std::uint16_t crc16(std::span<const std::uint8_t> data);

} // namespace hatpic::v2
