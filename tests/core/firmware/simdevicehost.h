// A host on the simulator's device core, without a link: sends frames, decodes the replies,
// steps the device while waiting. Shared by the device core's protocol tests
// (tst_deviceeffects, tst_devicepassivity), which drive the simulator's ideal mode.
#pragma once

#include "protocol/v2codec.h"
#include "sim/simulateddevice.h"

#include <QList>
#include <QString>

#include <optional>

namespace simdevicehost {

using namespace hatpic;

class Host
{
public:
    explicit Host(const SimulatedDevice::Config &config) : device(config) {}
    void send(quint8 seq, const v2::Message &message)
    {
        device.receive(v2::encodeFrame(seq, message));
    }
    QList<v2::Frame> take()
    {
        QList<v2::Frame> frames;
        decoder.feed(device.takeOutput(), frames);
        return frames;
    }
    //! The first reply of type T within 20 control cycles.
    template<typename T> std::optional<T> reply()
    {
        for (int i = 0; i < 20; ++i) {
            for (const v2::Frame &f : take()) {
                if (const auto *m = std::get_if<T>(&f.message))
                    return *m;
            }
            device.advance(1e-3);
        }
        return std::nullopt;
    }
    SimulatedDevice device;
    v2::FrameDecoder decoder{v2::Direction::FromDevice};
};

//! The simulator's ideal mode (the model as the actuator), unthrottled, with `hand`.
inline SimulatedDevice::Config idealConfig(const QString &hand = QStringLiteral("idle"))
{
    SimulatedDevice::Config c;
    c.ideal = true;
    c.throttle = false;
    c.hand = HandInput::parse(hand).value_or(HandInput{});
    return c;
}

} // namespace simdevicehost
