// Value types that cross the session thread boundary.
#pragma once

#include "model/params.h"
#include "protocol/deviceinfo.h"
#include "protocol/legacy.h"
#include "protocol/messages.h"
#include "protocol/v2codec.h"
#include "sim/handinput.h"
#include "sim/simulateddevice.h"
#include "telemetry/recording.h"

#include <QMetaType>
#include <QString>

#include <array>

namespace hatpic {

//! The port name that selects the in-process simulated joystick.
inline constexpr char16_t kSimPortName[] = u"sim";

enum class ProtocolChoice { Auto, V2, Legacy };

struct ConnectOptions
{
    QString port;    //!< device path ("/dev/ttyUSB0", a pty) or "sim"
    qint32 baud = 0; //!< 0 = default (921600 for v2/auto, 115200 for legacy)
    ProtocolChoice protocol = ProtocolChoice::Auto;
    quint16 streamRateHz = 1000; //!< requested telemetry rate (v2); the device may clamp it
    double feedbackRateHz = 100; //!< feedback frames per second; ≤ 0 = none [Hz]
    bool autoReconnect = true;   //!< reopen the same port after it vanished
    legacy::Conversion legacy;   //!< tick and load-unit conversion for legacy devices
    SimulatedDevice::Config sim; //!< used when port == "sim"
};

//! The commands of the v2 protocol the session sends (HELLO only while detecting).
enum class CommandKind { Hello, GetParams, SetParams, SetStream, Zero, SaveParams };
QString commandName(CommandKind kind); //!< the wire name: "SET_PARAMS", …

enum class SessionState { Disconnected, Opening, Detecting, Connected, Lost };
QString sessionStateName(SessionState state); //!< "disconnected", "opening", …

//! "K_max 0.4 → 0.6; N 0.1 → 0.12": every device field that differs as it travels on the wire
//! (the text of recording events and of the tuner's push markers). Empty when nothing does.
QString describeParamChange(const DeviceParams &from, const DeviceParams &to);

//! Registers every type above with Qt's meta-type system (queued signals); idempotent.
void registerSessionMetaTypes();

//! Outcome of one command (SET_PARAMS, SET_STREAM, ZERO, SAVE_PARAMS, GET_PARAMS).
struct CommandResult
{
    enum class Status {
        Ok,       //!< ACK OK (or PARAMS for GET_PARAMS)
        Rejected, //!< device answered with a non-OK ACK: see ackStatus / field
        Timeout,  //!< no answer after the retries
        NotConnected,
        Unsupported, //!< the protocol cannot carry it (legacy)
        Invalid,     //!< refused by host-side validation before sending
    };
    Status status = Status::Ok;
    v2::AckStatus ackStatus = v2::AckStatus::Ok;
    int field = -1;               //!< ParamBlock index the device named, or -1
    QString message;              //!< one clear sentence for a person
    bool readBack = false;        //!< a GET_PARAMS read-back followed (SET_PARAMS, ZERO)
    bool readBackMatches = false; //!< SET_PARAMS: the read-back equals what was sent (float32)
    bool ok() const { return status == Status::Ok; }
};

struct LinkStats
{
    double framesPerSecond = 0; //!< received frames, over the last second [1/s]
    double bytesPerSecond = 0;  //!< received bytes, over the last second [B/s]
    quint64 frames = 0;         //!< telemetry (or legacy) frames received
    quint64 bytes = 0;          //!< bytes received
    quint64 seqDrops = 0;       //!< telemetry frames missing by seq gaps
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
Q_DECLARE_METATYPE(hatpic::DeviceInfo)
Q_DECLARE_METATYPE(hatpic::CommandResult)
Q_DECLARE_METATYPE(hatpic::LinkStats)
Q_DECLARE_METATYPE(hatpic::RecordingStatus)
Q_DECLARE_METATYPE(hatpic::DeviceParams)
Q_DECLARE_METATYPE(hatpic::HostParams)
