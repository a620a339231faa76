// Helpers shared by the v2 protocol tests: readable messages and seeded random messages.
#pragma once

#include "protocol/v2codec.h"

#include <QRandomGenerator>
#include <QString>
#include <QTest>

#include <cstring>

namespace hatpic::v2 {

using namespace Qt::StringLiterals;

inline QString describeParams(const DeviceParams &p)
{
    QString s;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        s += (i ? u", "_s : QString()) + QString::number(p.field(i), 'g', 17);
    return s;
}

//! One-line description of a message, for failure output.
inline QString describe(const Message &message)
{
    return std::visit(
        [](const auto &m) -> QString {
            using T = std::decay_t<decltype(m)>;
            const QString type = QString::number(messageType(Message(m)), 16);
            if constexpr (std::is_same_v<T, SetParams> || std::is_same_v<T, Params>)
                return u"0x"_s + type + u" params ["_s + describeParams(m.params) + u']';
            else if constexpr (std::is_same_v<T, SetStream>)
                return u"SET_STREAM "_s + QString::number(m.rateHz);
            else if constexpr (std::is_same_v<T, SetFeedback>)
                return u"SET_FEEDBACK "_s + QString::number(m.tauExt, 'g', 9);
            else if constexpr (std::is_same_v<T, Ping> || std::is_same_v<T, Pong>)
                return u"0x"_s + type + u" token "_s + QString::number(m.token, 16);
            else if constexpr (std::is_same_v<T, HelloReply>)
                return u"HELLO_REPLY v%1 max %2 Hz id %3 tau_limit %4 fw '%5'"_s
                    .arg(m.protocolVersion)
                    .arg(m.maxStreamHz)
                    .arg(m.deviceId)
                    .arg(double(m.tauLimit), 0, 'g', 9)
                    .arg(toQString(m.firmware));
            else if constexpr (std::is_same_v<T, Ack>)
                return u"ACK of %1 %2 field %3"_s.arg(m.ackedSeq)
                    .arg(ackStatusName(m.status))
                    .arg(m.field);
            else if constexpr (std::is_same_v<T, Telemetry>)
                return u"TELEMETRY t %1 theta %2 omega %3 tau %4 rec %5 ext %6 flags %7"_s
                    .arg(m.t_us)
                    .arg(double(m.theta), 0, 'g', 9)
                    .arg(double(m.omega), 0, 'g', 9)
                    .arg(double(m.tau), 0, 'g', 9)
                    .arg(double(m.tau_rec), 0, 'g', 9)
                    .arg(double(m.tau_ext), 0, 'g', 9)
                    .arg(m.flags);
            else if constexpr (std::is_same_v<T, Log>)
                return u"LOG '"_s + toQString(m.text) + u'\'';
            else if constexpr (std::is_same_v<T, Refused>)
                return u"REFUSED type 0x"_s + QString::number(m.type, 16) + u' ' +
                       ackStatusName(m.status);
            else
                return u"type 0x"_s + type;
        },
        message);
}

//! QTest prints messages and frames with these (found by argument-dependent lookup).
inline char *toString(const Message &message)
{
    return qstrdup(describe(message).toUtf8().constData());
}
inline char *toString(const Frame &frame)
{
    const QString s = u"seq %1: "_s.arg(frame.seq) + describe(frame.message);
    return qstrdup(s.toUtf8().constData());
}

} // namespace hatpic::v2

