// Value types that cross the session thread boundary.
#pragma once

#include "link/linksource.h"
#include "model/devicetuning.h"
#include "model/effects.h"
#include "model/params.h"
#include "protocol/deviceinfo.h"
#include "protocol/legacy.h"
#include "protocol/messages.h"
#include "protocol/v2codec.h"
#include "telemetry/recording.h"

#include <QMetaType>
#include <QString>
#include <QStringList>

#include <array>

namespace hatpic {

struct ConnectOptions
{
    //! The device's name as the user gave it: its path ("/dev/ttyUSB0", a pty) or, with a `link`,
    //! that link's ("sim"). The session words it and records it; it reads no meaning into it.
    QString port;
    qint32 baud = 0; //!< 0 = default (921600 for v2/auto, 115200 for legacy)
    ProtocolChoice protocol = ProtocolChoice::Auto;
    quint16 streamRateHz = 1000; //!< requested telemetry rate (v2); the device may clamp it
    //! Feedback frames per second at most: a new τ_ext goes out at once within this cap, and
    //! the last one again every FeedbackStream::kKeepAliveMs; ≤ 0 = none [Hz]
    double feedbackRateHz = 1000;
    bool autoReconnect = true; //!< reopen the same port after it vanished
    legacy::Conversion legacy; //!< tick and load-unit conversion for legacy devices
    //! What the session connects through, made by the program (the in-process simulator, …);
    //! none: the serial port `port`.
    LinkSourcePtr link;
};

//! A command of the v2 protocol the session sends, by its wire type: HELLO (only while
//! detecting), GET_PARAMS, SET_PARAMS, SET_STREAM, ZERO, SAVE_PARAMS, SET_EFFECTS, GET_EFFECTS,
//! VIBRATE (messages.h).
using CommandKind = v2::MessageType;
//! True for the commands only a device with the effects capability takes.
constexpr bool isEffectCommand(CommandKind kind)
{
    return kind == CommandKind::SetEffects || kind == CommandKind::GetEffects ||
           kind == CommandKind::Vibrate;
}
//! True for the commands only a device with the passivity capability takes (passivity.md).
constexpr bool isPassivityCommand(CommandKind kind)
{
    return kind == CommandKind::SetPassivity || kind == CommandKind::GetPassivity;
}
//! The wire name: "SET_PARAMS", … (messages.h's kName).
inline QString commandName(CommandKind kind)
{
    return QString::fromLatin1(v2::messageName(kind));
}

enum class SessionState { Disconnected, Opening, Detecting, Connected, Lost };
QString sessionStateName(SessionState state); //!< "disconnected", "opening", …

//! Why the session is in its state (stateChanged's detail), in codes, names and numbers. The
//! session composes no sentence; ui/ (with tr()) and hatpicctl word it.
struct StateDetail
{
    enum class Kind {
        None,             //!< nothing to tell (e.g. disconnected by the user)
        Opening,          //!< opening the port
        OpenFailed,       //!< the port did not open: `error` is the system's reason
        UsingLegacy,      //!< the legacy protocol was chosen: no detection
        AskingHello,      //!< v2 was chosen: HELLO sent, waiting for HELLO_REPLY
        Listening,        //!< auto, step 1: listening for legacy frames
        SendingHello,     //!< auto, step 2: HELLO sent, waiting for HELLO_REPLY
        BaudSwitchFailed, //!< auto: the port would not switch to `targetBaud`; `error`
        NoAnswer,     //!< auto: neither protocol answered (listen…, legacyFrames…, helloWaitMs)
        NoHelloReply, //!< v2 chosen: HELLO went unanswered (attempts, intervalMs)
        Refused,      //!< HELLO_REPLY failed the checks; `error` says which (deviceinfo.h)
        ConnectedV2,  //!< a v2 device answered; `firmware`
        ConnectedLegacy, //!< a legacy device was found (or chosen)
        LinkFailed,      //!< lost: `error` is the link's reason
        Silent,          //!< lost: no byte for `silenceMs`
    };
    Kind kind = Kind::None;
    QString port;               //!< as given (ConnectOptions::port)
    bool simulated = false;     //!< the device is a simulator (LinkSource::simulated)
    qint32 baud = 0;            //!< the link's rate at the time [bit/s]
    QString error;              //!< the system's, the link's or the check's own text
    QString firmware;           //!< ConnectedV2: as the device reports it (printable)
    qint32 targetBaud = 0;      //!< BaudSwitchFailed [bit/s]
    qint32 listenBaud = 0;      //!< NoAnswer: the rate it listened at, if not `baud`; else 0
    int listenMs = 0;           //!< NoAnswer: how long it listened [ms]
    int legacyFrames = 0;       //!< NoAnswer: valid legacy frames heard
    int legacyFramesNeeded = 0; //!< NoAnswer: frames that decide "legacy"
    int helloWaitMs = 0;        //!< NoAnswer: how long it waited for HELLO_REPLY [ms]
    int attempts = 0;           //!< NoHelloReply: HELLOs sent
    int intervalMs = 0;         //!< NoHelloReply: between them [ms]
    int silenceMs = 0;          //!< Silent [ms]

