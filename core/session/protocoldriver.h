// One connected device's protocol: how received bytes become samples, parameters and log
// lines, what feedback and PING look like on the wire, and which commands it takes (v2's are
// encoded and resent by the CommandQueue, which the v2 driver feeds the answers). V2Driver and
// LegacyDriver are the two; the session holds one of them while connected. The protocols'
// differences live behind this interface except two the session passes on as they are: the
// decoder counts (v2Stats() or legacyStats(), for LinkStats) and the Connected state's kind.
#pragma once

#include "model/params.h"
#include "protocol/deviceinfo.h"
#include "session/sessiontypes.h"
#include "telemetry/sample.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QString>

#include <functional>

namespace hatpic {

class LinkStatistics;
class PingProbe;
class SamplePipeline;

//! What a driver works with, the session's parts it holds: where samples and the device's
//! tuning go, the link's counts, the PING probe, the session's clock, and the way out.
struct DriverLinks
{
    SamplePipeline &samples;
    LinkStatistics &statistics;
    PingProbe &ping;
    const QElapsedTimer &clock; //!< host time of samples
    std::function<void(const QByteArray &bytes)> write;
    std::function<void(const QString &line)> deviceText; //!< v2 LOG, legacy boot lines
};

class ProtocolDriver
{
public:
    virtual ~ProtocolDriver() = default;

    //! What the device told (or what is known of it).
    virtual DeviceInfo info() const = 0;
    //! The connection is established: the connect sequence (v2: GET_PARAMS, GET_EFFECTS when
    //! the device has effects, SET_STREAM).
    virtual void start() = 0;
    virtual void feed(const QByteArray &bytes) = 0;
    //! One feedback frame with τ_ext [N·m].
    virtual void sendFeedback(double tauExt) = 0;
    //! Feedback frames per second the device and its link take at most [Hz].
    virtual double maxFeedbackHz() const = 0;
    //! Sends a PING; false when the protocol has none or a command waits for its answer.
    virtual bool sendPing(quint32 token) = 0;
    //! Why the device cannot carry the wire step `step`; nullopt when it can.
    virtual std::optional<outcome::Unsupported::Why> refusal(CommandKind step) const = 0;
    //! The host parameters changed (legacy: its τ limit is the host's).
    virtual void hostParamsChanged(const HostParams &host) = 0;
    //! Stops handling anything (the link is gone) and hands its decoder's counts to the
    //! statistics.
    virtual void close() = 0;
    //! The live decoder counts, for LinkStats (one of the two is null).
    virtual const v2::DecoderStats *v2Stats() const { return nullptr; }
    virtual const legacy::DecoderStats *legacyStats() const { return nullptr; }
    //! The `Connected` state's detail (state::ConnectedV2 with the firmware, ConnectedLegacy).
    virtual StateDetail::Why connected() const = 0;
};

} // namespace hatpic
