#include "devicesession.h"

#include "link/seriallink.h"
#include "model/overloaded.h"
#include "session/legacydriver.h"
#include "session/sessionwording.h"
#include "session/v2driver.h"

#include <QLoggingCategory>

#include <algorithm>
#include <limits>

Q_LOGGING_CATEGORY(lcSession, "hatpic.device.session", QtWarningMsg)

namespace hatpic {

DeviceSession::DeviceSession(QObject *parent)
    : QObject(parent), m_reconnectTimer(this), m_statsTimer(this), m_queue(this),
      m_detector(m_queue, m_statistics, this),
      m_feedback([this](const AxisTorques &tauExt) { sendFeedback(tauExt); }, this),
      m_ping(
          m_clock, [this](quint32 token) { return sendPing(token); }, this),
      m_deviceText(this), m_samples(this)
{
    registerSessionMetaTypes();
    m_clock.start();

    m_reconnectTimer.setSingleShot(true);
    m_reconnectTimer.setInterval(kReconnectIntervalMs);
    m_statsTimer.setInterval(kStatsIntervalMs);

    connect(&m_reconnectTimer, &QTimer::timeout, this, &DeviceSession::tryReconnect);
    connect(&m_statsTimer, &QTimer::timeout, this, &DeviceSession::onStatsTick);

    connect(&m_detector, &ProtocolDetector::progress, this,
            [this](const StateDetail &detail) { setState(SessionState::Detecting, detail); });
    connect(&m_detector, &ProtocolDetector::foundLegacy, this, &DeviceSession::onFoundLegacy);
    connect(&m_detector, &ProtocolDetector::foundV2, this, &DeviceSession::onFoundV2);
    connect(&m_detector, &ProtocolDetector::failed, this, &DeviceSession::failDetection);

    connect(&m_deviceText, &DeviceTextGate::line, this, &DeviceSession::deviceLog);
    connect(&m_queue, &CommandQueue::finished, this, &DeviceSession::onCommandFinished);
    connect(&m_queue, &CommandQueue::retried, this, [this] { m_statistics.countRetry(); });
    connect(&m_queue, &CommandQueue::acknowledged, this, &DeviceSession::onAcknowledged);

    connect(&m_samples, &SamplePipeline::notice, this, &DeviceSession::notice);
}

DeviceSession::~DeviceSession()
{
    // Nobody listens any more: close quietly (the samples' signals too, which go straight out).
    blockSignals(true);
    m_samples.blockSignals(true);
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
    m_samples.clear();
    m_statsTimer.start();
    openLink();
}

void DeviceSession::disconnectDevice()
{
    const bool wasActive = m_wanted || m_link || m_state != SessionState::Disconnected;
    m_wanted = false;
    m_reconnectTimer.stop();
    m_samples.flush(); // every sample received reaches samplesReady (and the recording)
    m_samples.stopRecording();
    m_queue.failAll(outcome::Cut::Why::Disconnected);
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
    m_samples.stop();
}

StateDetail DeviceSession::detail(StateDetail::Why why) const
{
    return stateDetail(std::move(why), m_options, m_link);
}

void DeviceSession::openLink()
{
    closeLink();
    const qint32 baud = requestedBaud(m_options);
    m_link = m_options.link ? m_options.link->makeLink(baud, this)
                            : new SerialLink(m_options.port, baud, this);
    connect(m_link, &ByteLink::bytesReceived, this, &DeviceSession::onBytes);
    connect(m_link, &ByteLink::failed, this, &DeviceSession::linkLost);

    if (!m_everConnected)
        setState(SessionState::Opening, detail(state::Opening{}));
    if (!m_link->open()) {
        const StateDetail error = detail(state::OpenFailed{m_link->errorString()});
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
    m_deviceText.flush();
    m_detector.stop();
    m_queue.setWriter({});
    m_feedback.stop();
    m_ping.stop();
    if (m_driver) {
        if (const v2::DecoderStats *decoded = m_driver->v2Stats())
            m_statistics.absorb(*decoded);
        if (const legacy::DecoderStats *decoded = m_driver->legacyStats())
            m_statistics.absorb(*decoded);
        // Kept until the next close: this may run inside one of the driver's own writes.
        m_retired = std::move(m_driver);
    }
    m_pendingChange.reset();
    if (m_link) {
        m_link->disconnect(this);
        m_link->close();
        // Deferred: this may run inside one of the link's own signals.
        m_link->deleteLater();
        m_link = nullptr;
    }
}

void DeviceSession::sendFeedback(const AxisTorques &tauExt)
{
    if (m_driver && m_link)
        m_driver->sendFeedback(tauExt);
}

bool DeviceSession::sendPing(quint32 token)
{
    return m_driver && m_link && m_driver->sendPing(token);
}

DriverWrite DeviceSession::writer()
{
    return [this](const QByteArray &bytes) { write(bytes); };
}

void DeviceSession::dispatch(const std::vector<Received> &events)
{
    const ProtocolDriver *driver = m_driver.get();
    for (const Received &event : events) {
        if (!driver || m_driver.get() != driver)
            return; // a handler closed the link: the rest is not this connection's
        std::visit(Overloaded{
                       [this](const received::Telemetry &t) {
                           if (!m_statistics.countTelemetry(t.seq, t.telemetry.t_us))
                               return; // a repeat
                           if (!t.finite) {
                               m_statistics.countNonFinite();
                               return;
                           }
                           applyPendingChange();
                           m_samples.push(m_samples.builder().fromTelemetry(
                               t.telemetry, m_clock.nsecsElapsed() / 1000));
                       },
                       [this](const received::LegacyFrame &f) {
                           m_statistics.countFrame();
                           if (f.frame.tilt && !m_info.tilt) { // the IMU branch's board
                               m_info = m_driver->info();
                               Q_EMIT deviceInfoChanged(m_info);
                           }
                           m_samples.push(m_samples.builder().fromLegacy(
                               f.frame, *f.conversion, f.tauExt, m_clock.nsecsElapsed() / 1000));
                       },
                       [this](const v2::Ack &ack) { m_queue.onAck(ack); },
                       [this](const received::Tuning &tuning) {
                           if (tuning.knob == 0) {   // the session's: knob 1's
                               applyPendingChange(); // streaming off: no telemetry carried it
                               m_samples.tuningReceived(tuning.told);
                           }
                           m_queue.onTuning(tuning.told, tuning.knob);
                       },
                       [this](const received::Pong &pong) { m_ping.onPong(pong.token); },
                       [this](const received::Text &text) { m_deviceText.feed(text.line); },
                   },
                   event);
    }
}

void DeviceSession::onAcknowledged(const Command &command)
{
    // Another knob's tuning changed: the session's (knob 1's) did not.
    const bool sessionsKnob = command.knob() == 0;
    // The acknowledged step's message carries what it applied.
    std::visit(Overloaded{
                   [&](const v2::SetParams &set) {
                       if (sessionsKnob)
                           m_pendingChange = {CommandKind::SetParams, {set.params, {}, {}}};
                   },
                   [&](const v2::SetEffects &set) {
                       if (sessionsKnob)
                           m_pendingChange = {CommandKind::SetEffects, {{}, set.effects, {}}};
                   },
                   [&](const v2::SetPassivity &set) {
                       if (sessionsKnob)
                           m_pendingChange = {CommandKind::SetPassivity, {{}, {}, set.passivity}};
                   },
                   [&](const v2::Zero &) {
                       if (sessionsKnob)
                           m_pendingChange = {CommandKind::Zero, {}};
                   },
                   [&](const v2::SetStream &set) {
                       m_statistics.restartSeq(); // a new stream: no gap to count against the old
                       m_options.streamRateHz = set.rateHz; // a reconnect asks for the same rate
                   },
                   [](const auto &) {},
               },
               command.stepMessage());
}

void DeviceSession::applyPendingChange()
{
    if (!m_pendingChange)
        return;
    const auto [kind, applied] = *m_pendingChange;
    m_pendingChange.reset();
    m_samples.tuningApplied(kind, applied);
}

void DeviceSession::write(const QByteArray &bytes)
{
    if (m_link)
        m_link->write(bytes);
}

void DeviceSession::setState(SessionState state, const StateDetail &detail)
{
    if (state == m_state && detail == m_stateDetail)
        return;
    m_state = state;
    m_stateDetail = detail;
    qCInfo(lcSession) << sessionStateName(state) << SessionWording::stateDetail(detail);
    Q_EMIT stateChanged(state, detail);
}

void DeviceSession::failDetection(const StateDetail &message)
{
    qCWarning(lcSession) << "detection failed:" << SessionWording::stateDetail(message);
    m_queue.failAll(outcome::Cut::Why::DetectionFailed);
    closeLink();
    if (m_everConnected && m_wanted && m_options.autoReconnect) {
        // A port that came back without its device yet: keep trying.
        setState(SessionState::Lost, message);
        m_reconnectTimer.start();
        return;
    }
    m_wanted = false;
    m_statsTimer.stop();
    m_samples.stopRecording(); // no device comes back for a recording that waits
    setState(SessionState::Disconnected, message);
}

void DeviceSession::onFoundV2(const v2::HelloReply &reply, const QList<v2::Frame> &rest)
{
    if (const QString problem = helloReplyProblem(reply); !problem.isEmpty()) {
        failDetection(detail(state::Refused{problem}));
        return;
    }
    auto driver = std::make_unique<V2Driver>(reply, m_options, m_link->baud(),
                                             m_detector.takeDecoder(), m_queue, writer());
    V2Driver *v2 = driver.get();
    becomeConnected(std::move(driver));
    if (m_driver.get() == v2) { // what came after the reply in the same read
        std::vector<Received> events;
        v2->decode(rest, events);
        dispatch(events);
    }
}

void DeviceSession::onFoundLegacy()
{
    auto driver = std::make_unique<LegacyDriver>(m_options, m_link->baud(), writer());
    if (m_detector.heardImuBranch()) // known before the first sample, and so to a recording
        driver->noteImuBranch();
    becomeConnected(std::move(driver));
}

void DeviceSession::becomeConnected(std::unique_ptr<ProtocolDriver> driver)
{
    m_driver = std::move(driver);
    m_info = m_driver->info();
    m_everConnected = true;
    Q_EMIT deviceInfoChanged(m_info);
    setState(SessionState::Connected, detail(m_driver->connected()));
    m_samples.builder().setTauLimit(m_driver->sampleTauLimit(m_samples.builder().hostParams()));
    m_statistics.restartSeq();
    for (const Request &request : m_driver->startRequests())
        m_queue.enqueue(Command{request, wireSteps(request, m_info), {}});
    if (!m_link)
        return; // lost while writing the first command
    m_samples.connectionStarted(m_info);
    m_statistics.markReceived(m_clock.nsecsElapsed());
    m_feedback.start(std::min(m_options.feedbackRateHz, m_driver->maxFeedbackHz()));
    m_ping.start();
}

void DeviceSession::linkLost(const QString &reason)
{
    loseLink(detail(state::LinkFailed{reason}));
}

void DeviceSession::loseLink(const StateDetail &lost)
{
    if (!m_link)
        return;
    qCWarning(lcSession) << SessionWording::stateDetail(lost);
    m_queue.failAll(outcome::Cut::Why::ConnectionLost);
    closeLink();
    // A recording waits for the device when the session reconnects, else it closes.
    m_samples.connectionEnded(lost, m_wanted && m_options.autoReconnect);
    Q_EMIT statsUpdated(stats()); // the final figures, before anyone reads them as such
    setState(SessionState::Lost, lost);
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
    else if (m_driver) {
        std::vector<Received> events;
        m_driver->feed(bytes, events);
        dispatch(events);
    }
}

LinkStats DeviceSession::stats() const
{
    LinkStats s = m_driver ? m_statistics.snapshot(m_driver->v2Stats(), m_driver->legacyStats())
                           : m_statistics.snapshot(&m_detector.decoderStats(), nullptr);
    s.rttLastMs = m_ping.rtt().last();
    s.rttMedianMs = m_ping.rtt().median();
    s.rttMaxMs = m_ping.rtt().max();
    s.referenceGaps = m_samples.builder().referenceGaps();
    return s;
}

void DeviceSession::onStatsTick()
{
    const qint64 now = m_clock.nsecsElapsed();
    m_statistics.tick(now);
    if (m_driver && now - m_statistics.lastReceivedNs() > qint64(kSilenceTimeoutMs) * 1'000'000) {
        loseLink(detail(state::Silent{kSilenceTimeoutMs}));
    }
    Q_EMIT statsUpdated(stats());
}

// ---------------------------------------------------------------- commands

void DeviceSession::request(Request request, OutcomeHandler then)
{
    if (auto *push = std::get_if<request::Push>(&request); push && m_driver) {
        DeviceTuning &tuning = push->tuning;
        if (tuning.passivity && !m_info.hasPassivity() && (tuning.params || tuning.effects))
            tuning.passivity.reset();
    }
    const std::vector<CommandKind> kinds = stepKinds(wireSteps(request, m_info));
    if (std::optional<Outcome::Result> refused = refusal(request, kinds)) {
        if (then)
            then(Outcome{std::move(request), std::move(*refused), {}});
        return;
    }
    if (auto *push = std::get_if<request::Push>(&request)) {
        DeviceTuning &tuning = push->tuning;
        if (tuning.params)
            tuning.params = roundedForWire(*tuning.params);
        if (tuning.effects)
            tuning.effects = roundedForWire(*tuning.effects, m_info.tauLimit);
        if (tuning.passivity)
            tuning.passivity = roundedForWire(*tuning.passivity);
    }
    if (kinds.empty()) { // a push of nothing
        if (then)
            then(Outcome{std::move(request), outcome::Done{}, {}});
        return;
    }
    // The steps' messages carry the tuning as rounded.
    std::vector<WireStep> steps = wireSteps(request, m_info);
    m_queue.enqueue(Command{std::move(request), std::move(steps), std::move(then)});
}

std::optional<Outcome::Result> DeviceSession::refusal(const Request &request,
                                                      const std::vector<CommandKind> &steps) const
{
    // What the device cannot carry first: no value makes that right.
    for (const CommandKind step : steps) {
        if (const auto why = m_driver ? m_driver->refusal(step) : std::nullopt)
            return outcome::Unsupported{step, *why};
    }
    if (const Knob knob = knobOf(request); m_driver && !steps.empty() && knob >= m_info.axes)
        return outcome::Unsupported{steps.front(), outcome::Unsupported::Why::NoSuchKnob, knob,
                                    m_info.axes};
    std::vector<Violation> violations;
    if (const auto *push = std::get_if<request::Push>(&request); push && m_validate) {
        const DeviceTuning &tuning = push->tuning;
        if (tuning.params)
            violations = validate(*tuning.params);
        // The effects only once the device (its tau_limit) is known.
        if (tuning.effects && m_driver) {
            const auto more = validate(*tuning.effects, m_info.tauLimit);
            violations.insert(violations.end(), more.begin(), more.end());
        }
        if (tuning.passivity) {
            const auto more = validate(*tuning.passivity);
            violations.insert(violations.end(), more.begin(), more.end());
        }
    } else if (const auto *cue = std::get_if<request::Vibrate>(&request);
               cue && m_validate && m_driver) {
        // The control rate is the device's: an infinite one leaves f < rate/2 to the device.
        violations =
            validate(cue->vibration, m_info.tauLimit, std::numeric_limits<double>::infinity());
    }
    if (!violations.empty()) {
        outcome::Invalid invalid;
        for (const Violation &v : violations)
            invalid.problems << QString::fromStdString(v.message());
        return invalid;
    }
    if (!m_driver)
        return outcome::NotConnected{};
    return std::nullopt;
}

void DeviceSession::onCommandFinished(const Command &command, const Outcome &outcome)
{
    if (command.then)
        command.then(outcome);
}

// ---------------------------------------------------------------- host side

void DeviceSession::setFeedback(double tauExt)
{
    m_feedback.setTauExt(tauExt);
}

void DeviceSession::setFeedback(const AxisTorques &tauExt)
{
    m_feedback.setTorques(tauExt);
}

void DeviceSession::setHostParams(const HostParams &host)
{
    const auto violations = validate(host);
    if (!violations.empty()) {
        SessionNotice refused{SessionNotice::Kind::HostParamsRefused, {}};
        for (const Violation &v : violations)
            refused.problems << QString::fromStdString(v.message());
        qCWarning(lcSession) << "host parameters refused:" << refused.problems;
        Q_EMIT notice(refused);
        return;
    }
    if (m_samples.setHostParams(host) && m_driver)
        m_samples.builder().setTauLimit(m_driver->sampleTauLimit(host));
}

void DeviceSession::resetReference()
{
    m_samples.resetReference();
}

// ---------------------------------------------------------------- recording

void DeviceSession::startRecording(const QString &csvPath, const QString &source,
                                   const RecordingPlan &plan)
{
    if (m_state != SessionState::Connected) {
        m_samples.stopRecording();
        Q_EMIT notice({SessionNotice::Kind::RecordingNeedsDevice, {}});
        return;
    }
    m_samples.startRecording(csvPath, source, m_info, plan);
}

void DeviceSession::stopRecording()
{
    m_samples.stopRecording();
}

} // namespace hatpic
