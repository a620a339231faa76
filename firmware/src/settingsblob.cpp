#include "settingsblob.h"

#include "protocol/crc16.h"

#include <bit>

namespace hatpic::esp32 {

namespace {

constexpr std::size_t kCrcOffset = kSettingsBlobBytes - 2;

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
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        const auto bits =
            std::bit_cast<std::uint32_t>(static_cast<float>(settings.params.field(i)));
        std::uint8_t *at = &blob[4 + 4 * static_cast<std::size_t>(i)];
        for (int b = 0; b < 4; ++b)
            at[b] = static_cast<std::uint8_t>(bits >> (8 * b));
    }
    putU16(&blob[kCrcOffset], v2::crc16(std::span<const std::uint8_t>(blob).first(kCrcOffset)));
    return blob;
}

bool decodeSettingsBlob(std::span<const std::uint8_t> bytes, fw::StoredSettings &out)
{
    if (bytes.size() != kSettingsBlobBytes)
        return false;
    if (getU16(&bytes[0]) != kSettingsBlobVersion || getU16(&bytes[2]) != kSettingsPayloadBytes)
        return false;
    if (getU16(&bytes[kCrcOffset]) != v2::crc16(bytes.first(kCrcOffset)))
        return false;
    fw::StoredSettings settings;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i) {
        const std::uint8_t *at = &bytes[4 + 4 * static_cast<std::size_t>(i)];
        std::uint32_t bits = 0;
        for (int b = 0; b < 4; ++b)
            bits |= std::uint32_t{at[b]} << (8 * b);
        settings.params.setField(i, static_cast<double>(std::bit_cast<float>(bits)));
    }
    out = settings;
    return true;
}

} // namespace hatpic::esp32
