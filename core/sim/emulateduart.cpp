#include "emulateduart.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace hatpic {

std::size_t EmulatedUart::read(std::span<std::uint8_t> out)
{
    const auto n = std::min<qsizetype>(qsizetype(out.size()), m_received.size());
    std::memcpy(out.data(), m_received.constData(), std::size_t(n));
    m_received.remove(0, n);
    return std::size_t(n);
}

bool EmulatedUart::write(std::span<const std::uint8_t> frame, Traffic traffic)
{
    return write(QByteArrayView(frame.data(), qsizetype(frame.size())), traffic);
}

bool EmulatedUart::write(QByteArrayView bytes, Traffic traffic)
{
    const qsizetype room = kTxQueueBytes + (traffic == Traffic::Reply ? kReplyReserveBytes : 0);
    if (m_txQueue.size() + bytes.size() > room)
        return false;
    m_txQueue.append(bytes);
    if (!m_throttle)
        transfer(0);
    return true;
}

void EmulatedUart::transfer(double dt)
{
    const qsizetype space = kDeliveredBytes - m_delivered.size();
    qsizetype n = 0;
    if (!m_throttle) {
        n = std::min(m_txQueue.size(), space);
    } else {
        m_credit += dt * m_baud / 10.0;
        n = std::min({qsizetype(std::floor(m_credit)), m_txQueue.size(), space});
        m_credit -= double(n);
    }
    if (n > 0) {
        m_delivered.append(m_txQueue.left(n));
        m_txQueue.remove(0, n);
    }
    // An idle UART cannot send bytes later for time it spent idle.
    if (m_txQueue.isEmpty() || m_delivered.size() >= kDeliveredBytes)
        m_credit = std::min(m_credit, 1.0);
}

QByteArray EmulatedUart::take()
{
    QByteArray out;
    out.swap(m_delivered);
    return out;
}

} // namespace hatpic
