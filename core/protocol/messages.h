// Typed messages of protocol v2 (protocol.md § 3): one set of layouts for the host and the
// device core.
//
// Plain C++20: no Qt, no OS calls, no allocation (text fields are fixed arrays).
#pragma once

#include "model/axes.h"
#include "model/capabilities.h"
#include "model/cyclequantities.h"
#include "model/effects.h"
#include "model/params.h"
#include "model/passivity.h"
#include "model/stiffness.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>
#include <variant>

namespace hatpic::v2 {

enum class MessageType : std::uint8_t {
    // host → device
    Hello = 0x01,
    GetParams = 0x02,
    SetParams = 0x03,
    SetStream = 0x04,
    SetFeedback = 0x05,
    SaveParams = 0x06,
    Ping = 0x07,
    Zero = 0x08,
    SetEffects = 0x09, //!< effects.md § 3
    GetEffects = 0x0A,
    Vibrate = 0x0B,
    SetPassivity = 0x0C, //!< passivity.md (docs/protocol.md)
    GetPassivity = 0x0D,
    // device → host
    HelloReply = 0x81,
    Params = 0x82,
    Ack = 0x83,
    Pong = 0x87,
    Effects = 0x8A,
    Passivity = 0x8D,
    Telemetry = 0x90,
    Log = 0xE0,
};

constexpr std::uint8_t kProtocolVersion = 2;
constexpr std::size_t kMaxPayload = 240; //!< largest payload of any frame [bytes]
constexpr std::uint8_t kNoField = 0xFF;  //!< ACK `field` when no field applies
//! ACK `field` of OUT_OF_RANGE when the command's `axis` names no knob of the device.
constexpr std::uint8_t kAxisField = 0xFE;
constexpr std::size_t kFirmwareBytes = 16; //!< HELLO_REPLY's firmware name [bytes]

enum class AckStatus : std::uint8_t {
    Ok = 0,
    BadLength = 1,
    OutOfRange = 2,
    UnknownType = 3,
    StorageError = 4,
    Unsupported = 5,
};

//! Wire name of an ACK status ("OUT_OF_RANGE", …); empty for a status this build does not know.
std::string_view ackStatusWireName(AckStatus status);

// Telemetry flag bits.
constexpr std::uint8_t kFlagDeadZone = 0x01;
constexpr std::uint8_t kFlagNotch = 0x02;
constexpr std::uint8_t kFlagSaturated = 0x04;
constexpr std::uint8_t kFlagFeedbackStale = 0x08;
//! The device has turned the servo's torque off after a fault (100 bus errors in a row,
//! servo.md § 1) and keeps it off: set on every frame from then on.
constexpr std::uint8_t kFlagTorqueOff = 0x10;

//! The flag bit that says which stiffness zone θ lies in (kFlagDeadZone, kFlagNotch; none for
//! the outer zone): the device core sets it, and the host for legacy samples.
constexpr std::uint8_t zoneFlag(StiffnessZone zone)
{
    switch (zone) {
    case StiffnessZone::DeadZone:
        return kFlagDeadZone;
    case StiffnessZone::Notch:
        return kFlagNotch;
    case StiffnessZone::Outer:
        break;
    }
    return 0;
}

//! UTF-8 text of at most N bytes, stored inline. Assigning longer text cuts it at a character
//! boundary, so a name never ends in half a character.
template<std::size_t N> class FixedText
{
public:
    FixedText() = default;
    explicit FixedText(std::string_view text) { assign(text); }

    void assign(std::string_view text)
    {
        std::size_t n = std::min(text.size(), N);
        // Back off while the byte at the cut is a continuation byte (10xxxxxx).
        if (n < text.size()) {
            while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80)
                --n;
        }
        std::copy_n(text.data(), n, m_bytes.data());
        m_size = n;
    }
    std::string_view view() const { return {m_bytes.data(), m_size}; }
    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    static constexpr std::size_t capacity() { return N; }

    bool operator==(const FixedText &other) const { return view() == other.view(); }

private:
    std::array<char, N> m_bytes{};
    std::size_t m_size = 0;
};

// ---- how a message describes its payload ----
//
// Each message names its wire type once (`kType`, and `kName` as protocol.md spells it) and
// lists its payload fields once, in wire
// order, in `static constexpr void fields(auto &m, auto &v) { v(m.a); v(m.b); … }`. The codec
// (framecodec.*) derives from that one list the payload size, the encoding, the decoding and
// the lengths a receiver accepts. A message without fields() has no payload. A field's C++ type
// gives its wire form:
//   std::uint8_t, std::uint16_t, std::uint32_t, enums  little-endian unsigned of that size
//   float                                              IEEE-754 binary32
//   DeviceParams, EffectParams                         their fields in wire order, each an f32
//   FixedText<N>                                       N bytes, NUL-padded; read up to a NUL
//   Reserved                                           one byte: 0 when sent, ignored when read
//   a struct with fields()                             its fields in their order (KnobTelemetry)
//   std::optional<T> (last; several may follow each other, each sent only after all before it)
//                                                      T when present; a receiver accepts a
//                                                      longer payload (up to kMaxPayload) and
//                                                      reads T when its bytes are there
//   Rest{text} (last)                                  the rest of the payload: 1…N bytes

