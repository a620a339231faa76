// The simulated device's USB serial link: a fw::HostPort with the byte rate of a UART.
//
// Device output enters an 8 KiB transmit queue (stream frames that do not fit are dropped
// whole; replies may use 512 bytes more) and moves to the host side at baud/10 bytes per
// second (8N1) as simulated time passes; an idle link saves up no time. What has arrived but
// was not taken is kept up to 64 KiB; beyond that the link stalls. Host → device bytes are not
// rate-limited. Single-threaded (docs/simulator.md § 6).
#pragma once

#include "firmware/ports.h"

#include <QByteArray>
#include <QByteArrayView>

namespace hatpic {

class EmulatedUart : public fw::HostPort
{
public:
    static constexpr qsizetype kTxQueueBytes = 8 * 1024;    //!< the UART's transmit buffer
    static constexpr qsizetype kReplyReserveBytes = 512;    //!< extra room only replies use
    static constexpr qsizetype kDeliveredBytes = 64 * 1024; //!< carried but not yet taken

    //! @param baud link speed [bit/s]; @param throttle false = every byte arrives at once
    EmulatedUart(qint32 baud, bool throttle) : m_baud(baud), m_throttle(throttle) {}

    // ---- the device's side (fw::HostPort) ----
    std::size_t read(std::span<std::uint8_t> out) override;
    bool write(std::span<const std::uint8_t> frame, Traffic traffic) override;
    //! write() for Qt bytes (the legacy emulation's text and frames).
    bool write(QByteArrayView bytes, Traffic traffic);

    // ---- the host's side ----
    //! Host → device bytes, read by the device's next read().
    void fromHost(QByteArrayView bytes) { m_received.append(bytes); }
    //! Moves dt seconds' worth of bytes from the transmit queue to the host side [s].
    void transfer(double dt);
    //! What has arrived on the host side so far.
    QByteArray take();

    qint32 baud() const { return m_baud; }

private:
    qint32 m_baud;
    bool m_throttle;
    QByteArray m_received;  //!< host → device, not read yet
    QByteArray m_txQueue;   //!< device → host, not carried yet
    QByteArray m_delivered; //!< carried, not taken yet
    double m_credit = 0;    //!< bytes the link may still carry in the current step
};

} // namespace hatpic
