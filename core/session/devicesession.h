// The worker behind DeviceClient: owns the port and wires the session's parts together —
// protocol detection, the command queue, one protocol driver while connected, the feedback
// and PING streams, the link statistics and the sample pipeline (batches, recording). A plain
// QObject that lives on the session thread (DeviceClient moves it there); every method must
// be called on that thread. It works on any thread with an event loop, which is how the tests
// drive it directly.
#pragma once

#include "session/commandqueue.h"
#include "session/devicetext.h"
#include "session/linkstatistics.h"
#include "session/protocoldetector.h"
#include "session/protocoldriver.h"
#include "session/samplepipeline.h"
#include "session/sessiontypes.h"
#include "session/streams.h"
#include "telemetry/sample.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <memory>

namespace hatpic {

class ByteLink;

class DeviceSession : public QObject
{
    Q_OBJECT
public:
    static constexpr int kReconnectIntervalMs = 500; //!< reopen attempts after a loss [ms]
    static constexpr int kStatsIntervalMs = 250;     //!< statsUpdated() period [ms]
    static constexpr int kSilenceTimeoutMs =
        2000; //!< connected but no byte for this long → lost [ms]

    explicit DeviceSession(QObject *parent = nullptr);
    ~DeviceSession() override;

    void connectDevice(const ConnectOptions &options);
    void disconnectDevice();
    //! Disconnects and closes the recording; the session can be destroyed afterwards.
    void shutdown();

    //! Sends `request`'s wire steps (wireSteps()); `then` hears its outcome, once, on this
    //! thread. Before anything is sent: a step the device cannot carry is
    //! Unsupported; a push (each part; the effects against the device's tau_limit) or a
    //! vibration (against tau_limit: the device alone knows its control rate, so f < rate/2 is
    //! its check) that breaks a rule is Invalid; then without a device, NotConnected. A push is
    //! rounded to float32 here, once. A device without the passivity capability is sent no
    //! passivity block: dropped beside other parts, refused alone.
    void request(Request request, OutcomeHandler then = {});

    void setFeedback(double tauExt);             //!< knob 1's; the others' stay
    void setFeedback(const AxisTorques &tauExt); //!< every knob's
    void setHostParams(const HostParams &host);
    void resetReference();

    void startRecording(const QString &csvPath, const QString &source,
                        const RecordingPlan &plan = {});
    void stopRecording();

    SessionState state() const { return m_state; }
    //! The options of the current or last connection (connectDevice()).
    const ConnectOptions &options() const { return m_options; }
    DeviceInfo deviceInfo() const { return m_info; }
    LinkStats stats() const;
    //! Each sample as it is decoded, on this thread (samplelisteners.h); callable from any
    //! thread.
    SampleListeners &sampleListeners() { return m_samples.listeners(); }
    //! Where samples, the device's tuning and the recording's status come from (its signals:
    //! samplesReady, deviceTuningChanged, recordingChanged); on this thread.
    const SamplePipeline &samples() const { return m_samples; }

    // ---- test seams (session thread only) ----
    //! Stops (or resumes) the feedback stream, e.g. to see the device's watchdog act.
    void setFeedbackPaused(bool paused) { m_feedback.setPaused(paused); }
    //! Off: pushes and vibrations are sent without host-side validation, to exercise device
    //! rejections.
    void setValidateBeforeSending(bool validate) { m_validate = validate; }

Q_SIGNALS:
    void stateChanged(hatpic::SessionState state, const hatpic::StateDetail &detail);
    void deviceInfoChanged(const hatpic::DeviceInfo &info);
    void statsUpdated(const hatpic::LinkStats &stats);
    //! What the device says for people (v2 LOG, legacy boot text).
    void deviceLog(const QString &line);
    void notice(const hatpic::SessionNotice &notice);

private:
    // connection
    void openLink();
    void closeLink();
    void setState(SessionState state, const StateDetail &detail = {});
    StateDetail detail(StateDetail::Why why) const;
    void failDetection(const StateDetail &detail);
    void onFoundV2(const v2::HelloReply &reply, const QList<v2::Frame> &rest);
    void onFoundLegacy();
    void becomeConnected(std::unique_ptr<ProtocolDriver> driver);
    void linkLost(const QString &reason); //!< the link failed
    void loseLink(const StateDetail &lost);
    void tryReconnect();
    void onBytes(const QByteArray &bytes);
    void onStatsTick();
    void sendFeedback(const AxisTorques &tauExt); //!< through the driver, while connected
    bool sendPing(quint32 token);                 //!< through the driver; false when none went out

    // commands
    //! Why `request` (its wire steps `steps`) cannot be sent; nullopt when it can go.
    std::optional<Outcome::Result> refusal(const Request &request,
                                           const std::vector<CommandKind> &steps) const;
    void onCommandFinished(const Command &command, const Outcome &outcome);

    //! Acts on what the driver decoded, in the frames' order: counts, samples, the command
    //! queue's answers, PONGs, the device's text. Stops when a handler closed the link.
    void dispatch(const std::vector<Received> &events);
    //! A command step the device acknowledged: a change it applied (held until the next sample
    //! or read-back, which it belongs to), a new stream.
    void onAcknowledged(const Command &command);
    //! Hands the acknowledged change to the samples, before the sample or read-back at hand.
    void applyPendingChange();
    //! Where the drivers' frames go out.
    DriverWrite writer();
    void write(const QByteArray &bytes);

    ConnectOptions m_options;
    SessionState m_state = SessionState::Disconnected;
    StateDetail m_stateDetail;
    DeviceInfo m_info;
    bool m_wanted = false;        //!< the user asked to be connected
    bool m_everConnected = false; //!< since connectDevice(): losses reconnect
    bool m_validate = true;

    ByteLink *m_link = nullptr;
    QElapsedTimer m_clock;
    QTimer m_reconnectTimer;
    QTimer m_statsTimer;

    LinkStatistics m_statistics;
    CommandQueue m_queue;
    ProtocolDetector m_detector;
    std::unique_ptr<ProtocolDriver> m_driver;  //!< while connected
    std::unique_ptr<ProtocolDriver> m_retired; //!< the last one, closed (it may be on the stack)
    //! An acknowledged change (SET_PARAMS, SET_EFFECTS, SET_PASSIVITY with the part it sent;
    //! ZERO), applied with the next sample or read-back.
    std::optional<std::pair<CommandKind, DeviceTuning>> m_pendingChange;
    FeedbackStream m_feedback;
    PingProbe m_ping;
    DeviceTextGate m_deviceText; //!< the device's lines: printable, bounded in rate
    SamplePipeline m_samples;
};

} // namespace hatpic