namespace v2test {

using namespace hatpic;
using namespace hatpic::v2;

//! A float that survives the wire unchanged (finite; NaN never compares equal).
inline float randomFloat(QRandomGenerator &rng)
{
    switch (rng.bounded(4)) {
    case 0:
        return 0.0f;
    case 1: // any finite bit pattern, including denormals and extremes
        for (;;) {
            const quint32 bits = rng.generate();
            float f = 0;
            std::memcpy(&f, &bits, sizeof f);
            if (std::isfinite(f))
                return f;
        }
    default:
        return static_cast<float>(rng.bounded(20.0) - 10.0);
    }
}

//! A double that is exactly representable as a float, so it survives the wire unchanged.
inline double randomWireDouble(QRandomGenerator &rng)
{
    return static_cast<double>(randomFloat(rng));
}

inline DeviceParams randomParams(QRandomGenerator &rng)
{
    DeviceParams p;
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        p.setField(i, randomWireDouble(rng));
    return p;
}

//! Random text of valid UTF-8 (1-, 2-, 3- and 4-byte characters, no NUL) of at most
//! `maxBytes` and at least `minBytes` UTF-8 bytes.
inline QString randomText(QRandomGenerator &rng, int minBytes, int maxBytes)
{
    static const char32_t kChars[] = {U'a', U'Z', U'0', U' ', U'~',  U'\n', U'i',         U'\x01',
                                      U'é', U'ß', U'Ω', U'€', U'中', U'😀',  U'\U0010FFFF'};
    const int target = minBytes + int(rng.bounded(maxBytes - minBytes + 1));
    QString text;
    int bytes = 0;
    for (int tries = 0; tries < 1000 && bytes < target; ++tries) {
        const char32_t c = kChars[rng.bounded(int(std::size(kChars)))];
        const QString s = QString::fromUcs4(&c, 1);
        const int n = int(s.toUtf8().size());
        if (bytes + n > maxBytes)
            continue;
        text += s;
        bytes += n;
    }
    while (bytes < minBytes) { // only single-byte characters fit now
        text += u'x';
        ++bytes;
    }
    return text;
}

inline PassivityParams randomPassivity(QRandomGenerator &rng)
{
    PassivityParams p;
    for (int i = 0; i < PassivityParams::kFieldCount; ++i)
        p.setField(i, double(randomFloat(rng)));
    return p;
}

//! A random message travelling in `direction`.
inline Message randomMessage(QRandomGenerator &rng, Direction direction)
{
    if (direction == Direction::FromHost) {
        switch (rng.bounded(13)) {
        case 11:
            return SetPassivity{randomPassivity(rng)};
        case 12:
            return GetPassivity{};
        case 8: {
            EffectParams fx;
            for (int i = 0; i < EffectParams::kFieldCount; ++i)
                fx.setField(i, double(randomFloat(rng)));
            return SetEffects{fx};
        }
        case 9:
            return GetEffects{};
        case 10:
            return Vibrate{randomFloat(rng), randomFloat(rng), randomFloat(rng)};
        case 0:
            return Hello{};
        case 1:
            return GetParams{};
        case 2:
            return SetParams{randomParams(rng)};
        case 3:
            return SetStream{quint16(rng.bounded(65536))};
        case 4:
            return SetFeedback{randomFloat(rng)};
        case 5:
            return SaveParams{};
        case 6:
            return Ping{rng.generate()};
        default:
            return Zero{};
        }
    }
    switch (rng.bounded(8)) {
    case 6:
        return Passivity{randomPassivity(rng)};
    case 0: {
        HelloReply m;
        m.protocolVersion = quint8(rng.bounded(256));
        m.capabilities = quint8(rng.bounded(256));
        m.maxStreamHz = quint16(rng.bounded(65536));
        m.deviceId = rng.generate();
        m.tauLimit = randomFloat(rng);
        m.firmware = fixedText<kFirmwareBytes>(randomText(rng, 0, 16));
        return m;
    }
    case 1:
        return Params{randomParams(rng)};
    case 2: {
        Ack m;
        m.ackedSeq = quint8(rng.bounded(256));
        m.status = AckStatus(rng.bounded(6));
        m.field = quint8(rng.bounded(256));
        return m;
    }
    case 3:
        return Pong{rng.generate()};
    case 4: {
        Telemetry m;
        m.t_us = rng.generate();
        m.theta = randomFloat(rng);
        m.omega = randomFloat(rng);
        m.tau = randomFloat(rng);
        m.tau_rec = randomFloat(rng);
        m.tau_ext = randomFloat(rng);
        m.flags = quint8(rng.bounded(16));
        // The optional tail in order: τ_fx, then τ_pc and R (each only after all before it).
        if (rng.bounded(2)) {
            m.tau_fx = randomFloat(rng);
            if (rng.bounded(2)) {
                m.tau_pc = randomFloat(rng);
                m.pc_reserve = randomFloat(rng);
            }
        }
        return m;
    }
    case 5: {
        EffectParams fx;
        for (int i = 0; i < EffectParams::kFieldCount; ++i)
            fx.setField(i, double(randomFloat(rng)));
        return Effects{fx};
    }
    default:
        return Log{fixedText<kMaxPayload>(randomText(rng, 1, kMaxPayload))};
    }
}

//! Number of messages for the seeded random tests (HATPIC_FUZZ_COUNT raises it).
inline int fuzzCount(int fallback = 10000)
{
    bool ok = false;
    const int n = qEnvironmentVariableIntValue("HATPIC_FUZZ_COUNT", &ok);
    return ok && n > 0 ? n : fallback;
}

} // namespace v2test
