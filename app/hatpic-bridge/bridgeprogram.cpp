#include "bridgeprogram.h"

#include "common/exitcodes.h"
#include "realtime/realtime.h"
#include "session/sessionwording.h"

#include <QElapsedTimer>
#include <QEventLoop>

#include <cmath>
#include <cstdio>

namespace hatpic::bridge {

namespace {

QString num(double v)
{
    return QString::number(v, 'g', 4);
}

//! A time in milliseconds, "–" when not measured.
QString ms(double seconds)
{
    return std::isfinite(seconds) ? num(seconds * 1e3) : QStringLiteral("–");
}

//! "12/20 ms": the median and the 95th percentile.
QString spread(const Spread &s)
{
    return ms(s.median) + u'/' + ms(s.p95) + u" ms";
}

void printLine(FILE *stream, const QString &line)
{
    std::fprintf(stream, "%s\n", line.toUtf8().constData());
    std::fflush(stream);
}

} // namespace

BridgeProgram::BridgeProgram(const AppOptions &options, QObject *parent)
    : QObject(parent), m_options(options), m_bridge(m_client)
{
    m_statsTimer.setInterval(kStatsIntervalMs);
    connect(&m_statsTimer, &QTimer::timeout, this, &BridgeProgram::printStats);
    m_retryTimer.setSingleShot(true);
    m_retryTimer.setInterval(kRetryIntervalMs);
    connect(&m_retryTimer, &QTimer::timeout, this,
            [this] { m_client.connectDevice(m_options.connect); });
    connect(&m_client, &DeviceClient::stateChanged, this, &BridgeProgram::onStateChanged);
    connect(&m_client, &DeviceClient::deviceLog, this,
            [](const QString &line) { printLine(stderr, u"hatpic-bridge: device: " + line); });
}

QString BridgeProgram::start()
{
    // The robot path real-time where the system allows it: memory locked here, the session
    // thread's scheduling by the client (said on connecting), the middleware's by core/ros.
    if (const std::string problem = realtime::lockMemory(); !problem.empty())
        printLine(stderr, u"hatpic-bridge: " + QString::fromStdString(problem) + u'.');
    // Said now, before any thread asks for it, and on every status line after (issue 38): a
    // robot path at normal priority is delayed by every busy process on the machine.
    m_realtimeProblem = QString::fromStdString(realtime::probeRealtime());
    if (!m_realtimeProblem.isEmpty() && realtime::firstTimeFor(m_realtimeProblem.toStdString()))
        printLine(stderr, u"hatpic-bridge: robot path: " + m_realtimeProblem + u'.');
    if (m_options.profile)
        m_bridge.setReferenceMode(m_options.profile->host.mode);
    if (const QString error = m_bridge.start(m_options.settings); !error.isEmpty())
        return error;
    m_client.connectDevice(m_options.connect);
    m_statsTimer.start();
    return {};
}

void BridgeProgram::onStateChanged(SessionState state, const StateDetail &event)
{
    // What the device renders is known only while connected. (From the bridge's own figure,
    // the newest sample's: the 20 ms batches on this thread lag behind it, and the last line
    // at exit showed a τ_ext the device had already left.)
    m_deviceKnown = state == SessionState::Connected;
    if (m_closing)
        return;
    const QString detail = SessionWording::stateDetail(event);
    printLine(stderr, u"hatpic-bridge: " + sessionStateName(state) +
                          (detail.isEmpty() ? QString() : u": " + detail));
    if (state == SessionState::Connected) {
        if (const std::string problem = m_client.realtimeProblem();
            !problem.empty() && realtime::firstTimeFor(problem))
            printLine(stderr,
                      u"hatpic-bridge: session thread: " + QString::fromStdString(problem) + u'.');
        onConnected();
    }
    // A first connection that failed is tried again; a lost one reconnects by itself.
    if (state == SessionState::Disconnected)
        m_retryTimer.start();
}

void BridgeProgram::onConnected()
{
    HostParams host = m_options.profile ? m_options.profile->host : HostParams();
    const double limit = m_client.deviceInfo().tauLimit;
    if (std::isfinite(limit) && limit > 0 && limit <= 10)
        host.tau_limit = limit;
    m_client.setHostParams(host);
    // The device's tau_limit is known now (its HELLO): a limit above it is a bad option found
    // late. Refused as the options are, one sentence and the usage exit code (ros.md § Wrench
    // → τ_ext); the feedback is released first, so the device is left without force.
    if (const std::string problem = limitProblem(m_bridge.settings().feedback, limit);
        !problem.empty()) {
        refuse(QString::fromStdString(problem) + u"; restart with a --limit within it.");
        return;
    }
    // The profile's device block: refused by the device, it is a bad option found late too.
    if (m_options.profile && m_client.deviceInfo().canSetParams()) {
        m_client.request(request::Push{{m_options.profile->device, std::nullopt}},
                         {this, [this](const Outcome &outcome) {
                              if (std::holds_alternative<outcome::Refused>(outcome.result) ||
                                  std::holds_alternative<outcome::Invalid>(outcome.result))
                                  refuse(u"--profile: " + SessionWording::commandFailure(outcome));
                          }});
    }
}

void BridgeProgram::refuse(const QString &sentence)
{
    if (m_closing || m_exitCode != ExitSuccess)
        return;
    printLine(stderr, u"hatpic-bridge: " + sentence);
    m_bridge.releaseFeedback();
    m_exitCode = ExitBadUsage;
    Q_EMIT refused();
}

void BridgeProgram::printStats()
{
    const LinkStats link = m_client.stats();
    const BridgeStats s = m_bridge.stats();
    QString out;
    for (int i = 0; i < kOutTopicCount; ++i) {
        out += (i ? u", " : u"") + QString::fromLatin1(outTopicKey(OutTopic(i))) + u' ' +
               QString::number(s.published[i]);
    }
    const QString rtt = link.rttMedianMs < 0 ? QStringLiteral("–") : num(link.rttMedianMs) + u" ms";
    // The operator's axis, when there are axis topics (ros.md § Choosing the knob's axis).
    QString axis;
    if (!m_options.settings.topics.axis.empty() || !m_options.settings.topics.axisIndex.empty()) {
        axis = u" | axis " + QString::fromStdString(s.axis.twistName());
        if (s.pendingAxis)
            axis +=
                u", " + QString::fromStdString(s.pendingAxis->twistName()) + u" in the dead zone";
        if (s.axisRejected > 0)
            axis += u", refused " + QString::number(s.axisRejected) + u" (last '" +
                    QString::fromStdString(s.lastAxisRejected) + u"')";
    }
    printLine(stdout,
              u"link " + sessionStateName(m_client.state()) + u", " + num(link.framesPerSecond) +
                  u" frames/s, " + QString::number(link.seqDrops) + u" missing, rtt " + rtt +
                  u" | out " + out + u" | wrenches " + QString::number(s.wrenches.received) +
                  u", non-finite " + QString::number(s.wrenches.nonFinite) + u", stale " +
                  QString::number(s.wrenches.stale) + u", limited " +
                  QString::number(s.wrenches.limited) + u" | tau_ext " + num(s.tauExt) +
                  u" N·m, device " +
                  (m_deviceKnown && std::isfinite(s.deviceTauExt) ? num(s.deviceTauExt) + u" N·m"
                                                                  : QStringLiteral("–")) +
                  u" | wrench age " + ms(s.timing.age) + u" ms, delay " +
                  spread(s.timing.stampDelay) + u", echo " + spread(s.timing.echoDelay) +
                  u" (median/p95), lost ~" + QString::number(s.timing.lost) + u" | energy " +
                  num(s.passivity.energy * 1e3) + u" mJ" +
                  (s.passivity.warning ? QStringLiteral(", GENERATING") : QString()) +
                  (s.passivity.dampedAtRest ? QStringLiteral(", damped at rest") : QString()) +
                  (m_realtimeProblem.isEmpty() ? QString() : QStringLiteral(" | not real-time")) +
                  // The dead man's state, when there is one (ros.md § Enable switch).
                  (m_options.settings.topics.enable.empty() ? QString()
                   : s.engaged                              ? QStringLiteral(" | engaged")
                                                            : QStringLiteral(" | released")) +
                  axis);
}

void BridgeProgram::shutdown()
{
    m_closing = true;
    m_statsTimer.stop();
    m_retryTimer.stop();
    m_bridge.releaseFeedback(); // τ_ext 0 to the session; publishing goes on
    if (m_client.state() == SessionState::Connected) {
        // The session streams the 0 on its feedback timer; wait until the device's telemetry
        // says so and that has gone out on the feedback topic.
        QEventLoop loop;
        QElapsedTimer waited;
        waited.start();
        QTimer poll;
        connect(&poll, &QTimer::timeout, &loop, [&] {
            if (m_bridge.stats().publishedTauExt == 0 || waited.elapsed() >= kZeroConfirmMs)
                loop.quit();
        });
        poll.start(5);
        loop.exec();
    }
    m_bridge.stop();
    printStats();
    m_client.disconnectDevice();
}

} // namespace hatpic::bridge
