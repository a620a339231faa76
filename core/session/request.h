// What a caller asks of the device, and what came of it: one Request (a type per thing it can
// ask), whose wire steps follow from its type, and one Outcome (a type per way it can end), which
// wording, the editor's sync state and hatpicctl visit. Values; they cross threads by copy.
#pragma once

#include "model/devicetuning.h"
#include "model/effects.h"
#include "protocol/deviceinfo.h"
#include "protocol/messages.h"

#include <QMetaType>
#include <QStringList>

#include <cstdint>

#include <functional>
#include <optional>
#include <string_view>
#include <variant>
#include <vector>

namespace hatpic {

//! A step on the wire, by the message it sends: HELLO (only while detecting), GET_PARAMS,
//! SET_PARAMS, SET_STREAM, ZERO, SAVE_PARAMS, SET_EFFECTS, GET_EFFECTS, SET_PASSIVITY,
//! GET_PASSIVITY, VIBRATE (messages.h).
using CommandKind = v2::MessageType;
//! True for the steps only a device with the effects capability takes.
constexpr bool isEffectCommand(CommandKind kind)
{
    return kind == CommandKind::SetEffects || kind == CommandKind::GetEffects ||
           kind == CommandKind::Vibrate;
}
//! True for the steps only a device with the passivity capability takes (passivity.md).
constexpr bool isPassivityCommand(CommandKind kind)
{
    return kind == CommandKind::SetPassivity || kind == CommandKind::GetPassivity;
}
//! The wire name: "SET_PARAMS", … (messages.h's kName).
QString commandName(CommandKind kind);

//! The knob a request is about: 0 for knob 1 … DeviceInfo::axes − 1. A device with several
//! knobs (v2's kCapabilityAxes) keeps a tuning per knob; knob 1's is the session's (samples,
//! recordings, the window), the others' travel only in their requests' outcomes.
using Knob = std::uint8_t;

namespace request {
//! Each part the tuning has sent, then read back: SET_PARAMS, GET_PARAMS, SET_EFFECTS,
//! GET_EFFECTS, SET_PASSIVITY, GET_PASSIVITY, in that order. The session validates it and
//! rounds it to float32 once; the outcome carries it as it travelled.
struct Push
{
    DeviceTuning tuning;
    Knob knob = 0;
};
//! The device's tuning: GET_PARAMS, and GET_EFFECTS and GET_PASSIVITY on a device that has them.
struct Read
{
    Knob knob = 0;
};
//! ZERO (θ0 := the current angle), then GET_PARAMS for the new θ0.
struct Zero
{
    Knob knob = 0;
};
//! SAVE_PARAMS: the device keeps its tuning across power cycles.
struct Save
{};
//! SET_STREAM: telemetry at `rateHz`; 0 stops it. The device may clamp it.
struct Stream
{
    quint16 rateHz = 0;
};
//! VIBRATE: a cue of amplitude 0 stops one that plays.
struct Vibrate
{
    Vibration vibration;
    Knob knob = 0;
};
} // namespace request

using Request = std::variant<request::Push, request::Read, request::Zero, request::Save,
                             request::Stream, request::Vibrate>;

//! The knob `request` is about; 0 for those about the whole device (SAVE_PARAMS, SET_STREAM).
Knob knobOf(const Request &request);

//! One step on the wire: the message it sends, carrying the part of its request it applies
//! (SET_PARAMS the pushed parameters, VIBRATE the cue, SET_STREAM the rate) and, on a device
//! with several knobs, the knob's `axis` byte (none for knob 1).
struct WireStep
{
    v2::Message message;

