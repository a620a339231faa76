#include "emulatedsts3032.h"

#include "sim/servoplant.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hatpic {

namespace sts = fw::sts;

namespace {

constexpr std::size_t kRegisterCount = 256;
constexpr double kMaxMagnitude15 = 32767; //!< largest magnitude of a bit-15 register

bool readOnly(std::size_t addr)
{
    return addr < 5 || (addr >= sts::kRegPresentPosition && addr <= sts::kRegPresentTemperature);
}

bool covers(std::size_t addr, std::size_t count, std::size_t reg, std::size_t width)
{
    return addr < reg + width && reg < addr + count;
}

//! Whole ticks of `radians` as the simulator has always rounded them (half away from zero).
double roundedTicks(double radians)
{
    return std::round(radians * sts::kTicksPerRev / (2.0 * std::numbers::pi));
}

std::uint16_t signMagnitude15(double value)
{
    const double clamped = std::clamp(value, -kMaxMagnitude15, kMaxMagnitude15);
    return sts::encodeSignMagnitude(static_cast<std::int32_t>(clamped), 15);
}

} // namespace

EmulatedSts3032::EmulatedSts3032(ServoPlant &plant, const Config &config)
    : m_plant(plant), m_config(config), m_rng(config.seed)
{
    if (!(std::isfinite(m_config.tauLimit) && m_config.tauLimit > 0))
        m_config.tauLimit = sts::kDefaultTauLimit; // as SimulatedDevice does
    m_regs[0] = 3;                                 // firmware version major, minor: arbitrary
    m_regs[1] = 10;
    setWord(sts::kRegModelNumber, m_config.modelNumber);
    m_regs[5] = m_config.id;
    m_regs[sts::kRegMode] = sts::kModePosition;
    m_regs[sts::kRegTorqueEnable] = m_plant.torqueEnabled() ? 1 : 0;
    setWord(sts::kRegGoalPosition,
            signMagnitude15(m_config.centerTick + roundedTicks(m_plant.command())));
    m_regs[sts::kRegPresentVoltage] = m_config.voltage;
    m_regs[sts::kRegPresentTemperature] = m_config.temperature;
    sampleFeedback(false);
}

EmulatedSts3032::Stats EmulatedSts3032::stats() const
{
    Stats s = m_stats;
    s.badPackets = m_parser.stats().errors();
    return s;
}

void EmulatedSts3032::receive(std::span<const std::uint8_t> bytes)
{
    for (const std::uint8_t b : bytes) {
        bool have = m_parser.push(b);
        while (have) {
            handle(m_parser.packet());
            have = m_parser.next();
        }
    }
}

std::size_t EmulatedSts3032::takeOutput(std::span<std::uint8_t> out)
{
    const std::size_t n = std::min(out.size(), m_output.size());
    std::copy_n(m_output.begin(), n, out.begin());
    m_output.erase(m_output.begin(), m_output.begin() + static_cast<std::ptrdiff_t>(n));
    return n;
}

