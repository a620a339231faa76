// The v2 protocol (protocol.md) of a connected device: frames in, telemetry to samples, ACKs,
// PARAMS and EFFECTS to the command queue (and the device's tuning to the samples), SET_FEEDBACK
// and PING out.
#pragma once

#include "protocol/v2codec.h"
#include "session/protocoldriver.h"

#include <QList>
#include <QObject>

#include <limits>
#include <optional>

namespace hatpic {

class CommandQueue;
struct Command;

class V2Driver : public QObject, public ProtocolDriver
{
    Q_OBJECT
public:
    //! `reply` is the device's HELLO_REPLY (checked by the caller); `decoder` continues
    //! detection's (the start of the frame after the reply may be in it).
    V2Driver(DriverLinks links, CommandQueue &queue, const v2::HelloReply &reply,
             const ConnectOptions &options, qint32 baud, v2::FrameDecoder decoder);
    ~V2Driver() override;

    DeviceInfo info() const override { return m_info; }
    void start() override;
    void feed(const QByteArray &bytes) override;
    //! Frames decoded elsewhere (detection's chunk after HELLO_REPLY).
    void handleFrames(const QList<v2::Frame> &frames);
    void sendFeedback(double tauExt) override;
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
    void hostParamsChanged(const HostParams &) override {}
    void close() override;
    const v2::DecoderStats *v2Stats() const override { return &m_decoder.stats(); }
    StateDetail::Why connected() const override { return state::ConnectedV2{m_info.firmware}; }

private:
    //! An acknowledged change, applied with the next sample (or the read-back).
    struct PendingChange
    {
        CommandKind kind = CommandKind::SetParams; //!< SetParams, Zero, SetEffects or SetPassivity
        DeviceTuning applied;                      //!< the part it sent
    };

    void handleFrame(const v2::Frame &frame);
    void handleTelemetry(quint8 seq, const v2::Telemetry &telemetry);
    //! A PARAMS, EFFECTS or PASSIVITY: `told` has the part it carried.
    void handleTuning(const DeviceTuning &told);
    void onAcknowledged(const Command &command);
    void applyPendingChange();

    DriverLinks m_links;
    CommandQueue &m_queue;
    DeviceInfo m_info;
    quint16 m_streamRateHz; //!< asked for on start()
    v2::FrameDecoder m_decoder;
    quint8 m_feedbackSeq = 0;
    std::optional<PendingChange> m_pendingChange;
    bool m_closed = false;
};

} // namespace hatpic
