#include "v2driver.h"

#include "model/cyclequantities.h"
#include "session/commandqueue.h"

#include <QLoggingCategory>

#include <algorithm>
#include <cmath>
#include <type_traits>

Q_LOGGING_CATEGORY(lcV2, "hatpic.device.v2", QtWarningMsg)

namespace hatpic {

V2Driver::V2Driver(const v2::HelloReply &reply, const ConnectOptions &options, qint32 baud,
                   v2::FrameDecoder decoder, CommandQueue &queue, DriverWrite write)
    : m_streamRateHz(options.streamRateHz), m_decoder(std::move(decoder)), m_queue(queue),
      m_write(std::move(write))
{
    m_info.protocol = WireProtocol::V2;
    m_info.port = options.port;
    m_info.baud = baud;
    m_info.protocolVersion = reply.protocolVersion;
    m_info.maxStreamHz = reply.maxStreamHz;
    m_info.deviceId = reply.deviceId;
    m_info.tauLimit = reply.tauLimit;
    m_info.firmware = printableDeviceText(v2::toQString(reply.firmware));
    m_info.simulated = options.link && options.link->simulated();
    m_info.capabilities = reply.capabilities;
    // Several knobs only with the capability that carries them (docs/protocol.md § 2).
    if ((reply.capabilities & v2::kCapabilityAxes) != 0 && reply.axes)
        m_info.axes = quint8(std::clamp<int>(*reply.axes, 1, kMaxAxes));
    if (reply.protocolVersion != v2::kProtocolVersion) {
        qCWarning(lcV2) << "device reports protocol version" << reply.protocolVersion
                        << "; this host speaks" << v2::kProtocolVersion;
    }
    // Discard the detection's noise (e.g. the tail of a stream we opened in the middle of).
    m_decoder.resetStats();
}

std::vector<Request> V2Driver::startRequests() const
{
    // The device's tuning (its parameters, and its effects and passivity block when it has
    // them), then the stream.
    return {request::Read{}, request::Stream{m_streamRateHz}};
}

void V2Driver::feed(const QByteArray &bytes, std::vector<Received> &out)
{
    QList<v2::Frame> frames;
    m_decoder.feed(bytes, frames);
    decode(frames, out);
}

void V2Driver::decode(const QList<v2::Frame> &frames, std::vector<Received> &out) const
{
    for (const v2::Frame &frame : frames) {
        if (std::optional<Received> said = event(frame))
            out.push_back(std::move(*said));
    }
}

std::optional<Received> V2Driver::event(const v2::Frame &frame) const
{
    return std::visit(
        [&](const auto &message) -> std::optional<Received> {
            using T = std::decay_t<decltype(message)>;
            if constexpr (std::is_same_v<T, v2::Telemetry>) {
                // A quantity a capability brings (τ_fx, τ_pc, R) is read only from a device
                // that announced it: the bytes after the flags of any other device are not ours
                // to interpret (effects.md § 3, passivity.md).
                received::Telemetry said{frame.seq, message};
                forEachCycleQuantity<v2::Telemetry>([&](const CycleQuantity &q, auto member) {
                    auto &value = said.telemetry.*member;
                    if constexpr (requires { value.reset(); }) {
                        if ((m_info.capabilities & q.capability) == 0)
                            value.reset();
                        // One not sent (or not announced) is no harm.
                        said.finite = said.finite && std::isfinite(value.value_or(0.0f));
                    } else if constexpr (std::is_floating_point_v<
                                             std::remove_cvref_t<decltype(value)>>) {
                        said.finite = said.finite && std::isfinite(value);
                    }
                });
                // Knob blocks only of the knobs the device announced, each wholly finite.
                for (std::size_t k = 0; k < said.telemetry.more.size(); ++k) {
                    std::optional<v2::KnobTelemetry> &knob = said.telemetry.more[k];
                    if (int(k) + 1 >= m_info.axes) {
                        knob.reset();
                        continue;
                    }
                    if (!knob)
                        continue;
                    forEachKnobQuantity<v2::KnobTelemetry>([&](const CycleQuantity &, auto member) {
                        if constexpr (std::is_floating_point_v<
                                          std::remove_cvref_t<decltype((*knob).*member)>>)
                            said.finite = said.finite && std::isfinite((*knob).*member);
                    });
                }
                return said;
            } else if constexpr (std::is_same_v<T, v2::Ack>) {
                return message;
            } else if constexpr (std::is_same_v<T, v2::Params> || std::is_same_v<T, v2::Effects> ||
                                 std::is_same_v<T, v2::Passivity>) {
                // PARAMS, EFFECTS, PASSIVITY, of the knob they name; one the device did not
                // announce is nobody's.
                const int knob = v2::knobIndex(message.axis);
                if (knob >= m_info.axes)
                    return std::nullopt;
                received::Tuning tuning{{}, Knob(knob)};
                if constexpr (std::is_same_v<T, v2::Params>)
                    tuning.told.params = message.params;
                else if constexpr (std::is_same_v<T, v2::Effects>)
                    tuning.told.effects = message.effects;
                else
                    tuning.told.passivity = message.passivity;
                return tuning;
            } else if constexpr (std::is_same_v<T, v2::Pong>) {
                return received::Pong{message.token};
            } else if constexpr (std::is_same_v<T, v2::Log>) {
                return received::Text{v2::toQString(message.text)}; // the session escapes
            } else {
                if constexpr (std::is_same_v<T, v2::HelloReply>)
                    qCInfo(lcV2) << "late HELLO_REPLY ignored";
                return std::nullopt; // a host's message echoed: nothing the device said
            }
        },
        frame.message);
}

void V2Driver::sendFeedback(const AxisTorques &tauExt)
{
    // One frame for every knob: knob 1's τ_ext, then the further knobs' (kCapabilityAxes).
    v2::SetFeedback feedback{static_cast<float>(tauExt[0])};
    for (std::size_t k = 1; k < std::min<std::size_t>(m_info.axes, tauExt.size()); ++k)
        feedback.more[k - 1] = static_cast<float>(tauExt[k]);
    m_write(v2::encodeFrame(m_feedbackSeq++, feedback));
}

bool V2Driver::sendPing(quint32 token)
{
    // Not while a command waits for its answer: the device recognises a retry only when it
    // is the very last command it saw, and a PING in between would make it apply a retried
    // ZERO twice. The probe simply waits for the next tick.
    if (m_queue.busy())
        return false;
    m_write(v2::encodeFrame(m_queue.nextSeq(), v2::Ping{token}));
    return true;
}

} // namespace hatpic
