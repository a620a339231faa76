// Typed messages of protocol v2 (protocol.md § 3).
#pragma once

#include "model/params.h"

#include <QString>
#include <QtGlobal>

#include <variant>

namespace hatpic::v2 {

enum class MessageType : quint8 {
    // host → device
    Hello = 0x01,
    GetParams = 0x02,
    SetParams = 0x03,
    SetStream = 0x04,
    SetFeedback = 0x05,
    SaveParams = 0x06,
    Ping = 0x07,
    Zero = 0x08,
    // device → host
    HelloReply = 0x81,
    Params = 0x82,
    Ack = 0x83,
    Pong = 0x87,
    Telemetry = 0x90,
    Log = 0xE0,
};

constexpr quint8 kProtocolVersion = 2;
constexpr int kMaxPayload = 240;  //!< largest payload of any frame [bytes]
constexpr quint8 kNoField = 0xFF; //!< ACK `field` when no field applies

enum class AckStatus : quint8 {
    Ok = 0,
    BadLength = 1,
    OutOfRange = 2,
    UnknownType = 3,
    StorageError = 4,
    Unsupported = 5,
};

//! Human-readable name of an ACK status ("OUT_OF_RANGE", …).
QString ackStatusName(AckStatus status);

// Telemetry flag bits.
constexpr quint8 kFlagDeadZone = 0x01;
constexpr quint8 kFlagNotch = 0x02;
constexpr quint8 kFlagSaturated = 0x04;
constexpr quint8 kFlagFeedbackStale = 0x08;

// ---- host → device ----
struct Hello
{
    friend bool operator==(const Hello &, const Hello &) = default;
};
struct GetParams
{
    friend bool operator==(const GetParams &, const GetParams &) = default;
};
struct SetParams
{
    DeviceParams params; //!< travels as 7 × f32
    friend bool operator==(const SetParams &, const SetParams &) = default;
};
struct SetStream
{
    quint16 rateHz = 0; //!< telemetry rate, 0 = stop [Hz]
    friend bool operator==(const SetStream &, const SetStream &) = default;
};
struct SetFeedback
{
    float tauExt = 0; //!< external feedback torque [N·m]
    friend bool operator==(const SetFeedback &, const SetFeedback &) = default;
};
struct SaveParams
{
    friend bool operator==(const SaveParams &, const SaveParams &) = default;
};
struct Ping
{
    quint32 token = 0;
    friend bool operator==(const Ping &, const Ping &) = default;
};
struct Zero
{
    friend bool operator==(const Zero &, const Zero &) = default;
};

// ---- device → host ----
struct HelloReply
{
    quint8 protocolVersion = kProtocolVersion;
    quint16 maxStreamHz = 0; //!< highest telemetry rate the device produces [Hz]
    quint32 deviceId = 0;
    float tauLimit = 0; //!< actuator torque limit [N·m]
    QString firmware;   //!< at most 16 UTF-8 bytes on the wire
    friend bool operator==(const HelloReply &, const HelloReply &) = default;
};
struct Params
{
    DeviceParams params; //!< travels as 7 × f32
    friend bool operator==(const Params &, const Params &) = default;
};
struct Ack
{
    quint8 ackedSeq = 0;
    AckStatus status = AckStatus::Ok;
    quint8 field = kNoField; //!< first violating ParamBlock index for OUT_OF_RANGE
    friend bool operator==(const Ack &, const Ack &) = default;
};
struct Pong
{
    quint32 token = 0;
    friend bool operator==(const Pong &, const Pong &) = default;
};
struct Telemetry
{
    quint32 t_us = 0;  //!< device clock, wraps at 2³² [µs]
    float theta = 0;   //!< absolute knob angle [rad]
    float omega = 0;   //!< knob rate [rad/s]
    float tau = 0;     //!< interaction torque of eq. (1); operator torque is −tau [N·m]
    float tau_rec = 0; //!< re-centering torque rendered this cycle [N·m]
    float tau_ext = 0; //!< external feedback rendered this cycle [N·m]
    quint8 flags = 0;  //!< kFlag* bits
    friend bool operator==(const Telemetry &, const Telemetry &) = default;
};
struct Log
{
    QString text; //!< 1…240 UTF-8 bytes on the wire
    friend bool operator==(const Log &, const Log &) = default;
};

//! A frame that passed the CRC but has a type unknown to the receiver or a payload length
//! wrong for its type. The decoder counts it as dropped; a device answers it with an ACK
//! carrying `status` (UNKNOWN_TYPE or BAD_LENGTH) and `seq`.
struct Refused
{
    quint8 type = 0;
    AckStatus status = AckStatus::UnknownType;
    friend bool operator==(const Refused &, const Refused &) = default;
};

using Message = std::variant<Hello, GetParams, SetParams, SetStream, SetFeedback, SaveParams, Ping,
                             Zero, HelloReply, Params, Ack, Pong, Telemetry, Log, Refused>;

//! The wire type of a message (Refused gives its original type).
quint8 messageType(const Message &message);

//! One decoded frame.
struct Frame
{
    quint8 seq = 0;
    Message message;
    friend bool operator==(const Frame &, const Frame &) = default;
};

} // namespace hatpic::v2