//! A byte the layout reserves: sent as 0, ignored when read.
struct Reserved
{};

//! Text that fills the rest of the payload, at least one byte (LOG).
template<typename Text> struct Rest
{
    Text &text;
};
template<typename Text> Rest(Text &) -> Rest<Text>;

//! The knob a per-knob command or reply is about (kCapabilityAxes): 0 for knob 1 … axes − 1.
//! Absent on the wire means knob 1, so a single-knob host and device never send it.
using AxisIndex = std::optional<std::uint8_t>;
//! The knob index `axis` names (0 when absent).
constexpr int knobIndex(const AxisIndex &axis)
{
    return axis.value_or(0);
}

// ---- host → device ----
struct Hello
{
    static constexpr MessageType kType = MessageType::Hello;
    static constexpr std::string_view kName = "HELLO";
    friend bool operator==(const Hello &, const Hello &) = default;
};
struct GetParams
{
    static constexpr MessageType kType = MessageType::GetParams;
    static constexpr std::string_view kName = "GET_PARAMS";
    AxisIndex axis{};
    static constexpr void fields(auto &m, auto &v) { v(m.axis); }
    friend bool operator==(const GetParams &, const GetParams &) = default;
};
struct SetParams
{
    static constexpr MessageType kType = MessageType::SetParams;
    static constexpr std::string_view kName = "SET_PARAMS";
    DeviceParams params; //!< travels as 7 × f32
    AxisIndex axis{};
    static constexpr void fields(auto &m, auto &v)
    {
        v(m.params);
        v(m.axis);
    }
    friend bool operator==(const SetParams &, const SetParams &) = default;
};
struct SetStream
{
    static constexpr MessageType kType = MessageType::SetStream;
    static constexpr std::string_view kName = "SET_STREAM";
    std::uint16_t rateHz = 0; //!< telemetry rate, 0 = stop [Hz]
    static constexpr void fields(auto &m, auto &v) { v(m.rateHz); }
    friend bool operator==(const SetStream &, const SetStream &) = default;
};
struct SetFeedback
{
    static constexpr MessageType kType = MessageType::SetFeedback;
    static constexpr std::string_view kName = "SET_FEEDBACK";
    float tauExt = 0; //!< external feedback torque [N·m] (knob 1)
    //! τ_ext of knobs 2, 3, 4 (kCapabilityAxes) [N·m]. Sent in order, so only the last ones
    //! can be absent; a knob without a value keeps the one it had (and its watchdog runs on).
    std::array<std::optional<float>, kMaxAxes - 1> more{};
    static constexpr void fields(auto &m, auto &v)
    {
        v(m.tauExt);
        for (auto &tau : m.more)
            v(tau);
    }
    friend bool operator==(const SetFeedback &, const SetFeedback &) = default;
};
struct SaveParams
{
    static constexpr MessageType kType = MessageType::SaveParams;
    static constexpr std::string_view kName = "SAVE_PARAMS";
    friend bool operator==(const SaveParams &, const SaveParams &) = default;
};
struct Ping
{
    static constexpr MessageType kType = MessageType::Ping;
    static constexpr std::string_view kName = "PING";
    std::uint32_t token = 0;
    static constexpr void fields(auto &m, auto &v) { v(m.token); }
    friend bool operator==(const Ping &, const Ping &) = default;
};
struct Zero
{
    static constexpr MessageType kType = MessageType::Zero;
    static constexpr std::string_view kName = "ZERO";
    AxisIndex axis{};
    static constexpr void fields(auto &m, auto &v) { v(m.axis); }
    friend bool operator==(const Zero &, const Zero &) = default;
};
struct SetEffects
{
    static constexpr MessageType kType = MessageType::SetEffects;
    static constexpr std::string_view kName = "SET_EFFECTS";
    EffectParams effects; //!< travels as 7 × f32
    AxisIndex axis{};
    static constexpr void fields(auto &m, auto &v)
    {
        v(m.effects);
        v(m.axis);
    }
    friend bool operator==(const SetEffects &, const SetEffects &) = default;
};
struct SetPassivity
{
    static constexpr MessageType kType = MessageType::SetPassivity;
    static constexpr std::string_view kName = "SET_PASSIVITY";
    PassivityParams passivity; //!< travels as 2 × f32
    AxisIndex axis{};
    static constexpr void fields(auto &m, auto &v)
    {
        v(m.passivity);
        v(m.axis);
    }
    friend bool operator==(const SetPassivity &, const SetPassivity &) = default;
};
struct GetPassivity
{
    static constexpr MessageType kType = MessageType::GetPassivity;
    static constexpr std::string_view kName = "GET_PASSIVITY";
    AxisIndex axis{};
    static constexpr void fields(auto &m, auto &v) { v(m.axis); }
    friend bool operator==(const GetPassivity &, const GetPassivity &) = default;
};
struct GetEffects
{
    static constexpr MessageType kType = MessageType::GetEffects;
    static constexpr std::string_view kName = "GET_EFFECTS";
    AxisIndex axis{};
    static constexpr void fields(auto &m, auto &v) { v(m.axis); }
    friend bool operator==(const GetEffects &, const GetEffects &) = default;
};
struct Vibrate
{
    static constexpr MessageType kType = MessageType::Vibrate;
    static constexpr std::string_view kName = "VIBRATE";
    float amplitude = 0; //!< a [N·m]; 0 stops a running cue
    float frequency = 0; //!< f [Hz]
    float duration = 0;  //!< d [s]
    AxisIndex axis{};
    static constexpr void fields(auto &m, auto &v)
    {
        v(m.amplitude);
        v(m.frequency);
        v(m.duration);
        v(m.axis);
    }
    friend bool operator==(const Vibrate &, const Vibrate &) = default;
};

