#include "experimentrunner.h"

#include "protocol/messages.h"
#include "session/deviceclient.h"

#include <algorithm>
#include <cmath>

namespace hatpic {

ExperimentRunner::ExperimentRunner(DeviceClient &client, SimulatedJoystick *simulator,
                                   QObject *parent)
    : QObject(parent), m_client(&client), m_simulator(simulator)
{
    qRegisterMetaType<ExperimentResult>();
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(kTickMs);
    connect(&m_timer, &QTimer::timeout, this, &ExperimentRunner::tick);
    m_drainTimer.setSingleShot(true);
    m_drainTimer.setInterval(kDrainTimeoutMs);
    connect(&m_drainTimer, &QTimer::timeout, this,
            [this] { end(ExperimentResult::Outcome::Completed, {}); });
    m_releaseTimer.setSingleShot(true);
    m_releaseTimer.setInterval(kReleaseMs);
    connect(&m_releaseTimer, &QTimer::timeout, this, [this] {
        m_releasing = false;
        beginPlanWhenReady();
    });
    connect(&client, &DeviceClient::samplesReady, this, &ExperimentRunner::onSamples);
    connect(&client, &DeviceClient::deviceLog, this, &ExperimentRunner::onDeviceLog);
    connect(&client, &DeviceClient::stateChanged, this, [this](SessionState state) {
        if (running() && state != SessionState::Connected)
            end(ExperimentResult::Outcome::Failed,
                QStringLiteral("The device was lost during the experiment."));
    });
}

ExperimentRunner::~ExperimentRunner()
{
    if (running() && m_client) {
        m_client->setFeedback(0);
        restoreHand();
        restorePassivity();
    }
}

RunHand ExperimentRunner::handFor() const
{
    return m_client && m_simulator && m_client->deviceInfo().simulated ? RunHand::SimulatedIdle
                                                                       : RunHand::User;
}

QString ExperimentRunner::refusal(const DeviceClient &client)
{
    if (client.state() != SessionState::Connected)
        return QStringLiteral("No device is connected.");
    if (client.deviceInfo().protocol == WireProtocol::Legacy)
        return QStringLiteral(
            "Experiments need a protocol v2 device: the legacy firmware has no telemetry rate to "
            "ask for (it streams at its own few hertz) and reports no τ_ext, too little to "
            "measure a response.");
    if (!client.deviceTuning().params ||
        (client.deviceInfo().hasPassivity() && !client.deviceTuning().passivity))
        return QStringLiteral("The device's parameters have not been read yet.");
    return {};
}

QString ExperimentRunner::start(const ExperimentPlan &plan)
{
    if (running())
        return QStringLiteral("An experiment is already running.");
    if (!m_client)
        return QStringLiteral("No device is connected.");
    if (QString why = refusal(*m_client); !why.isEmpty())
        return why;
    const DeviceParams params = *m_client->deviceTuning().params;
    if (plan.kind != ExperimentKind::Spectrum && !(params.K_max > 0))
        return QStringLiteral("The knob has no re-centering stiffness (K_max = 0), so it has no "
                              "second-order response to measure.");
    const double tauLimit = m_client->deviceInfo().tauLimit;
    if (QString why = plan.check(tauLimit); !why.isEmpty())
        return why;
    m_plan = plan;
    m_params = params;
    m_tauLimit = tauLimit;
    m_samples.clear();
    m_deviceLog.clear();
    m_deviceClock = ClockMap();
    m_lastProgress = -1;
    m_hand = handFor();
    m_handBefore = m_hand == RunHand::SimulatedIdle ? m_simulator->hand() : HandInput{};
    m_client->setFeedback(m_plan.tauExt(0));
    m_passivityBefore.reset();
    m_phase = Phase::Preparing;
    const std::optional<PassivityParams> &passivity = m_client->deviceTuning().passivity;
    m_quieting = passivity && passivity->enabled();
    if (m_quieting) {
        // The controller off before the plan, once the device has taken it.
        m_passivityBefore = *passivity;
        DeviceTuning off;
        off.passivity = PassivityParams{0.0, passivity->pc_reserve_max};
        m_client->request(request::Push{off},
                          {this, [this](const Outcome &outcome) { onQuieted(outcome); }});
        if (m_phase != Phase::Preparing)
            return {}; // refused at once: the run has ended, saying why
    }
    m_releasing = m_hand == RunHand::SimulatedIdle && m_handBefore.kind != HandInput::Kind::Idle;
    if (m_releasing) {
        // The hand lets go; the knob comes to rest at the plan's first level, then the plan.
        m_simulator->setHand(HandInput{});
        m_releaseTimer.start();
    }
    beginPlanWhenReady();
    return {};
}

void ExperimentRunner::onQuieted(const Outcome &outcome)
{
    if (m_phase != Phase::Preparing || !m_quieting)
        return; // the run ended meanwhile
    m_quieting = false;
    if (!outcome.ok()) {
        // Whether a timed-out SET_PASSIVITY took effect is unknown: end() sends the block back.
        end(ExperimentResult::Outcome::Failed,
            QStringLiteral("The device did not turn its passivity controller off for the run, "
                           "so the experiment did not start."));
        return;
    }
    beginPlanWhenReady();
}

void ExperimentRunner::beginPlanWhenReady()
{
    if (m_phase == Phase::Preparing && !m_quieting && !m_releasing)
        beginPlan();
}

void ExperimentRunner::restorePassivity()
{
    if (!m_passivityBefore)
        return;
    if (m_client)
        sendPassivity(*m_passivityBefore, kRestoreAttempts);
    m_passivityBefore.reset();
}

void ExperimentRunner::sendPassivity(const PassivityParams &block, int attempts)
{
    DeviceTuning tuning;
    tuning.passivity = block;
    m_client->request(request::Push{tuning},
                      {this, [this, block, attempts](const Outcome &outcome) {
                           const bool unanswered =
                               std::holds_alternative<outcome::TimedOut>(outcome.result) ||
                               std::holds_alternative<outcome::QueueFull>(outcome.result);
                           // Not once a new run has begun: it sends its own block back.
                           if (unanswered && attempts > 1 && m_client && !running())
                               sendPassivity(block, attempts - 1);
                       }});
}

void ExperimentRunner::beginPlan()
{
    m_phase = Phase::Running;
    m_clock.start();
    if (m_client)
        m_client->setFeedback(m_plan.tauExt(0));
    m_timer.start();
}

void ExperimentRunner::restoreHand()
{
    if (m_simulator && m_hand == RunHand::SimulatedIdle && m_simulator->hand() != m_handBefore)
        m_simulator->setHand(m_handBefore);
}

void ExperimentRunner::cancel()
{
    if (running())
        end(ExperimentResult::Outcome::Cancelled, QStringLiteral("The experiment was cancelled."));
}

double ExperimentRunner::elapsed() const
{
    return static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
}

void ExperimentRunner::tick()
{
    if (!m_client) {
        end(ExperimentResult::Outcome::Failed, QStringLiteral("The device was closed."));
        return;
    }
    const double t = elapsed();
    if (t >= m_plan.totalDuration()) {
        // The plan is over: τ_ext back to 0 at once, then wait for its last samples.
        m_timer.stop();
        if (m_client)
            m_client->setFeedback(0);
        m_phase = Phase::Draining;
        m_drainTimer.start();
        Q_EMIT progress(1.0);
        return;
    }
    m_client->setFeedback(m_plan.tauExt(t));
    const int percent = static_cast<int>(100 * t / m_plan.totalDuration());
    if (percent != m_lastProgress) {
        m_lastProgress = percent;
        Q_EMIT progress(percent / 100.0);
    }
}

void ExperimentRunner::onDeviceLog(const QString &line)
{
    if (running() && m_deviceLog.size() < kMaxLogLines)
        m_deviceLog.append(line);
}

void ExperimentRunner::onSamples(const QList<Sample> &batch)
{
    if (!running() || m_phase == Phase::Preparing || batch.isEmpty())
        return;
    for (const Sample &s : batch) {
        if (s.flags & v2::kFlagTorqueOff) {
            QString why = QStringLiteral(
                "The device has turned its torque off (a servo bus fault): the knob could not "
                "follow the experiment, so it has no figures.");
            if (!m_deviceLog.isEmpty())
                why +=
                    u" The device said: \"" + m_deviceLog.join(QStringLiteral("\"; \"")) + u"\".";
            end(ExperimentResult::Outcome::Failed, why);
            return;
        }
    }
    const double now = elapsed();
    m_deviceClock.add(now, batch.last().t_s - now);
    const qsizetype room = kMaxSamples - m_samples.size();
    m_samples.append(batch.mid(0, std::min(room, batch.size())));
    if (m_phase == Phase::Draining &&
        batch.last().t_s >= m_deviceClock.deviceTime(m_plan.totalDuration()))
        end(ExperimentResult::Outcome::Completed, {});
}

void ExperimentRunner::end(ExperimentResult::Outcome outcome, const QString &problem)
{
    if (!running())
        return;
    m_timer.stop();
    m_drainTimer.stop();
    m_releaseTimer.stop();
    m_quieting = false;
    m_releasing = false;
    if (m_client)
        m_client->setFeedback(0);
    restoreHand();
    restorePassivity();
    m_phase = Phase::Idle;
    ExperimentResult result;
    if (outcome == ExperimentResult::Outcome::Completed) {
        result = analyseExperiment(m_plan, m_samples, m_deviceClock, m_params, m_tauLimit);
    } else {
        result.plan = m_plan;
        result.params = m_params;
        result.tauLimit = m_tauLimit;
        result.samples = m_samples;
        result.clock = m_deviceClock;
        result.problem = problem;
    }
    result.outcome = outcome;
    result.hand = m_hand;
    m_samples.clear();
    Q_EMIT finished(result);
}

} // namespace hatpic
