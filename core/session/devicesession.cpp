#include "devicesession.h"

#include "link/seriallink.h"
#include "sim/simlink.h"
#include "telemetry/numbertext.h"

#include <QDateTime>
#include <QLoggingCategory>

#include <algorithm>
#include <cmath>

Q_LOGGING_CATEGORY(lcSession, "hatpic.device.session", QtWarningMsg)

namespace hatpic {

namespace {

constexpr qint32 kDefaultV2Baud = defaultBaud(WireProtocol::V2);
constexpr qint32 kDefaultLegacyBaud = defaultBaud(WireProtocol::Legacy);

QString fieldName(int index)
{
    return QString::fromLatin1(deviceFieldName(index));
}

QString describeHostChange(const HostParams &from, const HostParams &to)
{
    QStringList parts;
    auto onOff = [](bool on) { return on ? QStringLiteral("on") : QStringLiteral("off"); };
    if (from.v_max != to.v_max)
        parts << u"v_max " % compactNumberText(from.v_max) % u" → " % compactNumberText(to.v_max);
    if (from.mode != to.mode) {
        parts << u"mode " % QString::fromLatin1(referenceModeName(from.mode)) % u" → " %
                     QString::fromLatin1(referenceModeName(to.mode));
    }
    if (from.ref_deadzone != to.ref_deadzone)
        parts << u"ref_deadzone " % onOff(from.ref_deadzone) % u" → " % onOff(to.ref_deadzone);
    if (from.tau_limit != to.tau_limit) {
        parts << u"tau_limit " % compactNumberText(from.tau_limit) % u" → " %
                     compactNumberText(to.tau_limit);
    }
    return parts.join(QStringLiteral("; "));
}

//! First HELLO seq at or after `from` whose frame has no 0x69 ('i') byte (protocol.md § 4).
quint8 safeHelloSeq(quint8 from)
{
    for (int k = 0; k < 256; ++k) {
        const auto seq = static_cast<quint8>(from + k);
        if (!v2::encodeFrame(seq, v2::Hello{}).contains('i'))
            return seq;
    }
    return 0; // seq 0 encodes as 02 01 03 3e 2e 00
}

CommandResult result(CommandResult::Status status, const QString &message)
{
    CommandResult r;
    r.status = status;
    r.message = message;
    return r;
}

} // namespace

DeviceSession::DeviceSession(QObject *parent)
    : QObject(parent), m_detectTimer(this), m_commandTimer(this), m_reconnectTimer(this),
      m_feedbackTimer(this), m_pingTimer(this), m_statsTimer(this), m_batchTimer(this),
      m_recordingTimer(this)
{
    registerSessionMetaTypes();
    m_clock.start();

    m_detectTimer.setSingleShot(true);
    m_commandTimer.setSingleShot(true);
    m_commandTimer.setInterval(kCommandTimeoutMs);
    m_reconnectTimer.setSingleShot(true);
    m_reconnectTimer.setInterval(kReconnectIntervalMs);
    m_feedbackTimer.setTimerType(Qt::PreciseTimer);
    m_pingTimer.setInterval(kPingIntervalMs);
    m_statsTimer.setInterval(kStatsIntervalMs);
    m_batchTimer.setTimerType(Qt::PreciseTimer);
    m_batchTimer.setInterval(kBatchIntervalMs);
    m_recordingTimer.setInterval(RecordingWriter::kFlushIntervalMs);

    connect(&m_detectTimer, &QTimer::timeout, this, [this] {
        if (m_phase == Phase::Listening)
            onListenTimeout();
        else if (m_phase == Phase::Hello)
            onHelloTimeout();
    });
    connect(&m_commandTimer, &QTimer::timeout, this, &DeviceSession::onCommandTimeout);
    connect(&m_reconnectTimer, &QTimer::timeout, this, &DeviceSession::tryReconnect);
    connect(&m_feedbackTimer, &QTimer::timeout, this, &DeviceSession::sendFeedback);
    connect(&m_pingTimer, &QTimer::timeout, this, &DeviceSession::sendPing);
    connect(&m_statsTimer, &QTimer::timeout, this, &DeviceSession::onStatsTick);
    connect(&m_batchTimer, &QTimer::timeout, this, &DeviceSession::flushBatch);
    connect(&m_recordingTimer, &QTimer::timeout, this, &DeviceSession::onRecordingFlushTick);
}

DeviceSession::~DeviceSession()
{
    // Nobody listens any more: close quietly.
    blockSignals(true);
    shutdown();
}

// ---------------------------------------------------------------- connection

void DeviceSession::connectDevice(const ConnectOptions &options)
{
    if (m_wanted || m_link)
        disconnectDevice();
    m_options = options;
    m_wanted = true;
    m_everConnected = false;
    m_stats = {};
    m_dropBase = {};
    m_legacyMalformedBase = 0;
    m_rateMarks.clear();
    m_rtt.clear();
    m_builder.clear();
    m_statsTimer.start();
    openLink();
}

void DeviceSession::disconnectDevice()
{
    const bool wasActive = m_wanted || m_link || m_state != SessionState::Disconnected;
    m_wanted = false;
    m_reconnectTimer.stop();
    flushBatch();
    closeRecording();
    failAllCommands(QStringLiteral("The session was disconnected before the device answered."));
    closeLink();
    m_statsTimer.stop();
    if (wasActive) {
        Q_EMIT statsUpdated(stats());
        setState(SessionState::Disconnected);
    }
}

void DeviceSession::shutdown()
{
    disconnectDevice();
    m_recordingTimer.stop();
    m_batchTimer.stop();
}

QString DeviceSession::portDescription() const
{
    if (m_options.port == QStringView(kSimPortName))
        return QStringLiteral("the simulated joystick"); // no serial line, so no baud rate
    const qint32 baud = m_link ? m_link->baud() : requestedBaud();
    return m_options.port % u" at " % QString::number(baud) % u" baud";
}

qint32 DeviceSession::requestedBaud() const
{
    if (m_options.baud > 0)
        return m_options.baud;
    // Auto with no baud given listens at the published firmware's rate first, then asks for
    // HELLO at v2's rate (see onListenTimeout), so both kinds of device are found unaided.
    return m_options.protocol == ProtocolChoice::V2 ? kDefaultV2Baud : kDefaultLegacyBaud;
}

bool DeviceSession::detectsAtTwoRates() const
{
    return m_options.protocol == ProtocolChoice::Auto && m_options.baud <= 0;
}

void DeviceSession::openLink()
{
    closeLink();
    if (m_options.port == QStringView(kSimPortName))
        m_link = new SimLink(m_options.sim, this);
    else
        m_link = new SerialLink(m_options.port, requestedBaud(), this);
    connect(m_link, &ByteLink::bytesReceived, this, &DeviceSession::onBytes);
    connect(m_link, &ByteLink::failed, this, &DeviceSession::linkLost);

    if (!m_everConnected)
        setState(SessionState::Opening, u"Opening " % portDescription());
    if (!m_link->open()) {
        const QString error = u"Cannot open " % portDescription() % u": " % m_link->errorString();
        closeLink();
        if (m_everConnected) {
            // Still lost: the port has not come back yet.
            m_reconnectTimer.start();
            return;
        }
        m_wanted = false;
        m_statsTimer.stop();
        setState(SessionState::Disconnected, error);
        return;
    }
    m_lastRxNs = m_clock.nsecsElapsed();
    startDetection();
}

void DeviceSession::closeLink()
{
    m_detectTimer.stop();
    m_commandTimer.stop();
    m_feedbackTimer.stop();
    m_pingTimer.stop();
    m_phase = Phase::Idle;
    m_helloSeq.reset();
    m_pings.clear();
    m_pendingEffect.reset();
    if (m_link) {
        m_link->disconnect(this);
        m_link->close();
        // Deferred: this may run inside one of the link's own signals.
        m_link->deleteLater();
        m_link = nullptr;
    }
    // Keep the drop counts of this link; the decoders start over on the next one.
    const auto &dropped = m_v2.stats().drops;
    for (int i = 0; i < v2::kDropReasonCount; ++i)
        m_dropBase[i] += dropped[i];
    m_legacyMalformedBase += m_legacy.stats().malformed;
    m_v2.clear();
    m_v2.resetStats();
    m_legacy = legacy::Decoder();
}

void DeviceSession::setState(SessionState state, const QString &detail)
{
    if (state == m_state && detail == m_stateDetail)
        return;
    m_state = state;
    m_stateDetail = detail;
    qCInfo(lcSession) << sessionStateName(state) << detail;
    Q_EMIT stateChanged(state, detail);
}

void DeviceSession::startDetection()
{
    m_detectLegacy = legacy::Decoder();
    m_detectLegacyFrames = 0;
    m_helloSeq.reset();
    switch (m_options.protocol) {
    case ProtocolChoice::Legacy:
        setState(SessionState::Detecting, u"Using the legacy protocol on " % portDescription());
        becomeConnectedLegacy();
        return;
    case ProtocolChoice::V2: {
        setState(SessionState::Detecting, u"Asking for HELLO on " % portDescription());
        m_phase = Phase::Hello;
        Command hello;
        hello.kind = CommandKind::Hello;
        enqueue(hello);
        return;
    }
    case ProtocolChoice::Auto:
        break;
    }
    setState(SessionState::Detecting, u"Listening for a legacy device on " % portDescription());
    m_phase = Phase::Listening;
    m_detectTimer.start(kListenMs);
}

void DeviceSession::onListenTimeout()
{
    if (m_detectLegacyFrames >= kLegacyFramesNeeded) {
        becomeConnectedLegacy();
        return;
    }
    // Step 2: HELLO with a seq whose frame holds no 'i', so a legacy device is never upset.
    if (detectsAtTwoRates() && !m_link->setBaud(kDefaultV2Baud)) {
        failDetection(u"Cannot switch " % m_options.port % u" to " %
                      QString::number(kDefaultV2Baud) % u" baud: " % m_link->errorString());
        return;
    }
    setState(SessionState::Detecting, u"Sending HELLO on " % portDescription());
    m_phase = Phase::Hello;
    m_helloSeq = safeHelloSeq(m_seq);
    m_seq = static_cast<quint8>(*m_helloSeq + 1);
    m_v2.clear();
    m_helloSends = 0;
    sendDetectionHello();
}

void DeviceSession::sendDetectionHello()
{
    // Led by a delimiter: a stray byte already on the line (noise, a terminal's echo) ends
    // as a frame of its own that the device drops, instead of corrupting the HELLO. Sent
    // kHelloSends times within the wait, the same bytes each time, in case one is lost.
    ++m_helloSends;
    m_link->write(QByteArray(1, '\0') + v2::encodeFrame(*m_helloSeq, v2::Hello{}));
    m_detectTimer.start(kHelloWaitMs / kHelloSends);
}

void DeviceSession::onHelloTimeout()
{
    if (m_link && m_helloSeq && m_helloSends < kHelloSends) {
        sendDetectionHello();
        return;
    }
    const QString listenBaud =
        detectsAtTwoRates() ? u" at " % QString::number(kDefaultLegacyBaud) % u" baud" : QString();
    failDetection(u"No HATPIC answered on " % portDescription() % u": listened " %
                  QString::number(kListenMs) % u" ms" % listenBaud % u" for legacy frames (got " %
                  QString::number(m_detectLegacyFrames) % u" valid, " %
                  QString::number(kLegacyFramesNeeded) % u" needed), then sent HELLO and got no " %
                  u"HELLO_REPLY within " % QString::number(kHelloWaitMs) % u" ms.");
}

void DeviceSession::failDetection(const QString &message)
{
    qCWarning(lcSession) << message;
    failAllCommands(message);
    closeLink();
    if (m_everConnected && m_wanted && m_options.autoReconnect) {
        // A port that came back without its device yet: keep trying.
        setState(SessionState::Lost, message);
        m_reconnectTimer.start();
        return;
    }
    m_wanted = false;
    m_statsTimer.stop();
    setState(SessionState::Disconnected, message);
}

void DeviceSession::becomeConnectedV2(const v2::HelloReply &reply)
{
    m_detectTimer.stop();
    if (const QString problem = helloReplyProblem(reply); !problem.isEmpty()) {
        failDetection(u"Refused the device on " % portDescription() % u": " % problem %
                      u". It does not behave as a HATPIC joystick; nothing was sent to it.");
        return;
    }
    m_phase = Phase::Connected;
    m_protocol = WireProtocol::V2;
    m_info = DeviceInfo();
    m_info.protocol = WireProtocol::V2;
    m_info.port = m_options.port;
    m_info.baud = m_link->baud();
    m_info.protocolVersion = reply.protocolVersion;
    m_info.maxStreamHz = reply.maxStreamHz;
    m_info.deviceId = reply.deviceId;
    m_info.tauLimit = reply.tauLimit;
    m_info.firmware = printableDeviceText(v2::toQString(reply.firmware));
    m_info.simulated = m_options.port == QStringView(kSimPortName);
    if (reply.protocolVersion != v2::kProtocolVersion) {
        qCWarning(lcSession) << "device reports protocol version" << reply.protocolVersion
                             << "; this host speaks" << v2::kProtocolVersion;
    }
    m_builder.setTauLimit(m_info.tauLimit);
    m_paramsKnown = false;
    m_telemetrySeq.reset();
    // Discard the detection's noise (e.g. the tail of a stream we opened in the middle of).
    m_v2.resetStats();
    m_everConnected = true;
    Q_EMIT deviceInfoChanged(m_info);
    setState(SessionState::Connected,
             u"HATPIC v2 \"" % m_info.firmware % u"\" on " % portDescription());

    Command get;
    get.kind = CommandKind::GetParams;
    enqueue(get);
    Command stream;
    stream.kind = CommandKind::SetStream;
    stream.rate = m_options.streamRateHz;
    enqueue(stream);
    if (!m_link)
        return; // lost while writing the first command
    startConnectedTimers();
    m_pingTimer.start();
    sendPing();
}

void DeviceSession::becomeConnectedLegacy()
{
    m_detectTimer.stop();
    m_phase = Phase::Connected;
    m_protocol = WireProtocol::Legacy;
    m_info = DeviceInfo();
    m_info.protocol = WireProtocol::Legacy;
    m_info.port = m_options.port;
    m_info.baud = m_link->baud();
    m_info.protocolVersion = 0;
    m_info.maxStreamHz = 5;
    m_info.deviceId = 0;
    m_info.tauLimit = m_options.legacy.tauLimit;
    m_info.firmware = QStringLiteral("published firmware (legacy)");
    m_info.simulated = m_options.port == QStringView(kSimPortName);
    // The published firmware renders its own fixed spring; the host estimates τ_rec from its
    // copy of the parameters, which stays at the defaults (θ0 = 0).
    m_builder.setTauLimit(m_builder.hostParams().tau_limit);
    m_paramsKnown = false;
    m_legacyField = m_options.legacy.feedbackToField(0);
    m_legacy = legacy::Decoder();
    m_everConnected = true;
    Q_EMIT deviceInfoChanged(m_info);
    setState(SessionState::Connected, u"Legacy HATPIC on " % portDescription());
    startConnectedTimers();
}

void DeviceSession::startConnectedTimers()
{
    m_builder.markDiscontinuity();
    m_lastRxNs = m_clock.nsecsElapsed();
    if (m_options.feedbackRateHz > 0) {
        m_feedbackTimer.setInterval(
            std::max(1, static_cast<int>(std::lround(1000.0 / m_options.feedbackRateHz))));
        m_feedbackTimer.start();
        sendFeedback();
    }
    m_batchTimer.start();
}

void DeviceSession::linkLost(const QString &reason)
{
    if (!m_link)
        return;
    const QString detail = u"Lost " % portDescription() % u": " % reason;
    qCWarning(lcSession) << detail;
    flushBatch();
    if (m_recorder.isOpen()) {
        closeRecording();
        Q_EMIT deviceLog(QStringLiteral("Recording closed: the device was lost."));
    }
    failAllCommands(QStringLiteral("The connection was lost before the device answered."));
    closeLink();
    m_builder.markDiscontinuity();
    Q_EMIT statsUpdated(stats()); // the final figures, before anyone reads them as such
    setState(SessionState::Lost, detail);
    if (m_wanted && m_options.autoReconnect)
        m_reconnectTimer.start();
}

void DeviceSession::tryReconnect()
{
    if (!m_wanted || m_link)
        return;
    openLink();
}

// ---------------------------------------------------------------- bytes in

void DeviceSession::onBytes(const QByteArray &bytes)
{
    m_lastRxNs = m_clock.nsecsElapsed();
    m_stats.bytes += static_cast<quint64>(bytes.size());

    switch (m_phase) {
    case Phase::Idle:
        return;
    case Phase::Listening: {
        m_legacyFrames.clear();
        m_detectLegacy.feed(bytes, m_legacyFrames, nullptr);
        m_detectLegacyFrames += static_cast<int>(m_legacyFrames.size());
        // The decision cannot change once two frames are in, so it need not wait 500 ms.
        if (m_detectLegacyFrames >= kLegacyFramesNeeded)
            becomeConnectedLegacy();
        return;
    }
    case Phase::Hello:
    case Phase::Connected:
        break;
    }

    if (m_phase == Phase::Connected && m_protocol == WireProtocol::Legacy) {
        m_legacyFrames.clear();
        m_textLines.clear();
        m_legacy.feed(bytes, m_legacyFrames, &m_textLines);
        for (const QString &line : std::as_const(m_textLines)) {
            if (!line.isEmpty())
                Q_EMIT deviceLog(line);
        }
        for (const legacy::Frame &frame : std::as_const(m_legacyFrames))
            handleLegacyFrame(frame);
        return;
    }

    m_v2Frames.clear();
    m_v2.feed(bytes, m_v2Frames);
    // Handlers may close the link (e.g. a failed detection); stop as soon as it is gone.
    for (const v2::Frame &frame : std::as_const(m_v2Frames)) {
        if (m_phase == Phase::Idle)
            break;
        handleV2Frame(frame);
    }
}

void DeviceSession::handleV2Frame(const v2::Frame &frame)
{
    if (m_phase == Phase::Hello) {
        if (const auto *reply = std::get_if<v2::HelloReply>(&frame.message)) {
            if (m_inflight && m_inflight->kind == CommandKind::Hello) {
                m_commandTimer.stop();
                m_inflight.reset();
            }
            becomeConnectedV2(*reply);
        }
        return;
    }
    std::visit(
        [&](const auto &message) {
            using T = std::decay_t<decltype(message)>;
            if constexpr (std::is_same_v<T, v2::Telemetry>)
                handleTelemetry(frame.seq, message);
            else if constexpr (std::is_same_v<T, v2::Ack>)
                handleAck(message);
            else if constexpr (std::is_same_v<T, v2::Params>)
                handleParams(message.params);
            else if constexpr (std::is_same_v<T, v2::Pong>)
                handlePong(message.token);
            else if constexpr (std::is_same_v<T, v2::Log>)
                Q_EMIT deviceLog(printableDeviceText(v2::toQString(message.text)));
            else if constexpr (std::is_same_v<T, v2::HelloReply>)
                qCInfo(lcSession) << "late HELLO_REPLY ignored";
        },
        frame.message);
}

void DeviceSession::handleTelemetry(quint8 seq, const v2::Telemetry &telemetry)
{
    ++m_stats.frames;
    const TelemetrySequence::Step step = m_telemetrySeq.accept(seq, telemetry.t_us);
    if (step.duplicate) { // the same frame again (a link that repeats): one sample only
        ++m_stats.duplicates;
        return;
    }
    m_stats.seqDrops += step.missing;
    // A NaN or ±Inf would enter p_ref's integral and stay there for the rest of the session:
    // such a frame is counted and skipped, never integrated.
    if (!std::isfinite(telemetry.theta) || !std::isfinite(telemetry.omega) ||
        !std::isfinite(telemetry.tau) || !std::isfinite(telemetry.tau_rec) ||
        !std::isfinite(telemetry.tau_ext)) {
        ++m_stats.nonFinite;
        return;
    }
    if (m_pendingEffect)
        applyPendingEffect();
    pushSample(m_builder.fromTelemetry(telemetry, hostUs()));
}

void DeviceSession::handleLegacyFrame(const legacy::Frame &frame)
{
    ++m_stats.frames;
    const double tauExt =
        m_options.feedbackRateHz > 0 ? m_options.legacy.fieldToFeedback(m_legacyField) : 0.0;
    pushSample(m_builder.fromLegacy(frame, m_options.legacy, tauExt, hostUs()));
}

void DeviceSession::handleAck(const v2::Ack &ack)
{
    if (!m_inflight || m_inflight->wire.isEmpty() || ack.ackedSeq != m_inflight->seq)
        return; // a late answer to a retry, or to nothing of ours
    switch (m_inflight->kind) {
    case CommandKind::Hello:
    case CommandKind::GetParams:
        // HELLO and GET_PARAMS are answered by their reply, not an ACK; an ACK here is a
        // refusal (UNKNOWN_TYPE, BAD_LENGTH, …).
        if (ack.status == v2::AckStatus::Ok)
            return;
        break;
    default:
        break;
    }
    m_commandTimer.stop();

    if (ack.status != v2::AckStatus::Ok) {
        CommandResult r;
        r.status = CommandResult::Status::Rejected;
        r.ackStatus = ack.status;
        const QString status = v2::ackStatusName(ack.status);
        if (ack.field != v2::kNoField && ack.field < DeviceParams::kFieldCount) {
            r.field = ack.field;
            r.message = u"The device rejected " % fieldName(ack.field) % u" (field " %
                        QString::number(ack.field) % u"): " % status %
                        u"; its parameters are unchanged.";
        } else {
            r.message =
                u"The device rejected " % commandName(m_inflight->kind) % u": " % status % u'.';
        }
        finishInflight(r);
        return;
    }

    Command &cmd = *m_inflight;
    switch (cmd.kind) {
    case CommandKind::SetParams:
    case CommandKind::Zero: {
        PendingEffect effect;
        effect.kind = cmd.kind;
        effect.params = cmd.params;
        m_pendingEffect = effect;
        // Read back what the device now holds, under the same request id.
        cmd.origin = cmd.kind;
        cmd.kind = CommandKind::GetParams;
        cmd.readBack = true;
        cmd.retries = 0;
        sendInflight();
        return;
    }
    case CommandKind::SetStream:
        m_options.streamRateHz = cmd.rate;
        m_telemetrySeq.reset();
        finishInflight(result(CommandResult::Status::Ok,
                              cmd.rate ? u"Telemetry requested at " % QString::number(cmd.rate) %
                                             u" Hz (the device may clamp it)."
                                       : QStringLiteral("Telemetry stopped.")));
        return;
    case CommandKind::SaveParams:
        finishInflight(
            result(CommandResult::Status::Ok, QStringLiteral("The device saved its parameters.")));
        return;
    case CommandKind::Hello:
    case CommandKind::GetParams:
        return;
    }
}

void DeviceSession::handleParams(const DeviceParams &params)
{
    if (m_pendingEffect)
        applyPendingEffect(); // streaming off: no telemetry carried the change
    const DeviceParams held = m_builder.deviceParams();
    if (m_paramsKnown && !sameOnWire(held, params)) {
        flushBatch();
        addEvent(describeParamChange(held, params) % u" (read back)");
    }
    m_builder.setDeviceParams(params);
    m_paramsKnown = true;
    Q_EMIT deviceParamsChanged(params);

    if (!m_inflight || m_inflight->kind != CommandKind::GetParams)
        return;
    m_commandTimer.stop();
    CommandResult r;
    if (!m_inflight->readBack) {
        r.message = QStringLiteral("Parameters read from the device.");
    } else if (m_inflight->origin == CommandKind::Zero) {
        r.readBack = true;
        r.readBackMatches = true;
        r.message =
            u"The device zeroed: theta0 is now " % compactNumberText(params.theta0) % u" rad.";
    } else {
        r.readBack = true;
        r.readBackMatches = sameOnWire(m_inflight->params, params);
        if (r.readBackMatches) {
            r.message = QStringLiteral("The device applied the parameters; the read-back matches.");
        } else {
            r.message = u"The device acknowledged the parameters, but the read-back differs: " %
                        describeParamChange(m_inflight->params, params) % u" (sent → read).";
        }
    }
    finishInflight(r);
}

void DeviceSession::handlePong(quint32 token)
{
    const auto it = m_pings.find(token);
    if (it == m_pings.end())
        return;
    m_rtt.add(static_cast<double>(m_clock.nsecsElapsed() - it.value()) * 1e-6);
    m_pings.erase(it);
}

// ---------------------------------------------------------------- commands

QString DeviceSession::commandName(CommandKind kind)
{
    switch (kind) {
    case CommandKind::Hello:
        return QStringLiteral("HELLO");
    case CommandKind::GetParams:
        return QStringLiteral("GET_PARAMS");
    case CommandKind::SetParams:
        return QStringLiteral("SET_PARAMS");
    case CommandKind::SetStream:
        return QStringLiteral("SET_STREAM");
    case CommandKind::Zero:
        return QStringLiteral("ZERO");
    case CommandKind::SaveParams:
        return QStringLiteral("SAVE_PARAMS");
    }
    return {};
}

quint8 DeviceSession::nextSeq()
{
    return m_seq++;
}

void DeviceSession::pushParams(quint64 id, const DeviceParams &params)
{
    if (m_validate) {
        const auto violations = validate(params);
        if (!violations.empty()) {
            QStringList messages;
            for (const Violation &v : violations)
                messages << QString::fromStdString(v.message());
            Q_EMIT commandFinished(id, result(CommandResult::Status::Invalid,
                                              u"The parameters are not valid: " %
                                                  messages.join(QStringLiteral("; ")) % u'.'));
            return;
        }
    }
    Command cmd;
    cmd.id = id;
    cmd.kind = CommandKind::SetParams;
    cmd.params = roundedForWire(params);
    enqueue(cmd);
}

void DeviceSession::readParams(quint64 id)
{
    Command cmd;
    cmd.id = id;
    cmd.kind = CommandKind::GetParams;
    enqueue(cmd);
}

void DeviceSession::zero(quint64 id)
{
    Command cmd;
    cmd.id = id;
    cmd.kind = CommandKind::Zero;
    enqueue(cmd);
}

void DeviceSession::saveParams(quint64 id)
{
    Command cmd;
    cmd.id = id;
    cmd.kind = CommandKind::SaveParams;
    enqueue(cmd);
}

void DeviceSession::setStreamRate(quint64 id, quint16 hz)
{
    Command cmd;
    cmd.id = id;
    cmd.kind = CommandKind::SetStream;
    cmd.rate = hz;
    enqueue(cmd);
}

void DeviceSession::enqueue(Command command)
{
    const bool detectingHello = command.kind == CommandKind::Hello && m_phase == Phase::Hello;
    if (m_phase != Phase::Connected && !detectingHello) {
        if (command.id) {
            Q_EMIT commandFinished(command.id,
                                   result(CommandResult::Status::NotConnected,
                                          QStringLiteral("Not connected to a device.")));
        }
        return;
    }
    if (m_phase == Phase::Connected && m_protocol == WireProtocol::Legacy) {
        QString why;
        switch (command.kind) {
        case CommandKind::SetParams:
        case CommandKind::GetParams:
        case CommandKind::Zero:
        case CommandKind::SaveParams:
            why = commandName(command.kind) %
                  u" is not available: the device runs the published firmware (legacy protocol), "
                  u"which cannot send or take parameters. Host settings still apply.";
            break;
        default:
            why = commandName(command.kind) %
                  u" is not available: the device runs the published firmware (legacy protocol), "
                  u"which streams at its own fixed rate of about 5 Hz.";
            break;
        }
        if (command.id)
            Q_EMIT commandFinished(command.id, result(CommandResult::Status::Unsupported, why));
        return;
    }
    if (static_cast<int>(m_queue.size()) >= kMaxQueuedCommands) {
        if (command.id) {
            Q_EMIT commandFinished(command.id,
                                   result(CommandResult::Status::Invalid,
                                          u"Too many commands are waiting (" %
                                              QString::number(kMaxQueuedCommands) % u"); " %
                                              commandName(command.kind) % u" was not sent."));
        }
        return;
    }
    m_queue.push_back(std::move(command));
    pump();
}

void DeviceSession::pump()
{
    if (m_inflight || m_queue.empty() || !m_link)
        return;
    m_inflight = std::move(m_queue.front());
    m_queue.pop_front();
    sendInflight();
}

void DeviceSession::sendInflight()
{
    Command &cmd = *m_inflight;
    cmd.seq = nextSeq();
    switch (cmd.kind) {
    case CommandKind::Hello:
        // Led by a delimiter, as in detection: junk already on the line cannot spoil it.
        cmd.wire = QByteArray(1, '\0') + v2::encodeFrame(cmd.seq, v2::Hello{});
        break;
    case CommandKind::GetParams:
        cmd.wire = v2::encodeFrame(cmd.seq, v2::GetParams{});
        break;
    case CommandKind::SetParams:
        cmd.wire = v2::encodeFrame(cmd.seq, v2::SetParams{cmd.params});
        break;
    case CommandKind::SetStream:
        cmd.wire = v2::encodeFrame(cmd.seq, v2::SetStream{cmd.rate});
        break;
    case CommandKind::Zero:
        cmd.wire = v2::encodeFrame(cmd.seq, v2::Zero{});
        break;
    case CommandKind::SaveParams:
        cmd.wire = v2::encodeFrame(cmd.seq, v2::SaveParams{});
        break;
    }
    m_link->write(cmd.wire);
    m_commandTimer.start();
}

void DeviceSession::onCommandTimeout()
{
    if (!m_inflight || !m_link)
        return;
    Command &cmd = *m_inflight;
    if (cmd.retries < kCommandRetries) {
        // Same bytes, same seq: a device that did answer the first copy answers again
        // without applying it twice.
        ++cmd.retries;
        ++m_stats.retries;
        m_link->write(cmd.wire);
        m_commandTimer.start();
        return;
    }
    const QString name = cmd.readBack ? commandName(cmd.origin) : commandName(cmd.kind);
    if (cmd.kind == CommandKind::Hello) {
        m_inflight.reset();
        failDetection(u"No HATPIC v2 device answered on " % portDescription() % u": HELLO sent " %
                      QString::number(kCommandRetries + 1) % u" times, " %
                      QString::number(kCommandTimeoutMs) % u" ms apart, without a HELLO_REPLY.");
        return;
    }
    if (cmd.readBack) {
        // The device acknowledged the command; only its read-back went unanswered.
        CommandResult r = result(CommandResult::Status::Ok,
                                 u"The device acknowledged " % name %
                                     u", but did not answer the GET_PARAMS read-back.");
        finishInflight(r);
        return;
    }
    CommandResult r = result(CommandResult::Status::Timeout,
                             u"The device did not answer " % name % u" (sent " %
                                 QString::number(kCommandRetries + 1) % u" times, " %
                                 QString::number(kCommandTimeoutMs) % u" ms apart).");
    finishInflight(r);
}

void DeviceSession::finishInflight(const CommandResult &r)
{
    m_commandTimer.stop();
    const quint64 id = m_inflight ? m_inflight->id : 0;
    const CommandKind kind = m_inflight ? m_inflight->kind : CommandKind::GetParams;
    m_inflight.reset();
    if (id)
        Q_EMIT commandFinished(id, r);
    else if (!r.ok())
        qCWarning(lcSession) << commandName(kind) << "during connect:" << r.message;
    pump();
}

void DeviceSession::failAllCommands(const QString &message)
{
    m_commandTimer.stop();
    std::deque<Command> failing;
    if (m_inflight)
        failing.push_back(std::move(*m_inflight));
    m_inflight.reset();
    for (Command &c : m_queue)
        failing.push_back(std::move(c));
    m_queue.clear();
    for (const Command &c : failing) {
        if (c.id)
            Q_EMIT commandFinished(c.id, result(CommandResult::Status::NotConnected, message));
    }
}

// ---------------------------------------------------------------- streams

void DeviceSession::setFeedback(double tauExt)
{
    m_tauExt = std::isfinite(tauExt) ? tauExt : 0.0;
}

void DeviceSession::setFeedbackPaused(bool paused)
{
    m_feedbackPaused = paused;
}

void DeviceSession::sendFeedback()
{
    if (m_phase != Phase::Connected || !m_link || m_feedbackPaused)
        return;
    if (m_protocol == WireProtocol::V2) {
        m_link->write(
            v2::encodeFrame(m_feedbackSeq++, v2::SetFeedback{static_cast<float>(m_tauExt)}));
    } else {
        // One whole frame per write: the published firmware busy-waits from 'i' to 'o'.
        m_legacyField = m_options.legacy.feedbackToField(m_tauExt);
        m_link->write(legacy::encodeFrame(legacy::Frame{m_legacyField, 0, 0, 0}));
    }
}

void DeviceSession::sendPing()
{
    if (m_phase != Phase::Connected || !m_link || m_protocol != WireProtocol::V2)
        return;
    // Not while a command waits for its answer: the device recognises a retry only when it
    // is the very last command it saw, and a PING in between would make it apply a retried
    // ZERO twice. The probe simply waits for the next tick.
    if (m_inflight)
        return;
    const quint32 token = ++m_pingToken;
    if (m_pings.size() >= kMaxPendingPings) {
        // Forget the oldest unanswered probe.
        auto oldest = m_pings.begin();
        for (auto it = m_pings.begin(); it != m_pings.end(); ++it) {
            if (it.value() < oldest.value())
                oldest = it;
        }
        m_pings.erase(oldest);
    }
    m_pings.insert(token, m_clock.nsecsElapsed());
    m_link->write(v2::encodeFrame(nextSeq(), v2::Ping{token}));
}

LinkStats DeviceSession::stats() const
{
    LinkStats s = m_stats;
    const auto &dropped = m_v2.stats().drops;
    for (int i = 0; i < v2::kDropReasonCount; ++i)
        s.decoderDrops[i] = m_dropBase[i] + dropped[i];
    s.legacyMalformed = m_legacyMalformedBase + m_legacy.stats().malformed;
    s.rttLastMs = m_rtt.last();
    s.rttMedianMs = m_rtt.median();
    s.rttMaxMs = m_rtt.max();
    s.referenceGaps = m_builder.referenceGaps();
    return s;
}

void DeviceSession::onStatsTick()
{
    const qint64 now = m_clock.nsecsElapsed();
    m_rateMarks.push_back({now, m_stats.frames, m_stats.bytes});
    // Rates over the last second: the oldest mark at least 1 s old (or the oldest we have).
    while (m_rateMarks.size() > 2 && now - m_rateMarks[1].ns >= 1'000'000'000)
        m_rateMarks.pop_front();
    const RateMark &from = m_rateMarks.front();
    const double seconds = static_cast<double>(now - from.ns) * 1e-9;
    if (seconds > 0) {
        m_stats.framesPerSecond = static_cast<double>(m_stats.frames - from.frames) / seconds;
        m_stats.bytesPerSecond = static_cast<double>(m_stats.bytes - from.bytes) / seconds;
    }
    if (m_phase == Phase::Connected && now - m_lastRxNs > qint64(kSilenceTimeoutMs) * 1'000'000) {
        linkLost(u"no data from the device for " % QString::number(kSilenceTimeoutMs / 1000.0) %
                 u" s");
    }
    Q_EMIT statsUpdated(stats());
}

// ---------------------------------------------------------------- samples and events

void DeviceSession::pushSample(const Sample &sample)
{
    m_batch.append(sample);
    if (m_batch.size() >= kBatchMaxSamples)
        flushBatch();
}

void DeviceSession::flushBatch()
{
    if (m_batch.isEmpty())
        return;
    SampleBatch batch;
    batch.swap(m_batch);
    m_batch.reserve(kBatchMaxSamples);
    if (m_recorder.isOpen() && !m_recorder.append(batch))
        closeRecording(m_recorder.error());
    Q_EMIT samplesReady(batch);
}

void DeviceSession::applyPendingEffect()
{
    const PendingEffect effect = *m_pendingEffect;
    m_pendingEffect.reset();
    flushBatch(); // the event belongs to the next sample, not to those already waiting
    if (effect.kind == CommandKind::Zero) {
        addEvent(u"ZERO: theta0 := current angle (was " %
                 compactNumberText(m_builder.deviceParams().theta0) % u')');
        return;
    }
    const QString change = describeParamChange(m_builder.deviceParams(), effect.params);
    m_builder.setDeviceParams(effect.params);
    addEvent(change.isEmpty() ? QStringLiteral("SET_PARAMS (no change)") : change);
}

void DeviceSession::addEvent(const QString &text)
{
    if (m_recorder.isOpen())
        m_recorder.addEvent(text);
}

void DeviceSession::setHostParams(const HostParams &host)
{
    const auto violations = validate(host);
    if (!violations.empty()) {
        QStringList messages;
        for (const Violation &v : violations)
            messages << QString::fromStdString(v.message());
        qCWarning(lcSession) << "host parameters refused:" << messages;
        Q_EMIT deviceLog(u"Host parameters refused: " % messages.join(QStringLiteral("; ")));
        return;
    }
    const HostParams old = m_builder.hostParams();
    if (old == host)
        return;
    flushBatch();
    m_builder.setHostParams(host);
    if (m_protocol == WireProtocol::Legacy)
        m_builder.setTauLimit(host.tau_limit);
    addEvent(describeHostChange(old, host));
}

void DeviceSession::resetReference()
{
    flushBatch();
    m_builder.resetReference();
    addEvent(QStringLiteral("p_ref reset to 0"));
}

void DeviceSession::setSimulatedHand(const HandInput &hand)
{
    m_options.sim.hand = hand;
    if (SimLink *sim = simLink())
        sim->setHand(hand);
}

SimLink *DeviceSession::simLink() const
{
    return qobject_cast<SimLink *>(m_link);
}

// ---------------------------------------------------------------- recording

void DeviceSession::startRecording(const QString &csvPath, const QString &source)
{
    if (m_recorder.isOpen()) {
        flushBatch();
        closeRecording();
    }
    if (m_state != SessionState::Connected) {
        emitRecordingStatus(QStringLiteral("Not connected: a recording starts once a device is "
                                           "connected."));
        return;
    }
    flushBatch(); // samples that arrived before the start are not part of the recording
    RecordingMetadata meta;
    meta.start = QDateTime::currentDateTimeUtc();
    meta.device = m_info;
    meta.params = m_builder.deviceParams();
    meta.host = m_builder.hostParams();
    meta.source = source;
    if (!m_recorder.open(csvPath, meta)) {
        emitRecordingStatus(m_recorder.error());
        return;
    }
    m_recordingTimer.start();
    emitRecordingStatus();
}

void DeviceSession::stopRecording()
{
    if (!m_recorder.isOpen())
        return;
    flushBatch();
    closeRecording();
}

void DeviceSession::onRecordingFlushTick()
{
    if (!m_recorder.isOpen()) {
        m_recordingTimer.stop();
        return;
    }
    flushBatch();
    if (m_recorder.isOpen() && !m_recorder.flush()) {
        closeRecording(m_recorder.error());
        return;
    }
    if (m_recorder.isOpen())
        emitRecordingStatus();
}

void DeviceSession::closeRecording(const QString &error)
{
    m_recordingTimer.stop();
    const bool wasOpen = m_recorder.isOpen();
    m_recorder.close();
    if (wasOpen || !error.isEmpty())
        emitRecordingStatus(error.isEmpty() ? m_recorder.error() : error);
}

void DeviceSession::emitRecordingStatus(const QString &error)
{
    RecordingStatus status = m_recorder.status();
    if (!error.isEmpty())
        status.error = error;
    Q_EMIT recordingChanged(status);
}

} // namespace hatpic