void EmulatedSts3032::handle(const fw::StsPacket &packet)
{
    ++m_stats.received;
    const bool broadcast = packet.id == sts::kBroadcastId;
    if (!broadcast && packet.id != m_config.id) {
        ++m_stats.ignored;
        return;
    }
    const std::span<const std::uint8_t> p = packet.params;
    switch (packet.code) {
    case sts::kPing:
        if (broadcast) {
            ++m_stats.ignored;
            return;
        }
        reply({});
        return;
    case sts::kRead: {
        if (broadcast) {
            ++m_stats.ignored;
            return;
        }
        if (p.size() != 2 || p[1] == 0 || p[0] + std::size_t{p[1]} > kRegisterCount ||
            p[1] > sts::kMaxParams) {
            ++m_stats.refused;
            return;
        }
        const std::size_t addr = p[0];
        const std::size_t count = p[1];
        if (covers(addr, count, sts::kRegPresentPosition, 6))
            sampleFeedback(covers(addr, count, sts::kRegPresentLoad, 2));
        reply(std::span<const std::uint8_t>(m_regs.data() + addr, count));
        return;
    }
    case sts::kWrite:
        if (p.size() < 2 || !apply(p[0], p.subspan(1))) {
            ++m_stats.refused;
            return;
        }
        break;
    case sts::kRegWrite:
        if (p.size() < 2 || p[0] + p.size() - 1 > kRegisterCount) {
            ++m_stats.refused;
            return;
        }
        std::copy(p.begin(), p.end(), m_registered.begin());
        m_registeredSize = p.size();
        break;
    case sts::kAction:
        if (m_registeredSize > 0) {
            const std::span<const std::uint8_t> r(m_registered.data(), m_registeredSize);
            apply(r[0], r.subspan(1));
            m_registeredSize = 0;
        }
        break;
    case sts::kSyncWrite: {
        // addr, n, then (id, n bytes) per servo; never answered.
        const std::size_t n = p.size() >= 2 ? p[1] : 0;
        if (n == 0 || (p.size() - 2) % (n + 1) != 0 || p[0] + n > kRegisterCount) {
            ++m_stats.refused;
            return;
        }
        for (std::size_t at = 2; at < p.size(); at += n + 1) {
            if (p[at] == m_config.id)
                apply(p[0], p.subspan(at + 1, n));
        }
        return;
    }
    default:
        ++m_stats.refused;
        return;
    }
    if (!broadcast)
        reply({});
}

void EmulatedSts3032::reply(std::span<const std::uint8_t> params)
{
    std::array<std::uint8_t, sts::kMaxPacketBytes> packet{};
    const std::size_t size = sts::encodePacket(m_config.id, 0, params, packet);
    m_output.insert(m_output.end(), packet.begin(), packet.begin() + size);
    ++m_stats.answered;
}

bool EmulatedSts3032::apply(std::size_t addr, std::span<const std::uint8_t> data)
{
    if (addr + data.size() > kRegisterCount)
        return false;
    for (std::size_t i = 0; i < data.size(); ++i) {
        if (!readOnly(addr + i))
            m_regs[addr + i] = data[i];
    }
    if (covers(addr, data.size(), sts::kRegTorqueEnable, 1))
        m_plant.setTorqueEnabled(m_regs[sts::kRegTorqueEnable] != 0);
    if (covers(addr, data.size(), sts::kRegGoalPosition, 2)) {
        const std::int32_t goal = sts::decodeSignMagnitude(
            sts::word(m_regs[sts::kRegGoalPosition], m_regs[sts::kRegGoalPosition + 1]),
            sts::kPositionSignBit);
        m_plant.setCommand(double(goal - m_config.centerTick) *
                           (2.0 * std::numbers::pi / sts::kTicksPerRev));
    }
    return true;
}

void EmulatedSts3032::sampleFeedback(bool drawNoise)
{
    // Not wrapped: the tick count is multi-turn, as docs/simulator.md § 3 measures it.
    setWord(sts::kRegPresentPosition,
            signMagnitude15(m_config.centerTick + roundedTicks(m_plant.theta())));
    setWord(sts::kRegPresentSpeed, signMagnitude15(roundedTicks(m_plant.omega())));
    // SimulatedDevice::measureTau's arithmetic, stopped at the register's integer count.
    double load = m_plant.motorTorque();
    if (drawNoise && m_config.noise > 0 && std::isfinite(m_config.noise))
        load += m_config.noise * m_normal(m_rng);
    const double quantum = m_config.tauLimit * 1e-3;
    const double counts = std::clamp(std::round(load / quantum), double(-sts::kLoadFullScale),
                                     double(sts::kLoadFullScale));
    setWord(sts::kRegPresentLoad,
            sts::encodeSignMagnitude(static_cast<std::int32_t>(counts), sts::kLoadSignBit));
}

void EmulatedSts3032::setWord(std::uint8_t addr, std::uint16_t value)
{
    const std::array<std::uint8_t, 2> bytes = sts::wordBytes(value);
    m_regs[addr] = bytes[0];
    m_regs[addr + 1] = bytes[1];
}

} // namespace hatpic
