// The record NvsParamStore keeps in NVS: StoredSettings as a versioned, CRC-checked byte block.
//
// Portable C++20 (no Arduino, no allocation): scripts/check-firmware compiles it with the
// device core, and it is the only part of the store whose bytes matter across firmware updates.
#pragma once

#include "firmware/paramstore.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace hatpic::esp32 {

//! Layout version; a blob of another version is ignored (power-up then uses the defaults).
//! Version 2 added the effect block (effects.md § 3); a version-1 blob (parameters only) is
//! still read, with the effects at their defaults. Version 3 added the passivity block
//! (passivity.md); older blobs are read with it at its defaults (the controller on).
inline constexpr std::uint16_t kSettingsBlobVersion = 3;
//! 7 × f32 in ParamBlock order (protocol.md § 3), 7 × f32 of the effect block, then 2 × f32
//! of the passivity block [bytes].
inline constexpr std::size_t kSettingsPayloadBytes =
    4 * (DeviceParams::kFieldCount + EffectParams::kFieldCount + PassivityParams::kFieldCount);
//! u16 version | u16 payload length | payload | u16 CRC-16/CCITT-FALSE of everything before it,
//! all little-endian [bytes].
inline constexpr std::size_t kSettingsBlobBytes = 2 + 2 + kSettingsPayloadBytes + 2;

using SettingsBlob = std::array<std::uint8_t, kSettingsBlobBytes>;

//! The blob for `settings` (each field rounded to f32, as the device holds it).
SettingsBlob encodeSettingsBlob(const fw::StoredSettings &settings);

//! Reads a blob back. False, and `out` untouched, when `bytes` has the wrong size, version or
//! length, or its CRC does not match. The values are not validated: the device core does that.
bool decodeSettingsBlob(std::span<const std::uint8_t> bytes, fw::StoredSettings &out);

} // namespace hatpic::esp32
