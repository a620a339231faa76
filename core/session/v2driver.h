// The v2 protocol (protocol.md) of a connected device, as a decoder: frames in, each one event
// (TELEMETRY with the quantities the device announced, ACK, PARAMS/EFFECTS/PASSIVITY, PONG,
// LOG); SET_FEEDBACK and PING out.
#pragma once

#include "protocol/v2codec.h"
#include "session/protocoldriver.h"

#include <QList>

#include <limits>
#include <optional>

namespace hatpic {

class CommandQueue;

class V2Driver : public ProtocolDriver
{
public:
    //! `reply` is the device's HELLO_REPLY (checked by the caller); `decoder` continues
    //! detection's (the start of the frame after the reply may be in it). `queue` numbers the
    //! PING frames (they share the commands' seq) and says when one may go.
    V2Driver(const v2::HelloReply &reply, const ConnectOptions &options, qint32 baud,
             v2::FrameDecoder decoder, CommandQueue &queue, DriverWrite write);

    DeviceInfo info() const override { return m_info; }
    std::vector<Request> startRequests() const override;
    void feed(const QByteArray &bytes, std::vector<Received> &out) override;
    //! Frames decoded elsewhere (detection's chunk after HELLO_REPLY).
    void decode(const QList<v2::Frame> &frames, std::vector<Received> &out) const;
    void sendFeedback(const AxisTorques &tauExt) override;
    //! The device's control rate (its highest telemetry rate): a faster frame is never used.
    //! A device that does not say leaves the cap to the session's options.
    double maxFeedbackHz() const override
    {
        return m_info.maxStreamHz > 0 ? double(m_info.maxStreamHz)
                                      : std::numeric_limits<double>::infinity();
    }
    bool sendPing(quint32 token) override;
    std::optional<outcome::Unsupported::Why> refusal(CommandKind step) const override
    {
        if (isEffectCommand(step) && !m_info.hasEffects())
            return outcome::Unsupported::Why::NoEffectsCapability;
        if (isPassivityCommand(step) && !m_info.hasPassivity())
            return outcome::Unsupported::Why::NoPassivityCapability;
        return std::nullopt;
    }
    double sampleTauLimit(const HostParams &) const override { return m_info.tauLimit; }
    const v2::DecoderStats *v2Stats() const override { return &m_decoder.stats(); }
    StateDetail::Why connected() const override { return state::ConnectedV2{m_info.firmware}; }

private:
    //! What `frame` said, or nothing (a late HELLO_REPLY).
    std::optional<Received> event(const v2::Frame &frame) const;

    DeviceInfo m_info;
    quint16 m_streamRateHz; //!< asked for on start
    v2::FrameDecoder m_decoder;
    CommandQueue &m_queue;
    DriverWrite m_write;
    quint8 m_feedbackSeq = 0;
};

} // namespace hatpic
