// The master side of the STS3032 bus (servo.md § 1): one request, at most one status packet.
//
// Plain C++20: no Qt, no OS calls, no exceptions, no RTTI, no allocation. Used from the
// control context only (it owns the ServoPort while a transaction runs).
#pragma once

#include "firmware/sts3032.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace hatpic::fw {

class ServoPort;

//! Why the last transaction failed.
enum class StsBusError : std::uint8_t {
    None,
    Timeout,   //!< not one byte of a reply arrived within the timeout (servo missing)
    Short,     //!< the reply stopped before a whole packet, or carried fewer params than asked
    Corrupt,   //!< bad checksum or LEN, or a well-formed packet of the wrong size
    ForeignId, //!< a valid status packet from another servo id
    Rejected,  //!< request not sent: too long, id 0xFF, or an answer asked of the broadcast id
};

//! Bus counters. Every failed transaction is counted once, under one kind.
struct StsBusStats
{
    std::uint32_t requests = 0;       //!< transactions started (including rejected ones)
    std::uint32_t replies = 0;        //!< status packets accepted as data
    std::uint32_t broadcasts = 0;     //!< requests to kBroadcastId (no reply awaited)
    std::uint32_t timeouts = 0;       //!< StsBusError::Timeout
    std::uint32_t shortReplies = 0;   //!< StsBusError::Short
    std::uint32_t corrupt = 0;        //!< StsBusError::Corrupt
    std::uint32_t foreignId = 0;      //!< StsBusError::ForeignId
    std::uint32_t rejected = 0;       //!< StsBusError::Rejected
    std::uint32_t echoesSkipped = 0;  //!< copies of the request heard back (not errors)
    std::uint32_t statusErrors = 0;   //!< accepted replies whose error byte was not 0
    std::uint8_t lastStatusError = 0; //!< error byte of the last accepted reply

    std::uint32_t errors() const { return timeouts + shortReplies + corrupt + foreignId; }
};

//! The STS protocol master over a ServoPort.
//!
//! One transaction: discardInput(), write the request, then read the status packet with the
//! timeout. A reply that is missing, short, corrupt or from another id fails the call, is
//! counted in stats() by kind, and none of its bytes reach the caller. A status packet whose
//! error byte is not 0 (the servo's overload, voltage, temperature… flags) still carries valid
//! data: it is accepted and counted in statusErrors.
//!
//! Half-duplex echo: adapters that tie TX and RX together hear the request itself before the
//! reply. A packet byte-identical to the request is skipped (once per transaction) and the
//! reply is read after it; the echo costs one more read, so such a transaction may take up to
//! two timeouts. (A reply that happens to equal the request would be taken for the echo on a
//! bus without one, and the call would time out; no request used here can be answered that
//! way, since an answer's error byte would have to equal the instruction.)
class StsBus
{
public:
    //! Default reply timeout [µs]. At 1 Mbaud a READ of 6 bytes is an 8-byte request (80 µs)
    //! and a 12-byte reply (120 µs); with the servo's turnaround and the ESP32 UART's receive
    //! timeout a reply is complete within about 300 µs of the call. 1000 µs leaves margin for
    //! task jitter while a missing servo costs at most one control period per transaction.
    //! USB–TTL adapters on a PC deliver in USB frames and need several ms: configure it.
    static constexpr std::uint32_t kDefaultTimeoutUs = 1000;

    explicit StsBus(ServoPort &port, std::uint32_t timeoutUs = kDefaultTimeoutUs);

    std::uint32_t timeoutUs() const { return m_timeoutUs; }
    void setTimeoutUs(std::uint32_t timeoutUs) { m_timeoutUs = timeoutUs; }

    //! PING `id` (not broadcast). True when the servo answered.
    bool ping(std::uint8_t id);
    //! READ out.size() (1…kMaxParams) bytes from `addr` of servo `id` (not broadcast) into `out`.
    //! `out` is written only on success.
    bool read(std::uint8_t id, std::uint8_t addr, std::span<std::uint8_t> out);
    //! WRITE `data` (1…kMaxParams − 1 bytes) at `addr`. To kBroadcastId: sent, no reply awaited.
    bool write(std::uint8_t id, std::uint8_t addr, std::span<const std::uint8_t> data);
    //! REG_WRITE: like write(), applied by the servo on ACTION.
    bool regWrite(std::uint8_t id, std::uint8_t addr, std::span<const std::uint8_t> data);
    //! ACTION: servos apply their registered write (usually to kBroadcastId).
    bool action(std::uint8_t id);
    //! SYNC_WRITE (always broadcast, no reply): `groups` is (id, `length` data bytes) repeated.
    bool syncWrite(std::uint8_t addr, std::uint8_t length, std::span<const std::uint8_t> groups);

    const StsBusStats &stats() const { return m_stats; }
    StsBusError lastError() const { return m_lastError; }
    //! Statistics of the reply parser (resynchronisations, skipped bytes).
    const StsPacketParser::Stats &parserStats() const { return m_parser.stats(); }

private:
    //! Sends `code` with `params` to `id` and, unless broadcast, reads a reply carrying exactly
    //! `replyParams` bytes into `reply`.
    bool transact(std::uint8_t id, std::uint8_t code, std::span<const std::uint8_t> params,
                  std::span<std::uint8_t> reply);
    bool writeLike(std::uint8_t code, std::uint8_t id, std::uint8_t addr,
                   std::span<const std::uint8_t> data);
    bool fail(StsBusError error);

    ServoPort &m_port;
    std::uint32_t m_timeoutUs;
    StsPacketParser m_parser;
    std::uint8_t m_request[sts::kMaxPacketBytes]{};
    std::size_t m_requestSize = 0;
    std::uint8_t m_rx[sts::kMaxPacketBytes]{};
    StsBusStats m_stats;
    StsBusError m_lastError = StsBusError::None;
};

} // namespace hatpic::fw
