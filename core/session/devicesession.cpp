#include "devicesession.h"

#include "link/seriallink.h"
#include "session/legacydriver.h"
#include "session/v2driver.h"
#include "sim/simlink.h"

#include <QDateTime>
#include <QLoggingCategory>
#include <QStringBuilder>

Q_LOGGING_CATEGORY(lcSession, "hatpic.device.session", QtWarningMsg)

namespace hatpic {

namespace {

CommandResult result(CommandResult::Status status, const QString &message)
{
    CommandResult r;
    r.status = status;
    r.message = message;
    return r;
}

} // namespace

DeviceSession::DeviceSession(QObject *parent)
    : QObject(parent), m_reconnectTimer(this), m_statsTimer(this), m_batchTimer(this),
      m_queue(this), m_detector(m_queue, m_statistics, this),
      m_feedback(
          [this](double tauExt) {
              if (m_driver && m_link)
                  m_driver->sendFeedback(tauExt);
          },
          this),
      m_ping(
          m_clock,
          [this](quint32 token) { return m_driver && m_link && m_driver->sendPing(token); }, this),
      m_recording(this)
{
    registerSessionMetaTypes();
    m_clock.start();

    m_reconnectTimer.setSingleShot(true);
    m_reconnectTimer.setInterval(kReconnectIntervalMs);
    m_statsTimer.setInterval(kStatsIntervalMs);
    m_batchTimer.setTimerType(Qt::PreciseTimer);
    m_batchTimer.setInterval(kBatchIntervalMs);

    connect(&m_reconnectTimer, &QTimer::timeout, this, &DeviceSession::tryReconnect);
    connect(&m_statsTimer, &QTimer::timeout, this, &DeviceSession::onStatsTick);
    connect(&m_batchTimer, &QTimer::timeout, this, &DeviceSession::flushBatch);

    connect(&m_detector, &ProtocolDetector::progress, this,
            [this](const QString &detail) { setState(SessionState::Detecting, detail); });
    connect(&m_detector, &ProtocolDetector::foundLegacy, this, &DeviceSession::onFoundLegacy);
    connect(&m_detector, &ProtocolDetector::foundV2, this, &DeviceSession::onFoundV2);
    connect(&m_detector, &ProtocolDetector::failed, this, &DeviceSession::failDetection);

    connect(&m_queue, &CommandQueue::finished, this, &DeviceSession::onCommandFinished);
    connect(&m_queue, &CommandQueue::retried, this, [this] { m_statistics.countRetry(); });
    connect(&m_queue, &CommandQueue::acknowledged, this, [this](const Command &command) {
        if (command.kind == CommandKind::SetStream)
            m_options.streamRateHz = command.rate; // a reconnect asks for the same rate
    });

    connect(&m_recording, &RecordingSink::statusChanged, this, &DeviceSession::recordingChanged);
    connect(&m_recording, &RecordingSink::aboutToFlush, this, &DeviceSession::flushBatch);
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
    m_statistics.clear();
    m_ping.clear();
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
    m_recording.close();
    m_queue.failAll(QStringLiteral("The session was disconnected before the device answered."));
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
    m_batchTimer.stop();
}

QString DeviceSession::portDescription() const
{
    return hatpic::portDescription(m_options, m_link);
}

void DeviceSession::openLink()
{
    closeLink();
    if (m_options.port == QStringView(kSimPortName))
        m_link = new SimLink(m_options.sim, this);
    else
        m_link = new SerialLink(m_options.port, requestedBaud(m_options), this);
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
    m_statistics.markReceived(m_clock.nsecsElapsed());
    m_queue.setWriter([this](const QByteArray &bytes) { write(bytes); });
    m_detector.start(m_link, m_options);
}

void DeviceSession::closeLink()
{
    m_detector.stop();
    m_queue.setWriter({});
    m_feedback.stop();
    m_ping.stop();
    if (m_driver) {
        m_driver->close();
        // Kept until the next close: this may run inside the driver's own feed().
        m_retired = std::move(m_driver);
    }
    if (m_link) {
        m_link->disconnect(this);
        m_link->close();
        // Deferred: this may run inside one of the link's own signals.
        m_link->deleteLater();
        m_link = nullptr;
    }
}

void DeviceSession::write(const QByteArray &bytes)
{
    if (m_link)
        m_link->write(bytes);
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

void DeviceSession::failDetection(const QString &message)
{
    qCWarning(lcSession) << message;
    m_queue.failAll(message);
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

void DeviceSession::onFoundV2(const v2::HelloReply &reply, const QList<v2::Frame> &rest)
{
    if (const QString problem = helloReplyProblem(reply); !problem.isEmpty()) {
        failDetection(u"Refused the device on " % portDescription() % u": " % problem %
                      u". It does not behave as a HATPIC joystick; nothing was sent to it.");
        return;
    }
    auto driver = std::make_unique<V2Driver>(host(), m_queue, reply, m_options, m_link->baud(),
                                             m_detector.takeDecoder());
    V2Driver *v2 = driver.get();
    becomeConnected(std::move(driver));
    if (m_driver.get() == v2)
        v2->handleFrames(rest); // what came after the reply in the same read
}

void DeviceSession::onFoundLegacy()
{
    becomeConnected(std::make_unique<LegacyDriver>(host(), m_options, m_link->baud()));
}

void DeviceSession::becomeConnected(std::unique_ptr<ProtocolDriver> driver)
{
    m_driver = std::move(driver);
    m_info = m_driver->info();
    m_paramsKnown = false;
    m_everConnected = true;
    Q_EMIT deviceInfoChanged(m_info);
    setState(SessionState::Connected, m_driver->connectedDetail(portDescription()));
    m_driver->start();
    if (!m_link)
        return; // lost while writing the first command
    m_builder.markDiscontinuity();
    m_statistics.markReceived(m_clock.nsecsElapsed());
    m_feedback.start(m_options.feedbackRateHz);
    m_batchTimer.start();
    m_ping.start();
}

void DeviceSession::linkLost(const QString &reason)
{
    if (!m_link)
        return;
    const QString detail = u"Lost " % portDescription() % u": " % reason;
    qCWarning(lcSession) << detail;
    flushBatch();
    if (m_recording.isOpen()) {
        m_recording.close();
        Q_EMIT deviceLog(QStringLiteral("Recording closed: the device was lost."));
    }
    m_queue.failAll(QStringLiteral("The connection was lost before the device answered."));
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

void DeviceSession::onBytes(const QByteArray &bytes)
{
    m_statistics.countBytes(bytes.size(), m_clock.nsecsElapsed());
    if (m_detector.active())
        m_detector.feed(bytes);
    else if (m_driver)
        m_driver->feed(bytes);
}

LinkStats DeviceSession::stats() const
{
    LinkStats s = m_driver ? m_statistics.snapshot(m_driver->v2Stats(), m_driver->legacyStats())
                           : m_statistics.snapshot(&m_detector.decoderStats(), nullptr);
    s.rttLastMs = m_ping.rtt().last();
    s.rttMedianMs = m_ping.rtt().median();
    s.rttMaxMs = m_ping.rtt().max();
    s.referenceGaps = m_builder.referenceGaps();
    return s;
}

void DeviceSession::onStatsTick()
{
    const qint64 now = m_clock.nsecsElapsed();
    m_statistics.tick(now);
    if (m_driver && now - m_statistics.lastReceivedNs() > qint64(kSilenceTimeoutMs) * 1'000'000) {
        linkLost(u"no data from the device for " % QString::number(kSilenceTimeoutMs / 1000.0) %
                 u" s");
    }
    Q_EMIT statsUpdated(stats());
}

// ---------------------------------------------------------------- commands

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
    submit(cmd);
}

void DeviceSession::readParams(quint64 id)
{
    Command cmd;
    cmd.id = id;
    cmd.kind = CommandKind::GetParams;
    submit(cmd);
}

void DeviceSession::zero(quint64 id)
{
    Command cmd;
    cmd.id = id;
    cmd.kind = CommandKind::Zero;
    submit(cmd);
}

void DeviceSession::saveParams(quint64 id)
{
    Command cmd;
    cmd.id = id;
    cmd.kind = CommandKind::SaveParams;
    submit(cmd);
}

void DeviceSession::setStreamRate(quint64 id, quint16 hz)
{
    Command cmd;
    cmd.id = id;
    cmd.kind = CommandKind::SetStream;
    cmd.rate = hz;
    submit(cmd);
}

void DeviceSession::submit(Command command)
{
    if (!m_driver) {
        if (command.id) {
            Q_EMIT commandFinished(command.id,
                                   result(CommandResult::Status::NotConnected,
                                          QStringLiteral("Not connected to a device.")));
        }
        return;
    }
    if (const QString why = m_driver->refusal(command.kind); !why.isEmpty()) {
        if (command.id)
            Q_EMIT commandFinished(command.id, result(CommandResult::Status::Unsupported, why));
        return;
    }
    m_queue.enqueue(std::move(command));
}

void DeviceSession::onCommandFinished(const Command &command, const CommandResult &result)
{
    if (command.id)
        Q_EMIT commandFinished(command.id, result);
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
    m_recording.append(batch);
    Q_EMIT samplesReady(batch);
}

void DeviceSession::applyEffect(CommandKind kind, const DeviceParams &params)
{
    flushBatch(); // the event belongs to the next sample, not to those already waiting
    if (kind == CommandKind::Zero) {
        m_recording.zeroed(m_builder.deviceParams().theta0);
        return;
    }
    m_recording.paramsApplied(m_builder.deviceParams(), params);
    m_builder.setDeviceParams(params);
}

void DeviceSession::paramsReceived(const DeviceParams &params)
{
    const DeviceParams held = m_builder.deviceParams();
    if (m_paramsKnown && !sameOnWire(held, params)) {
        flushBatch();
        m_recording.paramsReadBack(held, params);
    }
    m_builder.setDeviceParams(params);
    m_paramsKnown = true;
    Q_EMIT deviceParamsChanged(params);
}

void DeviceSession::setFeedback(double tauExt)
{
    m_feedback.setTauExt(tauExt);
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
    if (m_driver)
        m_driver->hostParamsChanged(host);
    m_recording.hostChanged(old, host);
}

void DeviceSession::resetReference()
{
    flushBatch();
    m_builder.resetReference();
    m_recording.referenceReset();
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
    if (m_recording.isOpen()) {
        flushBatch();
        m_recording.close();
    }
    if (m_state != SessionState::Connected) {
        m_recording.report(QStringLiteral("Not connected: a recording starts once a device is "
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
    m_recording.open(csvPath, meta);
}

void DeviceSession::stopRecording()
{
    if (!m_recording.isOpen())
        return;
    flushBatch();
    m_recording.close();
}

} // namespace hatpic
