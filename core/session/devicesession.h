// The worker behind DeviceClient: owns the port, the protocol state machine, the reference
// model and the recorder. A plain QObject that lives on the session thread (DeviceClient
// moves it there); every method must be called on that thread. It works on any thread with
// an event loop, which is how the tests drive it directly.
#pragma once

#include "protocol/legacy.h"
#include "protocol/v2codec.h"
#include "session/rttstats.h"
#include "session/samplebuilder.h"
#include "session/sessiontypes.h"
#include "session/telemetrysequence.h"
#include "telemetry/recordingwriter.h"
#include "telemetry/sample.h"

#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <deque>
#include <optional>

namespace hatpic {

class ByteLink;
class SimLink;

class DeviceSession : public QObject
{
    Q_OBJECT
public:
    static constexpr int kListenMs = 500;            //!< detection: listen for legacy frames [ms]
    static constexpr int kHelloWaitMs = 500;         //!< detection: wait for HELLO_REPLY [ms]
    static constexpr int kHelloSends = 4;            //!< detection: HELLOs sent within the wait
    static constexpr int kLegacyFramesNeeded = 2;    //!< legacy frames that decide "legacy"
    static constexpr int kCommandTimeoutMs = 250;    //!< resend a command after this [ms]
    static constexpr int kCommandRetries = 3;        //!< resends before Timeout
    static constexpr int kMaxQueuedCommands = 16;    //!< commands waiting behind the one in flight
    static constexpr int kReconnectIntervalMs = 500; //!< reopen attempts after a loss [ms]
    static constexpr int kPingIntervalMs = 1000;     //!< PING period (v2) [ms]
    static constexpr int kMaxPendingPings = 16;      //!< unanswered PING tokens remembered
    static constexpr int kStatsIntervalMs = 250;     //!< statsUpdated() period [ms]
    static constexpr int kBatchIntervalMs = 20;      //!< samplesReady() at least this often [ms]
    static constexpr int kBatchMaxSamples = 64;      //!< …or when this many samples wait
    static constexpr int kSilenceTimeoutMs =
        2000; //!< connected but no byte for this long → lost [ms]

    explicit DeviceSession(QObject *parent = nullptr);
    ~DeviceSession() override;

    void connectDevice(const ConnectOptions &options);
    void disconnectDevice();
    //! Disconnects and closes the recording; the session can be destroyed afterwards.
    void shutdown();

    void pushParams(quint64 id, const DeviceParams &params);
    void readParams(quint64 id);
    void zero(quint64 id);
    void saveParams(quint64 id);
    void setStreamRate(quint64 id, quint16 hz);

    void setFeedback(double tauExt);
    void setHostParams(const HostParams &host);
    void resetReference();
    void setSimulatedHand(const HandInput &hand);

    void startRecording(const QString &csvPath, const QString &source);
    void stopRecording();

    SessionState state() const { return m_state; }
    DeviceInfo deviceInfo() const { return m_info; }
    LinkStats stats() const;

    // ---- test seams (session thread only) ----
    //! The in-process simulator's link while connected to "sim", else null.
    SimLink *simLink() const;
    //! Stops (or resumes) the feedback stream, e.g. to see the device's watchdog act.
    void setFeedbackPaused(bool paused);
    //! Off: pushParams() sends without host-side validation, to exercise device rejections.
    void setValidateBeforeSending(bool validate) { m_validate = validate; }

Q_SIGNALS:
    void stateChanged(hatpic::SessionState state, const QString &detail);
    void deviceInfoChanged(const hatpic::DeviceInfo &info);
    void deviceParamsChanged(const hatpic::DeviceParams &params);
    void samplesReady(const hatpic::SampleBatch &batch);
    void commandFinished(quint64 id, const hatpic::CommandResult &result);
    void statsUpdated(const hatpic::LinkStats &stats);
    void recordingChanged(const hatpic::RecordingStatus &status);
    void deviceLog(const QString &line);

private:
    enum class Phase { Idle, Listening, Hello, Connected };
    enum class CommandKind { Hello, GetParams, SetParams, SetStream, Zero, SaveParams };

    struct Command
    {
        quint64 id = 0; //!< 0 = the session's own (connect sequence), not reported
        CommandKind kind = CommandKind::GetParams;
        DeviceParams params;   //!< SET_PARAMS: what was sent (float32-rounded)
        quint16 rate = 0;      //!< SET_STREAM
        bool readBack = false; //!< the GET_PARAMS stage after SET_PARAMS / ZERO
        CommandKind origin = CommandKind::GetParams; //!< the command a read-back belongs to
        quint8 seq = 0;
        int retries = 0;
        QByteArray wire;
    };

