#include "devicerunner.h"

#include "common/exitcodes.h"
#include "console.h"
#include "session/sessionwording.h"

#include "model/overloaded.h"
#include "model/params.h"
#include "telemetry/numbertext.h"

#include <QEventLoop>
#include <QScopeGuard>
#include <QTimer>

#include <cmath>
#include <optional>

namespace hatpic::cli {

using namespace Qt::StringLiterals;

namespace {

constexpr int kResultAfterLossMs = 500; //!< wait for a command's result once the link is lost

QString portText(const ConnectOptions &options)
{
    return options.link && options.link->simulated() ? u"the simulated joystick"_s : options.port;
}

QString secondsText(double seconds)
{
    return compactNumberText(seconds) + (seconds == 1.0 ? u" second"_s : u" seconds"_s);
}

} // namespace

DeviceRunner::DeviceRunner(const DeviceOptions &options) : m_options(options)
{
    QObject::connect(
        &m_client, &DeviceClient::stateChanged, &m_context,
        [this](SessionState state, const StateDetail &detail) { onStateChanged(state, detail); });
    // What the device says for people (a fault, …), escaped by the session, as it comes.
    QObject::connect(&m_client, &DeviceClient::deviceLog, &m_context,
                     [](const QString &line) { printError(u"device: " + line); });
}

DeviceRunner::~DeviceRunner()
{
    m_closing = true;
    if (m_started)
        m_client.disconnectDevice();
}

void DeviceRunner::onStateChanged(SessionState state, const StateDetail &detail)
{
    if (!m_started || m_closing)
        return;
    const bool gone = state == SessionState::Lost || state == SessionState::Disconnected;
    if (gone && !m_lost) {
        m_lost = true;
        m_lostDetail = SessionWording::stateDetail(detail);
    }
}

DeviceRunner::Wait DeviceRunner::wait(const std::function<bool()> &done, double seconds)
{
    if (m_lost)
        return Wait::Lost;
    if (done())
        return Wait::Done;

    QEventLoop loop;
    Wait outcome = Wait::TimedOut;
    const auto check = [&] {
        if (m_lost) {
            outcome = Wait::Lost;
            loop.quit();
        } else if (done()) {
            outcome = Wait::Done;
            loop.quit();
        }
    };
    // Everything the client reports; a caller's own slots, connected before, have run.
    QObject::connect(&m_client, &DeviceClient::stateChanged, &loop, check);
    QObject::connect(&m_client, &DeviceClient::deviceInfoChanged, &loop, check);
    QObject::connect(&m_client, &DeviceClient::deviceTuningChanged, &loop, check);
    QObject::connect(&m_client, &DeviceClient::samplesReady, &loop, check);
    QObject::connect(&m_client, &DeviceClient::statsUpdated, &loop, check);
    QObject::connect(&m_client, &DeviceClient::recordingChanged, &loop, check);
    QObject::connect(&m_client, &DeviceClient::deviceLog, &loop, check);
    QObject::connect(&m_client, &DeviceClient::notice, &loop, check);
    m_wake = check; // wake(), and a request's outcome, given to runCommand() alone
    const auto unwake = qScopeGuard([this] { m_wake = nullptr; });

    QTimer deadline;
    deadline.setSingleShot(true);
    deadline.setTimerType(Qt::PreciseTimer);
    QObject::connect(&deadline, &QTimer::timeout, &loop, [&] {
        outcome = Wait::TimedOut;
        loop.quit();
    });
    if (seconds > 0)
        deadline.start(static_cast<int>(std::ceil(seconds * 1000.0)));

    loop.exec();
    return outcome;
}

void DeviceRunner::wake()
{
    if (m_wake)
        m_wake();
}

int DeviceRunner::reportLoss() const
{
    const QString port = portText(m_options.connect);
    if (!m_lostDetail.trimmed().isEmpty())
        printError(asSentence(m_lostDetail));
    else
        printError(u"The connection to " + port + u" was lost.");
    return ExitNoDevice;
}

int DeviceRunner::connect()
{
    m_started = true;
    m_client.connectDevice(m_options.connect);
    const Wait outcome =
        wait([this] { return m_client.state() == SessionState::Connected; }, m_options.timeoutS);
    switch (outcome) {
    case Wait::Done:
        break;
    case Wait::Lost:
        return reportLoss();
    case Wait::TimedOut:
        printError(u"No HATPIC answered on " + portText(m_options.connect) + u" within " +
                   secondsText(m_options.timeoutS) + u'.');
        return ExitNoDevice;
    }
    if (m_client.deviceInfo().protocol != WireProtocol::Legacy)
        return ExitSuccess;

    // A forced legacy connection has no handshake: only a frame shows that a device is there.
    bool heard = false;
    QObject context;
    QObject::connect(&m_client, &DeviceClient::samplesReady, &context,
                     [&heard](const SampleBatch &batch) { heard = heard || !batch.isEmpty(); });
    switch (wait([&heard] { return heard; }, m_options.timeoutS)) {
    case Wait::Done:
        return ExitSuccess;
    case Wait::Lost:
        // Silent from the start (the session gives up after 2 s without a byte): say what
        // was missing, as the timeout below does, not that a connection was lost.
        if (!heard) {
            printError(u"No legacy HATPIC frame arrived on " + portText(m_options.connect) + u": " +
                       asSentence(m_lostDetail));
            return ExitNoDevice;
        }
        return reportLoss();
    case Wait::TimedOut:
        break;
    }
    printError(u"No legacy HATPIC frame arrived on " + portText(m_options.connect) + u" within " +
               secondsText(m_options.timeoutS) + u'.');
    return ExitNoDevice;
}

int DeviceRunner::runCommand(const Request &request, Outcome *outcome)
{
    // The outcome comes to this call alone; `waiter` ends with it, so a late one (after a
    // timeout) goes nowhere.
    QObject waiter;
    std::optional<Outcome> finished;
    m_client.request(request, {&waiter, [&](const Outcome &o) {
                                   finished = o;
                                   wake();
                               }});
    switch (wait([&] { return finished.has_value(); }, m_options.timeoutS)) {
    case Wait::Done:
        if (outcome)
            *outcome = *finished;
        return ExitSuccess;
    case Wait::Lost:
        // The session fails the command in flight with the loss, just after or before telling
        // the loss: its outcome says what a push had changed by then (the caller tells it).
        if (!finished) {
            QEventLoop loop;
            QTimer::singleShot(kResultAfterLossMs, &loop, &QEventLoop::quit);
            m_wake = [&] { loop.quit(); };
            loop.exec();
            m_wake = nullptr;
        }
        if (outcome && finished)
            *outcome = *finished;
        return reportLoss();
    case Wait::TimedOut:
        break;
    }
    printError(u"The device did not answer within " + secondsText(m_options.timeoutS) + u'.');
    return ExitNoDevice;
}

int DeviceRunner::runFor(double seconds, const std::function<bool()> &stop)
{
    switch (wait(stop, seconds)) {
    case Wait::Done:
    case Wait::TimedOut:
        return ExitSuccess;
    case Wait::Lost:
        break;
    }
    return ExitNoDevice;
}

int DeviceRunner::reportOutcome(const Outcome &outcome)
{
    if (outcome.ok())
        return ExitSuccess;
    printError(asSentence(SessionWording::commandFailure(outcome).trimmed()));
    // Every ending named: a new one does not compile until it has its code.
    return std::visit(Overloaded{
                          [](const outcome::Done &) { return ExitSuccess; },
                          [](const outcome::Refused &) { return ExitRejected; },
                          [](const outcome::Unsupported &) { return ExitRejected; },
                          [](const outcome::TimedOut &) { return ExitNoDevice; },
                          [](const outcome::Cut &) { return ExitNoDevice; },
                          [](const outcome::NotConnected &) { return ExitNoDevice; },
                          [](const outcome::Invalid &) { return ExitBadUsage; },
                          [](const outcome::QueueFull &) { return ExitBadUsage; },
                      },
                      outcome.result);
}

} // namespace hatpic::cli