// ---- device → host ----
struct HelloReply
{
    static constexpr MessageType kType = MessageType::HelloReply;
    static constexpr std::string_view kName = "HELLO_REPLY";
    std::uint8_t protocolVersion = kProtocolVersion;
    std::uint8_t capabilities = 0; //!< kCapability* bits (0 on devices before effects.md)
    std::uint16_t maxStreamHz = 0; //!< highest telemetry rate the device produces [Hz]
    std::uint32_t deviceId = 0;
    float tauLimit = 0;                 //!< actuator torque limit [N·m]
    FixedText<kFirmwareBytes> firmware; //!< NUL-padded on the wire
    //! Knobs on the device, 2…kMaxAxes; sent with kCapabilityAxes only (absent: one knob).
    std::optional<std::uint8_t> axes{};
    static constexpr void fields(auto &m, auto &v)
    {
        v(m.protocolVersion);
        v(m.capabilities);
        v(m.maxStreamHz);
        v(m.deviceId);
        v(m.tauLimit);
        v(m.firmware);
        v(m.axes);
    }
    friend bool operator==(const HelloReply &, const HelloReply &) = default;
};
struct Params
{
    static constexpr MessageType kType = MessageType::Params;
    static constexpr std::string_view kName = "PARAMS";
    DeviceParams params; //!< travels as 7 × f32
    AxisIndex axis{};    //!< the request's, when it named one
    static constexpr void fields(auto &m, auto &v)
    {
        v(m.params);
        v(m.axis);
    }
    friend bool operator==(const Params &, const Params &) = default;
};
struct Effects
{
    static constexpr MessageType kType = MessageType::Effects;
    static constexpr std::string_view kName = "EFFECTS";
    EffectParams effects; //!< travels as 7 × f32
    AxisIndex axis{};     //!< the request's, when it named one
    static constexpr void fields(auto &m, auto &v)
    {
        v(m.effects);
        v(m.axis);
    }
    friend bool operator==(const Effects &, const Effects &) = default;
};
struct Passivity
{
    static constexpr MessageType kType = MessageType::Passivity;
    static constexpr std::string_view kName = "PASSIVITY";
    PassivityParams passivity; //!< travels as 2 × f32
    AxisIndex axis{};          //!< the request's, when it named one
    static constexpr void fields(auto &m, auto &v)
    {
        v(m.passivity);
        v(m.axis);
    }
    friend bool operator==(const Passivity &, const Passivity &) = default;
};
struct Ack
{
    static constexpr MessageType kType = MessageType::Ack;
    static constexpr std::string_view kName = "ACK";
    std::uint8_t ackedSeq = 0;
    AckStatus status = AckStatus::Ok;
    std::uint8_t field = kNoField; //!< first violating ParamBlock index for OUT_OF_RANGE
    static constexpr void fields(auto &m, auto &v)
    {
        v(m.ackedSeq);
        v(m.status);
        v(m.field);
        v(Reserved{});
    }
    friend bool operator==(const Ack &, const Ack &) = default;
};
struct Pong
{
    static constexpr MessageType kType = MessageType::Pong;
    static constexpr std::string_view kName = "PONG";
    std::uint32_t token = 0;
    static constexpr void fields(auto &m, auto &v) { v(m.token); }
    friend bool operator==(const Pong &, const Pong &) = default;
};
//! One further knob's quantities in TELEMETRY: every quantity of the cycle but t_us, in their
//! order, each an f32 but the flags (33 bytes). All of them: a device with several knobs has
//! the effects and passivity capabilities.
struct KnobTelemetry
{
    float theta = 0;
    float omega = 0;
    float tau = 0;
    float tau_rec = 0;
    float tau_ext = 0;
    std::uint8_t flags = 0;
    float tau_fx = 0;
    float tau_pc = 0;
    float pc_reserve = 0;
    static constexpr void fields(auto &m, auto &v)
    {
        forEachKnobQuantity<KnobTelemetry>(
            [&](const CycleQuantity &, auto member) { v(m.*member); });
    }
    friend bool operator==(const KnobTelemetry &, const KnobTelemetry &) = default;
};
struct Telemetry
{
    static constexpr MessageType kType = MessageType::Telemetry;
    static constexpr std::string_view kName = "TELEMETRY";
    std::uint32_t t_us = 0; //!< device clock, wraps at 2³² [µs]
    float theta = 0;        //!< absolute knob angle [rad]
    float omega = 0;        //!< knob rate [rad/s]
    float tau = 0;          //!< interaction torque of eq. (1); operator torque is −tau [N·m]
    float tau_rec = 0;      //!< re-centering torque rendered this cycle [N·m]
    float tau_ext = 0;      //!< external feedback rendered this cycle [N·m]
    std::uint8_t flags = 0; //!< kFlag* bits
    //! τ_det + τ_wall + τ_vib rendered this cycle [N·m]; only devices with the effects
    //! capability send it (a 29-byte TELEMETRY).
    std::optional<float> tau_fx;
    //! τ_pc = −β·ω, the passivity controller's torque this cycle [N·m], and its reserve R
    //! after the cycle [J]; only devices with the passivity capability send them, after
    //! τ_fx (a 37-byte TELEMETRY).
    std::optional<float> tau_pc;
    std::optional<float> pc_reserve;
    //! Knobs 2 … axes of a device with kCapabilityAxes, after R (136 bytes with four knobs).
    std::array<std::optional<KnobTelemetry>, kMaxAxes - 1> more{};
    //! The cycle's quantities in their order (model/cyclequantities.h), then the further knobs.
    static constexpr void fields(auto &m, auto &v)
    {
        forEachCycleQuantity<Telemetry>([&](const CycleQuantity &, auto member) { v(m.*member); });
        for (auto &knob : m.more)
            v(knob);
    }
    friend bool operator==(const Telemetry &, const Telemetry &) = default;
};
struct Log
{
    static constexpr MessageType kType = MessageType::Log;
    static constexpr std::string_view kName = "LOG";
    FixedText<kMaxPayload> text; //!< 1…240 UTF-8 bytes on the wire
    static constexpr void fields(auto &m, auto &v) { v(Rest{m.text}); }
    friend bool operator==(const Log &, const Log &) = default;
};

