#include "firmware/sts3032.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hatpic::fw {

namespace sts {

namespace {

constexpr double kRadPerTick = 2.0 * std::numbers::pi / kTicksPerRev; //!< [rad]

} // namespace

std::uint8_t checksum(std::uint8_t id, std::uint8_t code, std::span<const std::uint8_t> params)
{
    unsigned sum = id + static_cast<unsigned>(params.size() + 2) + code;
    for (const std::uint8_t b : params)
        sum += b;
    return static_cast<std::uint8_t>(~sum & 0xFF);
}

std::size_t encodePacket(std::uint8_t id, std::uint8_t code, std::span<const std::uint8_t> params,
                         std::span<std::uint8_t> out)
{
    const std::size_t size = params.size() + kPacketOverhead;
    if (params.size() > kMaxParams || out.size() < size)
        return 0;
    out[0] = kHeaderByte;
    out[1] = kHeaderByte;
    out[2] = id;
    out[3] = static_cast<std::uint8_t>(params.size() + 2);
    out[4] = code;
    std::copy(params.begin(), params.end(), out.begin() + 5);
    out[size - 1] = checksum(id, code, params);
    return size;
}

float positionToTheta(std::int32_t position, std::int32_t centerTick)
{
    return static_cast<float>(static_cast<double>(position - centerTick) * kRadPerTick);
}

float speedToOmega(std::int32_t speed)
{
    return static_cast<float>(static_cast<double>(speed) * kRadPerTick);
}

float loadToTorque(std::int32_t load, double tauLimit)
{
    // The simulator's formula, quantum = tauLimit·10⁻³: the same doubles before the rounding.
    const double quantum = tauLimit * 1e-3;
    return static_cast<float>(std::clamp(static_cast<double>(load) * quantum, -tauLimit, tauLimit));
}

std::int32_t thetaToGoalTick(double theta, std::int32_t centerTick)
{
    if (std::isnan(theta))
        return std::clamp(centerTick, kMinGoalTick, kMaxGoalTick);
    const double tick = centerTick + std::round(theta * kTicksPerRev / (2.0 * std::numbers::pi));
    // Clamped in double first: ±inf and huge angles never reach the integer conversion.
    return static_cast<std::int32_t>(std::clamp(tick, double(kMinGoalTick), double(kMaxGoalTick)));
}

} // namespace sts

bool StsPacketParser::push(std::uint8_t byte)
{
    if (m_packetSize > 0) {
        drop(m_packetSize);
        m_packetSize = 0;
    }
    // Cannot overflow: a held packet in progress is shorter than its LEN allows, and LEN is
    // bounded by kMaxParams, so at most kMaxPacketBytes − 1 bytes are held here.
    m_buffer[m_size++] = byte;
    return scan();
}

bool StsPacketParser::next()
{
    if (m_packetSize == 0)
        return false;
    drop(m_packetSize);
    m_packetSize = 0;
    return scan();
}

StsPacket StsPacketParser::packet() const
{
    if (m_packetSize == 0)
        return {};
    return {
        m_buffer[2], m_buffer[4],
        std::span<const std::uint8_t>(m_buffer.data() + 5, m_packetSize - sts::kPacketOverhead)};
}

std::span<const std::uint8_t> StsPacketParser::packetBytes() const
{
    return {m_buffer.data(), m_packetSize};
}

std::size_t StsPacketParser::missing() const
{
    if (m_packetSize > 0 || m_size < 4)
        return 0;
    return m_buffer[3] + std::size_t{4} - m_size;
}

void StsPacketParser::reset()
{
    m_size = 0;
    m_packetSize = 0;
}

void StsPacketParser::drop(std::size_t count)
{
    std::copy(m_buffer.begin() + count, m_buffer.begin() + m_size, m_buffer.begin());
    m_size -= count;
}

bool StsPacketParser::scan()
{
    for (;;) {
        // Header: FF FF and an id that is not FF (a run of FF is preamble, not an id).
        const bool badHeader = (m_size >= 1 && m_buffer[0] != sts::kHeaderByte) ||
                               (m_size >= 2 && m_buffer[1] != sts::kHeaderByte) ||
                               (m_size >= 3 && m_buffer[2] == sts::kHeaderByte);
        if (badHeader) {
            drop(1);
            ++m_stats.skippedBytes;
            continue;
        }
        if (m_size < 4)
            return false;
        const std::size_t len = m_buffer[3];
        if (len < 2 || len > sts::kMaxParams + 2) {
            ++m_stats.badLength;
            drop(1);
            ++m_stats.skippedBytes;
            continue;
        }
        const std::size_t size = len + 4;
        if (m_size < size)
            return false;
        const std::span<const std::uint8_t> params(m_buffer.data() + 5, len - 2);
        if (sts::checksum(m_buffer[2], m_buffer[4], params) != m_buffer[size - 1]) {
            ++m_stats.badChecksum;
            drop(1);
            ++m_stats.skippedBytes;
            continue;
        }
        ++m_stats.packets;
        m_packetSize = size;
        return true;
    }
}

} // namespace hatpic::fw
