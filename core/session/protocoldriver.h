// One connected device's protocol, as a decoder: received bytes become events the session acts
// on (a telemetry frame, an ACK, the device's tuning, a PONG, a line of text), in the order the
// frames came; feedback and PING go out in the protocol's own frames. V2Driver and LegacyDriver
// are the two; the session holds one of them while connected. A driver holds nothing of the
// session: it does not count, build samples or answer the command queue — the session does, with
// what the driver returns (DeviceSession::dispatch). The protocols' differences live behind this
// interface except the decoder counts (v2Stats() or legacyStats(), for LinkStats).
#pragma once

#include "model/axes.h"
#include "model/params.h"
#include "protocol/deviceinfo.h"
#include "protocol/legacy.h"
#include "protocol/messages.h"
#include "session/sessiontypes.h"

#include <QByteArray>
#include <QString>

#include <functional>
#include <variant>
#include <vector>

namespace hatpic {

//! What a received frame said.
namespace received {
//! A v2 TELEMETRY: its seq and its quantities, those of capabilities the device did not
//! announce already dropped.
struct Telemetry
{
    quint8 seq = 0;
    v2::Telemetry telemetry;
    //! Every quantity is a number: a NaN or ±Inf would enter p_ref's integral and stay there
    //! for the rest of the session, so such a frame is counted and never made a sample.
    bool finite = true;
};
//! A legacy frame, with what turns it into a sample: the conversion and the τ_ext the host
//! last sent each knob [N·m] (0 while feedback is off).
struct LegacyFrame
{
    legacy::Frame frame;
    const legacy::Conversion *conversion = nullptr;
    AxisTorques tauExt{};
};
//! A PARAMS, EFFECTS or PASSIVITY: the part of `knob`'s tuning it carried.
struct Tuning
{
    DeviceTuning told;
    Knob knob = 0;
};
struct Pong
{
    quint32 token = 0;
};
//! A line the device said for people (v2 LOG, a legacy text line), as it came.
struct Text
{
    QString line;
};
} // namespace received

//! One event of a received frame.
using Received = std::variant<received::Telemetry, received::LegacyFrame, v2::Ack, received::Tuning,
                              received::Pong, received::Text>;

//! Where a driver's frames go out (the session's link).
using DriverWrite = std::function<void(const QByteArray &bytes)>;

class ProtocolDriver
{
public:
    virtual ~ProtocolDriver() = default;

    //! What the device told (or what is known of it).
    virtual DeviceInfo info() const = 0;
    //! Requests the connection starts with (v2: read the tuning, set the stream).
    virtual std::vector<Request> startRequests() const = 0;
    //! Decodes `bytes` (any chunking) and appends what its frames said to `out`.
    virtual void feed(const QByteArray &bytes, std::vector<Received> &out) = 0;
    //! One feedback frame with each knob's τ_ext [N·m]; a device with one knob takes the first.
    virtual void sendFeedback(const AxisTorques &tauExt) = 0;
    //! Feedback frames per second the device and its link take at most [Hz].
    virtual double maxFeedbackHz() const = 0;
    //! Sends a PING; false when the protocol has none or a command waits for its answer.
    virtual bool sendPing(quint32 token) = 0;
    //! Why the device cannot carry the wire step `step`; nullopt when it can.
    virtual std::optional<outcome::Unsupported::Why> refusal(CommandKind step) const = 0;
    //! The τ limit samples are scaled and clamped with [N·m]: the device's (v2), or the host's
    //! `host.tau_limit` (legacy: the published firmware does not tell).
    virtual double sampleTauLimit(const HostParams &host) const = 0;
    //! The live decoder counts, for LinkStats (one of the two is null).
    virtual const v2::DecoderStats *v2Stats() const { return nullptr; }
    virtual const legacy::DecoderStats *legacyStats() const { return nullptr; }
    //! The `Connected` state's detail (state::ConnectedV2 with the firmware, ConnectedLegacy).
    virtual StateDetail::Why connected() const = 0;
};

} // namespace hatpic
