// The published firmware's text protocol (legacy): frames in at its fixed ~5 Hz, θ from
// ticks and τ_rec estimated by the host; feedback as whole 'i…o' frames; no commands, no PING.
#pragma once

#include "protocol/legacy.h"
#include "session/protocoldriver.h"

#include <QList>
#include <QStringList>

namespace hatpic {

class LegacyDriver : public ProtocolDriver
{
public:
    //! @param feedbackOn whether feedback is streamed at all (else τ_ext is 0 in samples)
    LegacyDriver(const ConnectOptions &options, qint32 baud, DriverWrite write);

    DeviceInfo info() const override { return m_info; }
    std::vector<Request> startRequests() const override { return {}; } // it takes none
    void feed(const QByteArray &bytes, std::vector<Received> &out) override;
    //! The published firmware busy-waits for a whole frame: the host keeps to the rate it
    //! has always used with it [Hz].
    static constexpr double kMaxFeedbackHz = 100;

    void sendFeedback(const AxisTorques &tauExt) override;
    //! The device is the IMU branch's board (four knobs, a tilt): detection heard it, or its
    //! first frame with the tilt says so.
    void noteImuBranch();
    double maxFeedbackHz() const override { return kMaxFeedbackHz; }
    bool sendPing(quint32) override { return false; }
    std::optional<outcome::Unsupported::Why> refusal(CommandKind step) const override;
    //! The published firmware renders its own fixed spring and does not say its limit: the
    //! host's copy of the parameters (the defaults) and its tau_limit estimate τ_rec.
    double sampleTauLimit(const HostParams &host) const override { return host.tau_limit; }
    const legacy::DecoderStats *legacyStats() const override { return &m_decoder.stats(); }
    StateDetail::Why connected() const override { return state::ConnectedLegacy{}; }

private:
    DriverWrite m_write;
    legacy::Conversion m_conversion;
    bool m_feedbackOn;
    DeviceInfo m_info;
    legacy::Decoder m_decoder;
    std::array<int, kMaxAxes> m_fields; //!< the last feedback fields A … D sent
};

} // namespace hatpic