    friend bool operator==(const StateDetail &, const StateDetail &) = default;
};

//! "K_max 0.4 → 0.6; detent_strength 0 → 0.05": every field of the parts `to` has that differs
//! from `from`'s as it travels on the wire (the text of recording events and of the tuner's push
//! markers); a part `from` lacks compares with its defaults. Empty when nothing differs. Give it
//! tunings as they travel (a device's, or CommandResult::sent): a value the wire moves inside its
//! bound (±π) would otherwise read as a change.
QString describeTuningChange(const DeviceTuning &from, const DeviceTuning &to);
//! What tells two devices apart, as names and values ("device_id 1397312817 → 42",
//! "tau_limit 0.44 → 0.3"): protocol, protocol version, device id, firmware, tau_limit,
//! max_stream_hz, capabilities and baud, i.e. what a recording's metadata says of its device.
//! Empty: the same device as far as it tells (any two legacy devices are).
QStringList describeDeviceChange(const DeviceInfo &from, const DeviceInfo &to);

//! Registers every type above with Qt's meta-type system (queued signals); idempotent.
void registerSessionMetaTypes();

//! Outcome of one command (a push or a read of the tuning, SET_STREAM, ZERO, SAVE_PARAMS,
//! VIBRATE): what happened, in codes and numbers. The session composes no sentence; ui/ (with tr())
//! and hatpicctl word it.
struct CommandResult
{
    enum class Status {
        Ok,       //!< ACK OK (or PARAMS for GET_PARAMS)
        Rejected, //!< device answered with a non-OK ACK: see ackStatus / field
        Timeout,  //!< no answer after the retries: see attempts, intervalMs
        NotConnected,
        Unsupported, //!< the protocol cannot carry it (legacy): see reason
        Invalid,     //!< refused before sending: see reason
    };
    //! The finer cause, where the status has several.
    enum class Reason {
        None,
        ReadBackUnanswered,    //!< Ok: acknowledged, but the read-back went unanswered
        NoDevice,              //!< NotConnected: no device was connected
        Disconnected,          //!< NotConnected: the session was disconnected before the answer
        ConnectionLost,        //!< NotConnected: the link was lost before the answer
        DetectionFailed,       //!< NotConnected: detection gave up (only the session's HELLO)
        NoParameters,          //!< Unsupported: the legacy firmware cannot send or take parameters
        FixedRate,             //!< Unsupported: the legacy firmware streams at its own rate
        NoEffects,             //!< Unsupported: the legacy firmware cannot render effects
        NoEffectsCapability,   //!< Unsupported: a v2 device without the effects capability bit
        NoPassivityCapability, //!< Unsupported: a device without the passivity capability bit
        InvalidParams,         //!< Invalid: host-side validation refused; see problems
        QueueFull,             //!< Invalid: `limit` commands were already waiting
    };
    Status status = Status::Ok;
    Reason reason = Reason::None;
    //! The command; a failure on the wire names the step it stopped at (a rejection: the frame
    //! refused; a timeout: the frame unanswered; a loss: the frame in flight)
    CommandKind command = CommandKind::GetParams;
    v2::AckStatus ackStatus = v2::AckStatus::Ok;
    int field = -1; //!< ParamBlock (effect block, VIBRATE) index the device named, or -1
    //! A read-back followed each change the command made (SET_PARAMS and ZERO: GET_PARAMS;
    //! SET_EFFECTS: GET_EFFECTS; SET_PASSIVITY: GET_PASSIVITY)
    bool readBack = false;
    bool readBackMatches = false; //!< …and it equals what was sent (ZERO's: always)
    DeviceTuning sent;            //!< a push: what was sent (float32-rounded), the parts it carried
    DeviceTuning received;        //!< a read or a read-back: what the device holds, the parts read
    Vibration vibration;          //!< VIBRATE: what was sent
    quint16 rate = 0;             //!< SET_STREAM: the rate asked for [Hz]; 0 = stop
    int attempts = 0;             //!< Timeout: frames sent
    int intervalMs = 0;           //!< Timeout: between them [ms]
    int limit = 0;                //!< QueueFull: commands that may wait
    QStringList problems;         //!< InvalidParams: the violations, as core/model words them
    bool ok() const { return status == Status::Ok; }
};

//! Something the session tells a person that is neither a state, a command's result nor the
//! device's own text. ui/ and hatpicctl word it.
struct SessionNotice
{
    enum class Kind {
        RecordingNeedsDevice, //!< startRecording() while not connected: nothing was opened
        //! the device was lost and the session does not reconnect: the recording was closed
        //! (files whole)
        RecordingClosedByLoss,
        //! the device was lost while recording: the file stays open and the rows resume in it
        //! when the same device is back (RecordingStatus::waiting)
        RecordingWaitsForDevice,
        RecordingResumed, //!< the same device is back: rows resume, the gap is an event
        //! a different device answered after the loss: the recording was closed at the loss;
        //! `problems` says what differs (describeDeviceChange)
        RecordingClosedOtherDevice,
        HostParamsRefused, //!< setHostParams() refused: `problems`; the old ones stay
    };
    Kind kind = Kind::RecordingNeedsDevice;
    //! HostParamsRefused: the violations, as core/model words them; RecordingClosedOtherDevice:
    //! what differs
    QStringList problems;
};

//! What a push that failed part-way had already changed: the parts the device acknowledged
//! before the step that failed (`result.command`) — each as read back where the read-back came,
//! else as sent. Empty for a push that changed nothing (its first step failed, or it was refused
//! before sending), for any other command, and for a success.
DeviceTuning appliedBeforeFailure(const CommandResult &result);
//! A push whose SET_EFFECTS or SET_PASSIVITY went out and was never answered (no ACK, or the
//! link went): whether the device applied that block is unknown. Gives that step, else nullopt.
std::optional<CommandKind> unansweredBlockStep(const CommandResult &result);

//! A result for `command` with `status` and `reason`; the other fields at their defaults.
CommandResult commandResult(CommandKind command, CommandResult::Status status,
                            CommandResult::Reason reason = CommandResult::Reason::None);

struct LinkStats
{
    double framesPerSecond = 0; //!< received frames, over the last second [1/s]
    double bytesPerSecond = 0;  //!< received bytes, over the last second [B/s]
    quint64 frames = 0;         //!< telemetry (or legacy) frames received
    quint64 bytes = 0;          //!< bytes received
    quint64 seqDrops = 0;       //!< telemetry frames missing by seq gaps (and device time)
    quint64 duplicates = 0;     //!< telemetry frames whose seq was seen already: skipped
    std::array<quint64, v2::kDropReasonCount> decoderDrops{}; //!< v2 drops by reason
    quint64 legacyMalformed = 0;
    double rttLastMs = -1; //!< -1 = none measured yet [ms]
    double rttMedianMs = -1;
    double rttMaxMs = -1;
    quint64 referenceGaps = 0; //!< gaps the reference held across
    quint64 retries = 0;       //!< command frames sent again
    quint64 nonFinite = 0;     //!< telemetry frames with a NaN or ±Inf value: skipped
    quint64 totalDecoderDrops() const;
};

} // namespace hatpic

Q_DECLARE_METATYPE(hatpic::ConnectOptions)
Q_DECLARE_METATYPE(hatpic::SessionState)
Q_DECLARE_METATYPE(hatpic::StateDetail)
Q_DECLARE_METATYPE(hatpic::SessionNotice)
Q_DECLARE_METATYPE(hatpic::DeviceInfo)
Q_DECLARE_METATYPE(hatpic::CommandResult)
Q_DECLARE_METATYPE(hatpic::LinkStats)
Q_DECLARE_METATYPE(hatpic::RecordingStatus)
Q_DECLARE_METATYPE(hatpic::DeviceParams)
Q_DECLARE_METATYPE(hatpic::DeviceTuning)
Q_DECLARE_METATYPE(hatpic::HostParams)
Q_DECLARE_METATYPE(hatpic::EffectParams)
Q_DECLARE_METATYPE(hatpic::PassivityParams)
Q_DECLARE_METATYPE(hatpic::Vibration)
