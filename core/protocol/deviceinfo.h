// Which protocol a device speaks and what it says about itself: the facts the session, the
// simulator, the recordings and the windows share about the device at the other end.
#pragma once

#include "protocol/messages.h"

#include <QString>
#include <QtGlobal>

#include <optional>

namespace hatpic {

enum class WireProtocol { V2, Legacy };
QString wireProtocolName(WireProtocol protocol); //!< "v2" / "legacy"

//! The protocol a connection asks for: found by detection (Auto), or chosen.
enum class ProtocolChoice { Auto, V2, Legacy };
//! The protocol chosen; none for Auto.
constexpr std::optional<WireProtocol> chosenProtocol(ProtocolChoice choice)
{
    if (choice == ProtocolChoice::Auto)
        return std::nullopt;
    return choice == ProtocolChoice::Legacy ? WireProtocol::Legacy : WireProtocol::V2;
}

//! The link's baud rate when none is asked for: protocol.md § 1 (v2) and the published
//! firmware's Serial.begin (legacy). The one definition every program and the simulator read.
constexpr qint32 defaultBaud(WireProtocol protocol)
{
    return protocol == WireProtocol::Legacy ? 115200 : 921600;
}

struct DeviceInfo
{
    WireProtocol protocol = WireProtocol::V2;
    QString port;
    qint32 baud = 0;
    quint8 protocolVersion = 0; //!< 2 for v2, 0 for legacy
    quint16 maxStreamHz = 0;    //!< legacy: 5
    quint32 deviceId = 0;       //!< legacy: 0 (unknown)
    double tauLimit = 0.44;     //!< [N·m]
    QString firmware;           //!< legacy: "published firmware (legacy)"
    bool simulated = false;     //!< the in-process simulator
    quint8 capabilities = 0;    //!< HELLO_REPLY's v2::kCapability* bits; legacy: 0
    quint8 axes = 1;            //!< knobs, 1…kMaxAxes (model/axes.h): 4 for the IMU branch
    bool tilt = false;          //!< it measures its tilt (roll, pitch): the IMU branch
    bool canSetParams() const { return protocol == WireProtocol::V2; }
    //! SET_EFFECTS, GET_EFFECTS, VIBRATE and τ_fx in TELEMETRY (effects.md § 3).
    bool hasEffects() const
    {
        return protocol == WireProtocol::V2 && (capabilities & v2::kCapabilityEffects) != 0;
    }
    //! SET_PASSIVITY, GET_PASSIVITY and τ_pc, R in TELEMETRY (passivity.md).
    bool hasPassivity() const
    {
        return protocol == WireProtocol::V2 && (capabilities & v2::kCapabilityPassivity) != 0;
    }
};

//! Text a device sent, safe to print: printableText() (model/printabletext.h), the one rule for all
//! foreign text, on a QString.
QString printableDeviceText(const QString &text);

//! Why a HELLO_REPLY is nonsense (model.md bounds: tau_limit finite, > 0 and ≤ 10 N·m;
//! max_stream_hz > 0); empty when every field is usable.
QString helloReplyProblem(const v2::HelloReply &reply);

} // namespace hatpic
