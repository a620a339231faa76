#include "v2driver.h"

#include "model/cyclequantities.h"
#include "session/commandqueue.h"
#include "session/linkstatistics.h"
#include "session/samplepipeline.h"
#include "session/streams.h"

#include <QLoggingCategory>

#include <cmath>
#include <type_traits>

Q_LOGGING_CATEGORY(lcV2, "hatpic.device.v2", QtWarningMsg)

namespace hatpic {

V2Driver::V2Driver(DriverLinks links, CommandQueue &queue, const v2::HelloReply &reply,
                   const ConnectOptions &options, qint32 baud, v2::FrameDecoder decoder)
    : m_links(std::move(links)), m_queue(queue), m_streamRateHz(options.streamRateHz),
      m_decoder(std::move(decoder))
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
    if (reply.protocolVersion != v2::kProtocolVersion) {
        qCWarning(lcV2) << "device reports protocol version" << reply.protocolVersion
                        << "; this host speaks" << v2::kProtocolVersion;
    }
    connect(&m_queue, &CommandQueue::acknowledged, this, &V2Driver::onAcknowledged);
    m_links.samples.builder().setTauLimit(m_info.tauLimit);
    m_links.statistics.restartSeq();
    // Discard the detection's noise (e.g. the tail of a stream we opened in the middle of).
    m_decoder.resetStats();
}

V2Driver::~V2Driver() = default;

void V2Driver::start()
{
    // The device's tuning: its parameters, and its effects and passivity block when it has them
    for (const Request &request :
         {Request(request::Read{}), Request(request::Stream{m_streamRateHz})})
        m_queue.enqueue(Command{request, wireSteps(request, m_info), {}});
}

void V2Driver::close()
{
    if (m_closed)
        return;
    m_closed = true;
    disconnect(&m_queue, nullptr, this, nullptr);
    m_links.statistics.absorb(m_decoder.stats());
    m_decoder.resetStats();
}

void V2Driver::feed(const QByteArray &bytes)
{
    QList<v2::Frame> frames;
    m_decoder.feed(bytes, frames);
    handleFrames(frames);
}

void V2Driver::handleFrames(const QList<v2::Frame> &frames)
{
    // Handlers may close the link (e.g. a write that fails); stop as soon as it is gone.
    for (const v2::Frame &frame : frames) {
        if (m_closed)
            break;
        handleFrame(frame);
    }
}

void V2Driver::handleFrame(const v2::Frame &frame)
{
    std::visit(
        [&](const auto &message) {
            using T = std::decay_t<decltype(message)>;
            if constexpr (std::is_same_v<T, v2::Telemetry>)
                handleTelemetry(frame.seq, message);
            else if constexpr (std::is_same_v<T, v2::Ack>)
                m_queue.onAck(message);
            else if constexpr (std::is_same_v<T, v2::Params>)
                handleTuning({message.params, std::nullopt, std::nullopt});
            else if constexpr (std::is_same_v<T, v2::Effects>)
                handleTuning({std::nullopt, message.effects, std::nullopt});
            else if constexpr (std::is_same_v<T, v2::Passivity>)
                handleTuning({std::nullopt, std::nullopt, message.passivity});
            else if constexpr (std::is_same_v<T, v2::Pong>)
                m_links.ping.onPong(message.token);
            else if constexpr (std::is_same_v<T, v2::Log>)
                m_links.deviceText(v2::toQString(message.text)); // the session escapes
            else if constexpr (std::is_same_v<T, v2::HelloReply>)
                qCInfo(lcV2) << "late HELLO_REPLY ignored";
        },
        frame.message);
}

void V2Driver::handleTelemetry(quint8 seq, const v2::Telemetry &received)
{
    // A quantity a capability brings (τ_fx, τ_pc, R) is read only from a device that announced
    // it: the bytes after the flags of any other device are not ours to interpret (effects.md
    // § 3, passivity.md).
    v2::Telemetry telemetry = received;
    forEachCycleQuantity<v2::Telemetry>([&](const CycleQuantity &q, auto member) {
        if constexpr (requires { (telemetry.*member).reset(); }) {
            if ((m_info.capabilities & q.capability) == 0)
                (telemetry.*member).reset();
        }
    });
    if (!m_links.statistics.countTelemetry(seq, telemetry.t_us))
        return;
    // A NaN or ±Inf would enter p_ref's integral and stay there for the rest of the session:
    // such a frame is counted and skipped, never integrated.
    bool finite = true;
    forEachCycleQuantity<v2::Telemetry>([&](const CycleQuantity &, auto member) {
        const auto &value = telemetry.*member;
        if constexpr (requires { value.value_or(0.0f); }) // a quantity not sent is no harm
            finite = finite && std::isfinite(value.value_or(0.0f));
        else if constexpr (std::is_floating_point_v<std::remove_cvref_t<decltype(value)>>)
            finite = finite && std::isfinite(value);
    });
    if (!finite) {
        m_links.statistics.countNonFinite();
        return;
    }
    if (m_pendingChange)
        applyPendingChange();
    m_links.samples.push(
        m_links.samples.builder().fromTelemetry(telemetry, m_links.clock.nsecsElapsed() / 1000));
}

void V2Driver::handleTuning(const DeviceTuning &told)
{
    if (m_pendingChange)
        applyPendingChange(); // streaming off: no telemetry carried the change
    m_links.samples.tuningReceived(told);
    m_queue.onTuning(told);
}

void V2Driver::onAcknowledged(const Command &command)
{
    const DeviceTuning *sent = command.pushed();
    switch (command.stepKind()) {
    case CommandKind::SetParams:
        m_pendingChange = PendingChange{CommandKind::SetParams, {sent->params, {}, {}}};
        return;
    case CommandKind::SetEffects:
        m_pendingChange = PendingChange{CommandKind::SetEffects, {{}, sent->effects, {}}};
        return;
    case CommandKind::SetPassivity:
        m_pendingChange = PendingChange{CommandKind::SetPassivity, {{}, {}, sent->passivity}};
        return;
    case CommandKind::Zero:
        m_pendingChange = PendingChange{CommandKind::Zero, {}};
        return;
    case CommandKind::SetStream:
        m_links.statistics.restartSeq(); // a new stream: no gap to count against the old
        return;
    default:
        return;
    }
}

void V2Driver::applyPendingChange()
{
    const PendingChange change = *m_pendingChange;
    m_pendingChange.reset();
    m_links.samples.tuningApplied(change.kind, change.applied);
}

void V2Driver::sendFeedback(double tauExt)
{
    m_links.write(v2::encodeFrame(m_feedbackSeq++, v2::SetFeedback{static_cast<float>(tauExt)}));
}

bool V2Driver::sendPing(quint32 token)
{
    // Not while a command waits for its answer: the device recognises a retry only when it
    // is the very last command it saw, and a PING in between would make it apply a retried
    // ZERO twice. The probe simply waits for the next tick.
    if (m_queue.busy())
        return false;
    m_links.write(v2::encodeFrame(m_queue.nextSeq(), v2::Ping{token}));
    return true;
}

} // namespace hatpic
