#include "deviceclient.h"

#include "session/devicesession.h"

#include "realtime/realtime.h"

#include <QThread>

#include <limits>

namespace hatpic {

DeviceClient::DeviceClient(QObject *parent) : QObject(parent), m_thread(new QThread(this))
{
    registerSessionMetaTypes();
    m_thread->setObjectName(QStringLiteral("hatpic-session"));
    m_session = new DeviceSession; // no parent: it moves to the session thread
    m_session->moveToThread(m_thread);
    connect(m_thread, &QThread::finished, m_session, &QObject::deleteLater);

    // Every connection below crosses threads, so it is queued: the slot runs on this
    // object's thread with a copy of the values, and the cache is updated before re-emitting.
    connect(m_session, &DeviceSession::stateChanged, this,
            [this](SessionState state, const StateDetail &detail) {
                m_state = state;
                Q_EMIT stateChanged(state, detail);
            });
    connect(m_session, &DeviceSession::deviceInfoChanged, this, [this](const DeviceInfo &info) {
        m_info = info;
        Q_EMIT deviceInfoChanged(info);
    });
    const SamplePipeline *samples = &m_session->samples();
    connect(samples, &SamplePipeline::deviceTuningChanged, this,
            [this](const DeviceTuning &tuning) {
                m_tuning = tuning;
                Q_EMIT deviceTuningChanged(tuning);
            });
    // The streams below are forwarded from the session thread (direct connections) and
    // posted here only while few of their kind wait, so a frozen thread's queue stays bounded.
    connect(
        samples, &SamplePipeline::samplesReady, this,
        [this](const SampleBatch &batch) {
            if (!post(m_pendingBatches, kMaxPendingBatches,
                      [this, batch] { Q_EMIT samplesReady(batch); }))
                ++m_droppedBatches;
        },
        Qt::DirectConnection);
    connect(m_session, &DeviceSession::notice, this, &DeviceClient::notice);
    connect(
        m_session, &DeviceSession::statsUpdated, this,
        [this](const LinkStats &stats) {
            post(m_pendingStats, kMaxPendingStats, [this, stats] {
                m_stats = stats;
                Q_EMIT statsUpdated(stats);
            });
        },
        Qt::DirectConnection);
    connect(
        samples, &SamplePipeline::recordingChanged, this,
        [this](const RecordingStatus &status) {
            auto deliver = [this, status] {
                m_recording = status;
                Q_EMIT recordingChanged(status);
            };
            // Progress of a running recording may be skipped; a start, stop, error or a wait
            // for the device never (the next progress, within 0.5 s, says it resumed).
            const bool progress = status.active && status.error.isEmpty() && !status.waiting;
            post(m_pendingRecording, progress ? kMaxPendingStats : std::numeric_limits<int>::max(),
                 deliver);
        },
        Qt::DirectConnection);
    connect(
        m_session, &DeviceSession::deviceLog, this,
        [this](const QString &line) {
            post(m_pendingLogLines, kMaxPendingLogLines, [this, line] { Q_EMIT deviceLog(line); });
        },
        Qt::DirectConnection);
    // The robot path's thread: real-time where the system allows it (else as before).
    connect(
        m_thread, &QThread::started, this,
        [this] {
            const std::string problem = realtime::makeThreadRealtime();
            const std::lock_guard lock(m_realtimeMutex);
            m_realtimeProblem = problem;
        },
        Qt::DirectConnection);
    m_thread->start(QThread::HighestPriority);
}

std::string DeviceClient::realtimeProblem() const
{
    const std::lock_guard lock(m_realtimeMutex);
    return m_realtimeProblem;
}

DeviceClient::~DeviceClient()
{
    // Close the port and the recording on the session thread, then let the thread end;
    // the session deletes itself there when the thread finishes.
    onSession<&DeviceSession::shutdown, Qt::BlockingQueuedConnection>();
    m_thread->quit();
    m_thread->wait();
}

template<typename Deliver>
bool DeviceClient::post(std::atomic<int> &pending, int cap, Deliver deliver)
{
    if (pending.load() >= cap)
        return false;
    ++pending;
    QMetaObject::invokeMethod(
        this,
        [&pending, deliver = std::move(deliver)] {
            --pending;
            deliver();
        },
        Qt::QueuedConnection);
    return true;
}

template<auto Method, Qt::ConnectionType Type, typename... Args>
void DeviceClient::onSession(Args &&...args)
{
    // The init-capture decays each argument: the functor owns a copy of every value.
    QMetaObject::invokeMethod(
        m_session, [s = m_session, ... args = std::forward<Args>(args)] { (s->*Method)(args...); },
        Type);
}

void DeviceClient::request(const Request &request, CommandDone then)
{
    OutcomeHandler handler;
    if (then.done) {
        // Called on the session thread; the outcome crosses back to this one by copy.
        handler = [this, then = std::move(then)](const Outcome &outcome) {
            QMetaObject::invokeMethod(
                this,
                [then, outcome] {
                    if (then.context)
                        then.done(outcome);
                },
                Qt::QueuedConnection);
        };
    }
    onSession<&DeviceSession::request>(request, std::move(handler));
}

void DeviceClient::connectDevice(const ConnectOptions &options)
{
    m_tuning = {};
    m_options = options;
    onSession<&DeviceSession::connectDevice>(options);
}

void DeviceClient::disconnectDevice()
{
    onSession<&DeviceSession::disconnectDevice>();
}

void DeviceClient::addSampleListener(SampleListener *listener)
{
    m_session->sampleListeners().add(listener);
}

void DeviceClient::removeSampleListener(SampleListener *listener)
{
    m_session->sampleListeners().remove(listener);
}

void DeviceClient::setFeedback(double tauExt)
{
    {
        const std::lock_guard lock(m_feedbackMutex);
        m_feedback[0] = tauExt;
    }
    postFeedback();
}

void DeviceClient::setFeedback(const AxisTorques &tauExt)
{
    {
        const std::lock_guard lock(m_feedbackMutex);
        m_feedback = tauExt;
    }
    postFeedback();
}

void DeviceClient::postFeedback()
{
    // At most one call waits on the session thread, and it takes the newest value: a flood of
    // wrenches never makes its queue grow.
    if (m_feedbackPosted.exchange(true))
        return;
    QMetaObject::invokeMethod(m_session, [this, s = m_session] {
        m_feedbackPosted.store(false);
        AxisTorques newest;
        {
            const std::lock_guard lock(m_feedbackMutex);
            newest = m_feedback;
        }
        s->setFeedback(newest);
    });
}

void DeviceClient::setHostParams(const HostParams &host)
{
    onSession<&DeviceSession::setHostParams>(host);
}

void DeviceClient::resetReference()
{
    onSession<&DeviceSession::resetReference>();
}

void DeviceClient::startRecording(const QString &csvPath, const QString &source)
{
    startRecording(csvPath, RecordingPlan{}, source);
}

void DeviceClient::startRecording(const QString &csvPath, const RecordingPlan &plan,
                                  const QString &source)
{
    onSession<&DeviceSession::startRecording>(csvPath, source, plan);
}

void DeviceClient::stopRecording()
{
    onSession<&DeviceSession::stopRecording>();
}

} // namespace hatpic
