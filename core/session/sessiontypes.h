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
#include "session/request.h"
#include "telemetry/recording.h"

#include <QMetaType>
#include <QString>
#include <QStringList>

#include <array>
#include <variant>

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
    //! How long detection keeps trying — listening, then HELLO, again — before it gives up: an
    //! ESP32 that resets when the port opens is silent while it boots. ≤ one round (auto: 1 s,
    //! forced v2: the HELLO's resends): one round. The tuner and the bridge give it
    //! kDetectBootMs, hatpicctl its --timeout [ms]
    int detectForMs = 0;
    static constexpr int kDetectBootMs = 3000; //!< an ESP32's reset and boot, with a margin [ms]
    legacy::Conversion legacy;                 //!< tick and load-unit conversion for legacy devices
    //! What the session connects through, made by the program (the in-process simulator, …);
    //! none: the serial port `port`.
    LinkSourcePtr link;
};

enum class SessionState { Disconnected, Opening, Detecting, Connected, Lost };
QString sessionStateName(SessionState state); //!< "disconnected", "opening", …

//! Why the session is in its state (stateChanged's detail), in codes, names and numbers: one
//! type per reason, each with only its own facts. The session composes no sentence; ui/ (with
//! tr()) and hatpicctl word it (SessionWording::stateDetail).
namespace state {
struct None //!< nothing to tell (e.g. disconnected by the user)
{
    friend bool operator==(const None &, const None &) = default;
};
struct Opening //!< opening the port
{
    friend bool operator==(const Opening &, const Opening &) = default;
};
struct OpenFailed //!< the port did not open
{
    QString error; //!< the system's reason
    friend bool operator==(const OpenFailed &, const OpenFailed &) = default;
};
struct UsingLegacy //!< the legacy protocol was chosen: no detection
{
    friend bool operator==(const UsingLegacy &, const UsingLegacy &) = default;
};
struct AskingHello //!< v2 was chosen: HELLO sent, waiting for HELLO_REPLY
{
    friend bool operator==(const AskingHello &, const AskingHello &) = default;
};
struct Listening //!< auto, step 1: listening for legacy frames
{
    friend bool operator==(const Listening &, const Listening &) = default;
};
struct SendingHello //!< auto, step 2: HELLO sent, waiting for HELLO_REPLY
{
    friend bool operator==(const SendingHello &, const SendingHello &) = default;
};
struct BaudSwitchFailed //!< auto: the port would not switch to the v2 rate
{
    qint32 targetBaud = 0; //!< [bit/s]
    QString error;         //!< the link's reason
    friend bool operator==(const BaudSwitchFailed &, const BaudSwitchFailed &) = default;
};
struct NoAnswer //!< auto: neither protocol answered
{
    qint32 listenBaud = 0;      //!< the rate it listened at, if not the detail's `baud`; else 0
    int listenMs = 0;           //!< how long it listened for legacy frames [ms]
    int legacyFrames = 0;       //!< valid legacy frames heard
    int legacyFramesNeeded = 0; //!< frames that decide "legacy"
    int helloWaitMs = 0;        //!< how long it waited for HELLO_REPLY [ms]
    friend bool operator==(const NoAnswer &, const NoAnswer &) = default;
};
struct NoHelloReply //!< v2 chosen: HELLO went unanswered
{
    int attempts = 0;   //!< HELLOs sent
    int intervalMs = 0; //!< between them [ms]
    friend bool operator==(const NoHelloReply &, const NoHelloReply &) = default;
};
struct Refused //!< HELLO_REPLY failed the checks
{
    QString error; //!< which (deviceinfo.h)
    friend bool operator==(const Refused &, const Refused &) = default;
};
struct ConnectedV2 //!< a v2 device answered
{
    QString firmware; //!< as the device reports it (printable)
    friend bool operator==(const ConnectedV2 &, const ConnectedV2 &) = default;
};
struct ConnectedLegacy //!< a legacy device was found (or chosen)
{
    friend bool operator==(const ConnectedLegacy &, const ConnectedLegacy &) = default;
};
struct LinkFailed //!< lost: the link failed
{
    QString error; //!< the link's reason
    friend bool operator==(const LinkFailed &, const LinkFailed &) = default;
};
struct Silent //!< lost: no byte for a while
{
    int silenceMs = 0;
    friend bool operator==(const Silent &, const Silent &) = default;
};
} // namespace state

struct StateDetail
{
    using Why =
        std::variant<state::None, state::Opening, state::OpenFailed, state::UsingLegacy,
                     state::AskingHello, state::Listening, state::SendingHello,
                     state::BaudSwitchFailed, state::NoAnswer, state::NoHelloReply, state::Refused,
                     state::ConnectedV2, state::ConnectedLegacy, state::LinkFailed, state::Silent>;
    Why why;
    QString port;           //!< as given (ConnectOptions::port)
    bool simulated = false; //!< the device is a simulator (LinkSource::simulated)
    qint32 baud = 0;        //!< the link's rate at the time [bit/s]

    template<typename Reason> bool is() const { return std::holds_alternative<Reason>(why); }
    template<typename Reason> const Reason *as() const { return std::get_if<Reason>(&why); }
    friend bool operator==(const StateDetail &, const StateDetail &) = default;
};

//! "K_max 0.4 → 0.6; detent_strength 0 → 0.05": every field of the parts `to` has that differs
//! from `from`'s as it travels on the wire (the text of recording events and of the tuner's push
//! markers); a part `from` lacks compares with its defaults. Empty when nothing differs. Give it
//! tunings as they travel (a device's, or Outcome::pushed()): a value the wire moves inside its
//! bound (±π) would otherwise read as a change.
QString describeTuningChange(const DeviceTuning &from, const DeviceTuning &to);
//! What tells two devices apart, as names and values ("device_id 1397312817 → 42",
//! "tau_limit 0.44 → 0.3"): protocol, protocol version, device id, firmware, tau_limit,
//! max_stream_hz, capabilities and baud, i.e. what a recording's metadata says of its device.
//! Empty: the same device as far as it tells (any two legacy devices are).
QStringList describeDeviceChange(const DeviceInfo &from, const DeviceInfo &to);

//! Registers every type above with Qt's meta-type system (queued signals); idempotent.
void registerSessionMetaTypes();

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
Q_DECLARE_METATYPE(hatpic::LinkStats)
Q_DECLARE_METATYPE(hatpic::RecordingStatus)
Q_DECLARE_METATYPE(hatpic::DeviceParams)
Q_DECLARE_METATYPE(hatpic::DeviceTuning)
Q_DECLARE_METATYPE(hatpic::HostParams)
Q_DECLARE_METATYPE(hatpic::EffectParams)
Q_DECLARE_METATYPE(hatpic::PassivityParams)
Q_DECLARE_METATYPE(hatpic::Vibration)
