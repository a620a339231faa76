#include "txqueue.h"

#include <algorithm>

namespace hatpic::esp32 {

bool TxQueue::push(std::span<const std::uint8_t> frame, fw::HostPort::Traffic traffic)
{
    const std::size_t reserve = traffic == fw::HostPort::Traffic::Stream ? kReplyReserve : 0;
    if (frame.size() + reserve > room())
        return false;
    const std::size_t end = (m_start + m_size) % kCapacity;
    const std::size_t first = std::min(frame.size(), kCapacity - end);
    std::copy_n(frame.begin(), first, m_bytes.begin() + std::ptrdiff_t(end));
    std::copy(frame.begin() + std::ptrdiff_t(first), frame.end(), m_bytes.begin());
    m_size += frame.size();
    return true;
}

std::span<const std::uint8_t> TxQueue::front() const
{
    return {m_bytes.data() + m_start, std::min(m_size, kCapacity - m_start)};
}

void TxQueue::pop(std::size_t count)
{
    count = std::min(count, front().size());
    m_start = (m_start + count) % kCapacity;
    m_size -= count;
    if (m_size == 0)
        m_start = 0; // the next frames go out in one piece
}

} // namespace hatpic::esp32
