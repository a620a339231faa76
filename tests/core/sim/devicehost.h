// Driving a SimulatedDevice offline as a host would, for the simulated device's tests
// (tst_simulateddevice, tst_simulateddevicelink, tst_simulateddevicemodel): frames in, decoded
// frames out, and the few helpers they share.
#pragma once

#include "model/params.h"
#include "sim/simulateddevice.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <numbers>
#include <optional>
#include <variant>

namespace hatpic::test {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

inline DeviceParams f32Params(DeviceParams p)
{
    for (int i = 0; i < DeviceParams::kFieldCount; ++i)
        p.setField(i, double(float(p.field(i))));
    return p;
}

inline HandInput handOf(const QString &spec)
{
    const std::optional<HandInput> h = HandInput::parse(spec);
    return h.value_or(HandInput{});
}

// Drives a device like a host would: frames in, decoded frames out.
class Host
{
public:
    explicit Host(const SimulatedDevice::Config &config) : device(config) {}

    void send(quint8 seq, const v2::Message &message)
    {
        device.receive(v2::encodeFrame(seq, message));
    }
    void sendRaw(const QByteArray &bytes) { device.receive(bytes); }

    //! Takes what the link carried so far; decodes it and keeps the raw bytes.
    QList<v2::Frame> take()
    {
        const QByteArray bytes = device.takeOutput();
        raw += bytes;
        QList<v2::Frame> frames;
        decoder.feed(bytes, frames);
        return frames;
    }
    //! The first frame of type T in what the link carried by now (advances a little if needed).
    template<typename T> std::optional<v2::Frame> reply()
    {
        for (int i = 0; i < 50; ++i) {
            for (const v2::Frame &f : take()) {
                if (std::holds_alternative<T>(f.message))
                    return f;
            }
            device.advance(1e-3);
        }
        return std::nullopt;
    }
    std::optional<v2::Ack> ack()
    {
        const std::optional<v2::Frame> f = reply<v2::Ack>();
        if (!f)
            return std::nullopt;
        return std::get<v2::Ack>(f->message);
    }
    DeviceParams params()
    {
        send(200, v2::GetParams{});
        const std::optional<v2::Frame> f = reply<v2::Params>();
        return f ? std::get<v2::Params>(f->message).params : DeviceParams{};
    }

    SimulatedDevice device;
    v2::FrameDecoder decoder{v2::Direction::FromDevice};
    QByteArray raw;
};

inline SimulatedDevice::Config fastConfig()
{
    SimulatedDevice::Config c;
    c.throttle = false; // replies are available at once
    return c;
}

inline QList<v2::Telemetry> telemetryOf(const QList<v2::Frame> &frames,
                                        QList<quint8> *seqs = nullptr)
{
    QList<v2::Telemetry> out;
    for (const v2::Frame &f : frames) {
        if (const auto *t = std::get_if<v2::Telemetry>(&f.message)) {
            out.append(*t);
            if (seqs)
                seqs->append(f.seq);
        }
    }
    return out;
}

} // namespace hatpic::test
