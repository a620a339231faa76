// Test helpers for the servo bus: a scripted ServoPort, the emulated servo rig, and the
// simulator's measurement quantisation as it was before the bus was emulated.
#pragma once

#include "firmware/ports.h"
#include "firmware/stsbus.h"
#include "sim/emulatedservoport.h"
#include "sim/emulatedsts3032.h"
#include "sim/servoplant.h"

#include <QByteArray>
#include <QList>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace ststest {

using namespace hatpic;

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

inline QByteArray toBytes(std::span<const std::uint8_t> s)
{
    return QByteArray(reinterpret_cast<const char *>(s.data()), qsizetype(s.size()));
}

//! A bus whose replies are scripted: each write() makes the next scripted bytes arrive.
class ScriptedPort : public fw::ServoPort
{
public:
    void discardInput() override
    {
        rx.clear();
        ++discards;
    }
    void write(std::span<const std::uint8_t> bytes) override
    {
        writes.append(toBytes(bytes));
        if (!script.isEmpty())
            rx += script.takeFirst();
    }
    std::size_t read(std::span<std::uint8_t> out, std::uint32_t timeoutUs) override
    {
        ++reads;
        lastTimeoutUs = timeoutUs;
        const qsizetype n = std::min(qsizetype(out.size()), rx.size());
        std::copy_n(rx.constData(), n, reinterpret_cast<char *>(out.data()));
        rx.remove(0, n);
        return std::size_t(n);
    }

    QList<QByteArray> script;
    QList<QByteArray> writes;
    QByteArray rx;
    int discards = 0;
    int reads = 0;
    std::uint32_t lastTimeoutUs = 0;
};

// The simulator's measurement quantisation before the bus was emulated (simulateddevice.cpp).
inline double simTheta(double theta)
{
    const double ticks = std::round(theta * 4096 / kTwoPi);
    return double(float(ticks * (kTwoPi / 4096)));
}
inline double simTau(double load, double tauLimit)
{
    const double quantum = tauLimit * 1e-3;
    return double(float(std::clamp(std::round(load / quantum) * quantum, -tauLimit, tauLimit)));
}

inline const QByteArray kRead6 = QByteArray::fromHex("ffff0104023806ba");
inline const QByteArray kFeedback = QByteArray::fromHex("ffff010800e8030a80f40588");

//! The servo, its plant and the whole master stack, in process.
struct Rig
{
    explicit Rig(double theta0 = 0.0, EmulatedSts3032::Config config = {})
        : plant(0.44, theta0), servo(plant, config), port(servo), bus(port)
    {}
    ServoPlant plant;
    EmulatedSts3032 servo;
    EmulatedServoPort port;
    fw::StsBus bus;
};

} // namespace ststest
