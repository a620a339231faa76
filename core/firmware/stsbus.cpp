#include "firmware/stsbus.h"

#include "firmware/ports.h"

#include <algorithm>
#include <array>

namespace hatpic::fw {

StsBus::StsBus(ServoPort &port, std::uint32_t timeoutUs) : m_port(port), m_timeoutUs(timeoutUs) {}

bool StsBus::ping(std::uint8_t id)
{
    if (id == sts::kBroadcastId) {
        ++m_stats.requests;
        return fail(StsBusError::Rejected);
    }
    return transact(id, sts::kPing, {}, {});
}

bool StsBus::read(std::uint8_t id, std::uint8_t addr, std::span<std::uint8_t> out)
{
    if (id == sts::kBroadcastId || out.empty() || out.size() > sts::kMaxParams) {
        ++m_stats.requests;
        return fail(StsBusError::Rejected);
    }
    const std::array<std::uint8_t, 2> params{addr, static_cast<std::uint8_t>(out.size())};
    return transact(id, sts::kRead, params, out);
}

bool StsBus::write(std::uint8_t id, std::uint8_t addr, std::span<const std::uint8_t> data)
{
    return writeLike(sts::kWrite, id, addr, data);
}

bool StsBus::regWrite(std::uint8_t id, std::uint8_t addr, std::span<const std::uint8_t> data)
{
    return writeLike(sts::kRegWrite, id, addr, data);
}

bool StsBus::action(std::uint8_t id)
{
    return transact(id, sts::kAction, {}, {});
}

bool StsBus::syncWrite(std::uint8_t addr, std::uint8_t length, std::span<const std::uint8_t> groups)
{
    const std::size_t group = std::size_t{length} + 1;
    if (length == 0 || groups.empty() || groups.size() % group != 0 ||
        groups.size() + 2 > sts::kMaxParams) {
        ++m_stats.requests;
        return fail(StsBusError::Rejected);
    }
    std::array<std::uint8_t, sts::kMaxParams> params{};
    params[0] = addr;
    params[1] = length;
    std::copy(groups.begin(), groups.end(), params.begin() + 2);
    return transact(sts::kBroadcastId, sts::kSyncWrite,
                    std::span<const std::uint8_t>(params.data(), groups.size() + 2), {});
}

bool StsBus::writeLike(std::uint8_t code, std::uint8_t id, std::uint8_t addr,
                       std::span<const std::uint8_t> data)
{
    if (data.empty() || data.size() + 1 > sts::kMaxParams) {
        ++m_stats.requests;
        return fail(StsBusError::Rejected);
    }
    std::array<std::uint8_t, sts::kMaxParams> params{};
    params[0] = addr;
    std::copy(data.begin(), data.end(), params.begin() + 1);
    return transact(id, code, std::span<const std::uint8_t>(params.data(), data.size() + 1), {});
}

bool StsBus::fail(StsBusError error)
{
    m_lastError = error;
    switch (error) {
    case StsBusError::None:
        break;
    case StsBusError::Timeout:
        ++m_stats.timeouts;
        break;
    case StsBusError::Short:
        ++m_stats.shortReplies;
        break;
    case StsBusError::Corrupt:
        ++m_stats.corrupt;
        break;
    case StsBusError::ForeignId:
        ++m_stats.foreignId;
        break;
    case StsBusError::Rejected:
        ++m_stats.rejected;
        break;
    }
    return false;
}

bool StsBus::transact(std::uint8_t id, std::uint8_t code, std::span<const std::uint8_t> params,
                      std::span<std::uint8_t> reply)
{
    ++m_stats.requests;
    // 0xFF is no id: FF FF FF reads as preamble on the bus, so no servo could parse the request.
    if (id > sts::kBroadcastId)
        return fail(StsBusError::Rejected);
    m_requestSize = sts::encodePacket(id, code, params, m_request);
    if (m_requestSize == 0)
        return fail(StsBusError::Rejected);
    const std::span<const std::uint8_t> request(m_request, m_requestSize);

    m_port.discardInput();
    m_port.write(request);
    if (id == sts::kBroadcastId) {
        ++m_stats.broadcasts;
        m_lastError = StsBusError::None;
        return true;
    }

    m_parser.reset();
    const std::uint32_t parserErrors = m_parser.stats().errors();
    const std::size_t replySize = reply.size() + sts::kPacketOverhead;
    // Enough for an echo, the reply and a packet's worth of line noise; beyond it the reply
    // is not coming in a usable form.
    const std::size_t budget = m_requestSize + replySize + sts::kMaxPacketBytes;
    std::size_t received = 0;
    bool echoSkipped = false;
    std::size_t want = replySize;
    for (;;) {
        const std::size_t n = m_port.read(std::span<std::uint8_t>(m_rx, want), m_timeoutUs);
        received += n;
        for (std::size_t i = 0; i < n; ++i) {
            bool have = m_parser.push(m_rx[i]);
            while (have) {
                const std::span<const std::uint8_t> bytes = m_parser.packetBytes();
                if (!echoSkipped && std::ranges::equal(bytes, request)) {
                    echoSkipped = true;
                    ++m_stats.echoesSkipped;
                    have = m_parser.next();
                    continue;
                }
                const StsPacket packet = m_parser.packet();
                if (packet.id != id)
                    return fail(StsBusError::ForeignId);
                if (packet.params.size() < reply.size())
                    return fail(StsBusError::Short);
                if (packet.params.size() > reply.size())
                    return fail(StsBusError::Corrupt);
                std::copy(packet.params.begin(), packet.params.end(), reply.begin());
                ++m_stats.replies;
                m_stats.lastStatusError = packet.code;
                if (packet.code != 0)
                    ++m_stats.statusErrors;
                m_lastError = StsBusError::None;
                return true;
            }
            if (m_parser.stats().errors() != parserErrors)
                return fail(StsBusError::Corrupt);
        }
        if (n < want) {
            const std::size_t echoBytes = echoSkipped ? m_requestSize : 0;
            return fail(received == echoBytes ? StsBusError::Timeout : StsBusError::Short);
        }
        if (received >= budget)
            return fail(StsBusError::Corrupt);
        // Read exactly what the packet in progress still lacks, so no byte of a later
        // transaction is taken here; without a LEN yet, assume it is the reply.
        const std::size_t pending = m_parser.pending();
        want = pending >= 4 ? m_parser.missing() : replySize - pending;
    }
}

} // namespace hatpic::fw
