// The host's end of FixedHostPort in the device-core tests, as frames: one sent to the device,
// those it sent back decoded. Qt (the host's FrameDecoder), so not in devicecoretest.h, which
// the bench compiles too.
#pragma once

#include "devicecoretest.h"

#include "protocol/v2codec.h"

#include <QList>

#include <array>
#include <cstdint>
#include <span>

namespace devicecoretest {

//! Queues `message` as the host's frame `seq`.
inline void sendToDevice(FixedHostPort &host, std::uint8_t seq, const v2::Message &message)
{
    v2::FrameBuffer buffer;
    const std::size_t n = v2::encodeFrame(seq, message, buffer);
    host.toDevice.push(std::span(buffer).first(n));
}

//! Every frame the device sent since the last call, decoded by the host's `decoder`.
inline QList<v2::Frame> framesFromDevice(FixedHostPort &host, v2::FrameDecoder &decoder)
{
    std::array<std::uint8_t, 4096> bytes;
    QList<v2::Frame> frames;
    for (std::size_t n; (n = host.toHost.pop(bytes)) > 0;)
        decoder.feed(QByteArrayView(bytes.data(), qsizetype(n)), frames);
    return frames;
}

} // namespace devicecoretest