    CommandKind kind() const { return static_cast<CommandKind>(v2::messageType(message)); }
    friend bool operator==(const WireStep &, const WireStep &) = default;
};

//! The wire steps of `request` on `device`, in order (see each request), each with its message.
std::vector<WireStep> wireSteps(const Request &request, const DeviceInfo &device);
//! The kind of each step, in order.
std::vector<CommandKind> stepKinds(const std::vector<WireStep> &steps);

namespace outcome {
//! What a read-back said of the changes a request made.
enum class ReadBack {
    None,       //!< the request changed nothing (a read, SAVE_PARAMS, SET_STREAM, VIBRATE)
    Matches,    //!< each change read back as sent (ZERO's: the new θ0, always)
    Differs,    //!< a read-back differs from what was sent: the device adjusted it
    Unanswered, //!< acknowledged, but a read-back went unanswered
};
//! Every step was answered.
struct Done
{
    ReadBack readBack = ReadBack::None;
};
//! A failure on the wire, at `step`: what the request had changed before it.
struct Stopped
{
    CommandKind step = CommandKind::GetParams;
    //! The parts a push had changed before `step` — each as read back where that came, else as
    //! sent — which are in force. Empty when nothing had changed.
    DeviceTuning applied;
};
//! The device answered `step` with a non-OK ACK: it did not apply that step.
struct Refused : Stopped
{
    v2::AckStatus status = v2::AckStatus::Ok;
    int field = -1; //!< the index in the step's block the device named; -1: none

    //! That field's name in its block ("K_max", "wall_stiffness", "pc_damping_max", the cue's
    //! "frequency"); empty when the device named none.
    std::string_view fieldName() const;
};
//! `step` went unanswered after every resend.
struct TimedOut : Stopped
{
    int attempts = 0;   //!< frames sent
    int intervalMs = 0; //!< between them [ms]
};
//! The session ended before `step` was answered.
struct Cut : Stopped
{
    enum class Why {
        Disconnected,    //!< by the user
        ConnectionLost,  //!< the link went
        DetectionFailed, //!< (only the session's HELLO)
    };
    Why why = Why::Disconnected;
};
//! Not sent: no device was connected.
struct NotConnected
{};
//! Not sent: the device cannot carry `step`.
struct Unsupported
{
    enum class Why {
        NoParameters,          //!< the legacy firmware cannot send or take parameters
        FixedRate,             //!< the legacy firmware streams at its own rate
        NoEffects,             //!< the legacy firmware cannot render effects
        NoEffectsCapability,   //!< a v2 device without the effects capability bit
        NoPassivityCapability, //!< a device without the passivity capability bit
        NoSuchKnob,            //!< the request names a knob past the device's last
    };
    CommandKind step = CommandKind::GetParams;
    Why why = Why::NoParameters;
    Knob knob = 0;   //!< NoSuchKnob: the knob named
    quint8 axes = 1; //!< NoSuchKnob: the device's knobs
};
//! Not sent: the host's validation refused it.
struct Invalid
{
    QStringList problems; //!< the violations, as core/model words them
};
//! Not sent: `limit` requests were already waiting.
struct QueueFull
{
    int limit = 0;
};
} // namespace outcome

struct Outcome
{
    using Result = std::variant<outcome::Done, outcome::Refused, outcome::TimedOut, outcome::Cut,
                                outcome::NotConnected, outcome::Unsupported, outcome::Invalid,
                                outcome::QueueFull>;
    //! What was asked; a push as it travelled (float32-rounded, the parts it carried).
    Request request;
    Result result;
    //! What the device said it holds: the read's parts and each read-back that came.
    DeviceTuning received;

    bool ok() const { return std::holds_alternative<outcome::Done>(result); }
    //! A failure on the wire (refused, timed out or cut), else null.
    const outcome::Stopped *stopped() const;
    //! The push's tuning as it travelled; null for any other request.
    const DeviceTuning *pushed() const;
    //! A push whose SET_EFFECTS or SET_PASSIVITY went out and was never answered (timed out, or
    //! cut): whether that block took effect is unknown. Gives that step, else nullopt.
    std::optional<CommandKind> unknownStep() const;
};

//! Where an outcome goes: called once, on the thread that ends the request (the session's).
using OutcomeHandler = std::function<void(const Outcome &)>;

} // namespace hatpic

Q_DECLARE_METATYPE(hatpic::Request)
Q_DECLARE_METATYPE(hatpic::Outcome)