//! A frame that passed the CRC but has a type unknown to the receiver or a payload length
//! wrong for its type. The decoder counts it as dropped; a device answers it with an ACK
//! carrying `status` (UNKNOWN_TYPE or BAD_LENGTH) and `seq`.
struct Refused
{
    std::uint8_t type = 0;
    AckStatus status = AckStatus::UnknownType;
    friend bool operator==(const Refused &, const Refused &) = default;
};

//! Every message, the one list of them: the decoder looks a wire type up among these (each
//! `kType`), the encoder writes any of them. Refused, last, is what a receiver made of a frame.
using Message =
    std::variant<Hello, GetParams, SetParams, SetStream, SetFeedback, SaveParams, Ping, Zero,
                 SetEffects, GetEffects, Vibrate, SetPassivity, GetPassivity, HelloReply, Params,
                 Effects, Passivity, Ack, Pong, Telemetry, Log, Refused>;

//! The wire type of a message (Refused gives its original type).
std::uint8_t messageType(const Message &message);

//! The name of a wire type as protocol.md spells it ("SET_PARAMS"); empty for an unknown one.
constexpr std::string_view messageName(MessageType type)
{
    std::string_view name;
    const auto nameIf = [&]<typename M>(std::type_identity<M>) {
        if constexpr (requires { M::kName; }) {
            if (M::kType == type)
                name = M::kName;
        }
    };
    [&]<typename... M>(std::type_identity<std::variant<M...>>) {
        (nameIf(std::type_identity<M>{}), ...);
    }(std::type_identity<Message>{});
    return name;
}

//! One decoded frame.
struct Frame
{
    std::uint8_t seq = 0;
    Message message;
    friend bool operator==(const Frame &, const Frame &) = default;
};

} // namespace hatpic::v2
