#include "settingsblob.h"

#include "protocol/crc16.h"

#include <bit>

namespace hatpic::esp32 {

namespace {

constexpr std::size_t kCrcOffset = kSettingsBlobBytes - 2;
constexpr std::size_t kVersion1PayloadBytes = 4 * DeviceParams::kFieldCount;
constexpr std::size_t kVersion2PayloadBytes =
    4 * (DeviceParams::kFieldCount + EffectParams::kFieldCount);

void putF32(std::uint8_t *at, double value)
{
    const auto bits = std::bit_cast<std::uint32_t>(static_cast<float>(value));
    for (int b = 0; b < 4; ++b)
        at[b] = static_cast<std::uint8_t>(bits >> (8 * b));
}

double getF32(const std::uint8_t *at)
{
    std::uint32_t bits = 0;
    for (int b = 0; b < 4; ++b)
        bits |= std::uint32_t{at[b]} << (8 * b);
    return static_cast<double>(std::bit_cast<float>(bits));
}

void putU16(std::uint8_t *at, std::uint16_t value)
{
    at[0] = static_cast<std::uint8_t>(value & 0xFF);
    at[1] = static_cast<std::uint8_t>(value >> 8);
}

std::uint16_t getU16(const std::uint8_t *at)
{
    return static_cast<std::uint16_t>(at[0] | (at[1] << 8));
}

} // namespace

SettingsBlob encodeSettingsBlob(const fw::StoredSettings &settings)
{
    SettingsBlob blob{};
    putU16(&blob[0], kSettingsBlobVersion);
    putU16(&blob[2], static_cast<std::uint16_t>(kSettingsPayloadBytes));
    std::uint8_t *at = &blob[4];
    for (int i = 0; i < DeviceParams::kFieldCount; ++i, at += 4)
        putF32(at, settings.params.field(i));
    for (int i = 0; i < EffectParams::kFieldCount; ++i, at += 4)
        putF32(at, settings.effects.field(i));
    for (int i = 0; i < PassivityParams::kFieldCount; ++i, at += 4)
        putF32(at, settings.passivity.field(i));
    putU16(&blob[kCrcOffset], v2::crc16(std::span<const std::uint8_t>(blob).first(kCrcOffset)));
    return blob;
}

bool decodeSettingsBlob(std::span<const std::uint8_t> bytes, fw::StoredSettings &out)
{
    if (bytes.size() < 6)
        return false;
    const std::uint16_t version = getU16(&bytes[0]);
    const std::size_t payload = getU16(&bytes[2]);
    const bool known = (version == kSettingsBlobVersion && payload == kSettingsPayloadBytes) ||
                       (version == 2 && payload == kVersion2PayloadBytes) ||
                       (version == 1 && payload == kVersion1PayloadBytes);
    if (!known || bytes.size() != 2 + 2 + payload + 2)
        return false;
    const std::size_t crcAt = 4 + payload;
    if (getU16(&bytes[crcAt]) != v2::crc16(bytes.first(crcAt)))
        return false;
    fw::StoredSettings settings;
    const std::uint8_t *at = &bytes[4];
    for (int i = 0; i < DeviceParams::kFieldCount; ++i, at += 4)
        settings.params.setField(i, getF32(at));
    if (version >= 2) {
        for (int i = 0; i < EffectParams::kFieldCount; ++i, at += 4)
            settings.effects.setField(i, getF32(at));
    }
    if (version >= 3) {
        for (int i = 0; i < PassivityParams::kFieldCount; ++i, at += 4)
            settings.passivity.setField(i, getF32(at));
    }
    out = settings;
    return true;
}

} // namespace hatpic::esp32