    struct PendingEffect
    {
        CommandKind kind = CommandKind::SetParams; //!< SetParams or Zero
        DeviceParams params;
    };

    // connection
    void openLink();
    void closeLink();
    void setState(SessionState state, const QString &detail = {});
    void startDetection();
    void onListenTimeout();
    void onHelloTimeout();
    void sendDetectionHello();
    void failDetection(const QString &message);
    void becomeConnectedV2(const v2::HelloReply &reply);
    void becomeConnectedLegacy();
    void startConnectedTimers();
    void linkLost(const QString &reason);
    void tryReconnect();
    QString portDescription() const;
    qint32 requestedBaud() const;
    bool detectsAtTwoRates() const;

    // bytes in
    void onBytes(const QByteArray &bytes);
    void handleV2Frame(const v2::Frame &frame);
    void handleTelemetry(quint8 seq, const v2::Telemetry &telemetry);
    void handleLegacyFrame(const legacy::Frame &frame);
    void handleAck(const v2::Ack &ack);
    void handleParams(const DeviceParams &params);
    void handlePong(quint32 token);

    // commands
    void enqueue(Command command);
    void pump();
    void sendInflight();
    void onCommandTimeout();
    void finishInflight(const CommandResult &result);
    void failAllCommands(const QString &message);
    static QString commandName(CommandKind kind);
    quint8 nextSeq();

    // streams
    void sendFeedback();
    void sendPing();
    void onStatsTick();

    // samples, events, recording
    void pushSample(const Sample &sample);
    void flushBatch();
    void applyPendingEffect();
    void addEvent(const QString &text);
    void onRecordingFlushTick();
    void closeRecording(const QString &error = {});
    void emitRecordingStatus(const QString &error = {});

    qint64 hostUs() const { return m_clock.nsecsElapsed() / 1000; }

    ConnectOptions m_options;
    SessionState m_state = SessionState::Disconnected;
    QString m_stateDetail;
    Phase m_phase = Phase::Idle;
    WireProtocol m_protocol = WireProtocol::V2;
    DeviceInfo m_info;
    bool m_wanted = false;        //!< the user asked to be connected
    bool m_everConnected = false; //!< since connectDevice(): losses reconnect
    bool m_paramsKnown = false;   //!< a PARAMS arrived on this connection
    bool m_validate = true;
    bool m_feedbackPaused = false;

    ByteLink *m_link = nullptr;
    QElapsedTimer m_clock;
    QTimer m_detectTimer;
    QTimer m_commandTimer;
    QTimer m_reconnectTimer;
    QTimer m_feedbackTimer;
    QTimer m_pingTimer;
    QTimer m_statsTimer;
    QTimer m_batchTimer;
    QTimer m_recordingTimer;

    // detection
    legacy::Decoder m_detectLegacy;
    int m_detectLegacyFrames = 0;
    std::optional<quint8> m_helloSeq;
    int m_helloSends = 0;

    // decoding
    v2::FrameDecoder m_v2{v2::Direction::FromDevice};
    legacy::Decoder m_legacy;
    QList<v2::Frame> m_v2Frames;
    QList<legacy::Frame> m_legacyFrames;
    QStringList m_textLines;

    // commands
    std::optional<Command> m_inflight;
    std::deque<Command> m_queue;
    quint8 m_seq = 0;
    quint8 m_feedbackSeq = 0;
    std::optional<PendingEffect> m_pendingEffect;

    // streams
    double m_tauExt = 0;                                         //!< requested feedback [N·m]
    int m_legacyField = legacy::Conversion().feedbackToField(0); //!< last legacy A sent
    quint32 m_pingToken = 0;
    QHash<quint32, qint64> m_pings; //!< token → send time [ns]
    RttStats m_rtt;
    TelemetrySequence m_telemetrySeq;
    qint64 m_lastRxNs = 0;

    // statistics
    LinkStats m_stats; //!< counters; decoder drops of closed links are in m_dropBase
    std::array<quint64, v2::kDropReasonCount> m_dropBase{};
    quint64 m_legacyMalformedBase = 0;
    struct RateMark
    {
        qint64 ns;
        quint64 frames;
        quint64 bytes;
    };
    std::deque<RateMark> m_rateMarks;

    // samples
    SampleBuilder m_builder;
    SampleBatch m_batch;
    RecordingWriter m_recorder;
    QString m_recordingError;
};

} // namespace hatpic
