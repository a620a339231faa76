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
#include <QString>

namespace hatpic {

class LinkStatistics;
class SampleBuilder;

//! What a driver reaches of its session.
class DriverHost
{
public:
    virtual void write(const QByteArray &bytes) = 0;
    virtual SampleBuilder &builder() = 0;
    virtual LinkStatistics &statistics() = 0;
    virtual qint64 hostUs() const = 0;
    //! A complete sample for the batch (and the recording).
    virtual void pushSample(const Sample &sample) = 0;
    //! The device applied `params` (SET_PARAMS) or zeroed (ZERO): it holds from the next
    //! sample on.
    virtual void paramsApplied(CommandKind kind, const DeviceParams &params) = 0;
    //! A PARAMS message arrived.
    virtual void paramsReceived(const DeviceParams &params) = 0;
    //! The device applied `effects` (SET_EFFECTS): it holds from the next sample on.
    virtual void effectsApplied(const EffectParams &effects) = 0;
    //! An EFFECTS message arrived.
    virtual void effectsReceived(const EffectParams &effects) = 0;
    virtual void pongReceived(quint32 token) = 0;
    //! Text the device sent for people (v2 LOG, legacy boot lines).
    virtual void deviceText(const QString &line) = 0;
    //! True while the link is open: a driver stops handling frames once it is gone.
    virtual bool linkOpen() const = 0;

protected:
    ~DriverHost() = default;
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
    //! Reason::None when the protocol carries `kind`; else why not (Status::Unsupported).
    virtual CommandResult::Reason refusal(CommandKind kind) const = 0;
    //! The host parameters changed (legacy: its τ limit is the host's).
    virtual void hostParamsChanged(const HostParams &host) = 0;
    //! Stops handling anything and hands its decoder's counts to the statistics.
    virtual void close() = 0;
    //! The live decoder counts, for LinkStats (one of the two is null).
    virtual const v2::DecoderStats *v2Stats() const { return nullptr; }
    virtual const legacy::DecoderStats *legacyStats() const { return nullptr; }
    //! The `Connected` state's detail kind (ConnectedV2, ConnectedLegacy).
    virtual StateDetail::Kind connectedKind() const = 0;
};

} // namespace hatpic
