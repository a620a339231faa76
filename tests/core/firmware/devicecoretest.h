// Allocation-free hardware for driving fw::DeviceCore in tests: a host port with fixed
// buffers, a manual clock, and a servo bus that answers like an STS3032 from canned registers.
// They sit below the device core's seams; the real servo emulation is tested on its own
// (tst_emulatedsts3032) and with the simulator.
#pragma once

#include "firmware/ports.h"
#include "firmware/sts3032.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>

namespace devicecoretest {

using namespace hatpic;

template<std::size_t N> class ByteRing
{
public:
    bool push(std::span<const std::uint8_t> bytes)
    {
        if (m_size + bytes.size() > N)
            return false;
        for (const std::uint8_t b : bytes)
            m_bytes[(m_start + m_size++) % N] = b;
        return true;
    }
    std::size_t pop(std::span<std::uint8_t> out)
    {
        const std::size_t n = std::min(out.size(), m_size);
        for (std::size_t i = 0; i < n; ++i)
            out[i] = m_bytes[(m_start + i) % N];
        m_start = (m_start + n) % N;
        m_size -= n;
        return n;
    }
    std::size_t size() const { return m_size; }

private:
    std::array<std::uint8_t, N> m_bytes{};
    std::size_t m_start = 0;
    std::size_t m_size = 0;
};

//! Host link with fixed buffers: the test writes host bytes and reads device bytes.
class FixedHostPort : public fw::HostPort
{
public:
    std::size_t read(std::span<std::uint8_t> out) override { return toDevice.pop(out); }
    bool write(std::span<const std::uint8_t> frame, Traffic) override { return toHost.push(frame); }
    ByteRing<1024> toDevice;
    ByteRing<64 * 1024> toHost;
};

class ManualClock : public fw::Clock
{
public:
    std::uint32_t micros() override { return now; }
    std::uint32_t now = 0;
};

//! Answers PING, READ and WRITE for id 1 from a register array, without allocating. The
//! test sets the present position/speed/load registers; WRITEs land in the array. With
//! `corruptReplies`, every status packet's checksum is wrong (the servo still obeys).
class CannedServo : public fw::ServoPort
{
public:
    CannedServo() { setPresent(1000, 0, 0); }

    void setPresent(std::int32_t position, std::int32_t speed, std::int32_t load)
    {
        setWord(fw::sts::kRegPresentPosition,
                fw::sts::encodeSignMagnitude(position, fw::sts::kPositionSignBit));
        setWord(fw::sts::kRegPresentSpeed,
                fw::sts::encodeSignMagnitude(speed, fw::sts::kSpeedSignBit));
        setWord(fw::sts::kRegPresentLoad,
                fw::sts::encodeSignMagnitude(load, fw::sts::kLoadSignBit));
    }
    std::uint16_t word(std::uint8_t addr) const
    {
        return fw::sts::word(regs[addr], regs[addr + 1]);
    }

    void discardInput() override { m_replySize = 0; }
    void write(std::span<const std::uint8_t> bytes) override
    {
        ++writes;
        if (bytes.size() < 6 || bytes[2] != 1)
            return;
        const std::uint8_t instr = bytes[4];
        const std::span<const std::uint8_t> params = bytes.subspan(5, bytes[3] - 2);
        std::array<std::uint8_t, 64> out{};
        std::size_t n = 0;
        if (instr == fw::sts::kRead) {
            n = fw::sts::encodePacket(1, 0, std::span(regs).subspan(params[0], params[1]), m_reply);
        } else {
            if (instr == fw::sts::kWrite) {
                for (std::size_t i = 1; i < params.size(); ++i)
                    regs[params[0] + i - 1] = params[i];
            }
            n = fw::sts::encodePacket(1, 0, std::span(out).first(0), m_reply);
        }
        if (corruptReplies && n > 0)
            m_reply[n - 1] ^= 0x5A;
        m_replySize = n;
        m_replyPos = 0;
    }
    std::size_t read(std::span<std::uint8_t> out, std::uint32_t) override
    {
        const std::size_t n = std::min(out.size(), m_replySize - m_replyPos);
        std::copy_n(m_reply.begin() + std::ptrdiff_t(m_replyPos), n, out.begin());
        m_replyPos += n;
        return n;
    }

    std::array<std::uint8_t, 256> regs{};
    bool corruptReplies = false;
    std::uint64_t writes = 0;

private:
    void setWord(std::uint8_t addr, std::uint16_t value)
    {
        regs[addr] = std::uint8_t(value);
        regs[addr + 1] = std::uint8_t(value >> 8);
    }
    std::array<std::uint8_t, fw::sts::kMaxPacketBytes> m_reply{};
    std::size_t m_replySize = 0;
    std::size_t m_replyPos = 0;
};

} // namespace devicecoretest
