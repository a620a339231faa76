// DeviceClient: the session on its own thread, queued calls, cached values, shutdown.
#include "session/deviceclient.h"
#include "sim/simulatorhost.h"
#include "simulatoroptions.h"
#include "telemetry/recordingreader.h"
#include "telemetry/recordingwriter.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPointer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

using namespace hatpic;

namespace {

constexpr int kConnectTimeoutMs = 5000;

ConnectOptions simOptions(ProtocolChoice choice = ProtocolChoice::V2)
{
    return test::simulatorOptions({}, choice);
}

//! Keeps the calling thread busy without processing events, as a frozen GUI would.
void freezeThisThread(int ms)
{
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms) {
        volatile int spin = 0;
        for (int i = 0; i < 10000; ++i)
            spin = spin + i;
    }
}

//! A simulated joystick behind a real pty, running on a thread of its own: its clock and its
//! feedback watchdog keep going whatever the test's main thread does.
class SimulatorThread
{
public:
    explicit SimulatorThread(const SimulatedDevice::Config &config)
    {
        m_thread.start();
        m_context.moveToThread(&m_thread);
        QMetaObject::invokeMethod(
            &m_context,
            [this, config] {
                m_host = new SimulatorHost(config);
                m_error = m_host->start();
                m_path = m_host->slavePath();
            },
            Qt::BlockingQueuedConnection);
    }
    ~SimulatorThread()
    {
        QThread *owner = QThread::currentThread();
        QMetaObject::invokeMethod(
            &m_context,
            [this, owner] {
                delete m_host;
                m_context.moveToThread(owner); // back home before the thread ends
            },
            Qt::BlockingQueuedConnection);
        m_thread.quit();
        m_thread.wait();
    }
    QString error() const { return m_error; }
    QString path() const { return m_path; }

private:
    QThread m_thread;
    QObject m_context;
    SimulatorHost *m_host = nullptr;
    QString m_error;
    QString m_path;
};

} // namespace

class TestDeviceClient : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void connectsOnItsOwnThread();
    void cacheIsUpdatedBeforeSignals();
    void outcomesComeToTheirCaller();
    void frozenMainThreadDoesNotStarveTheLink();
    void frozenMainThreadKeepsTheQueueBounded();
    void destructorClosesRecordingAndJoins();
    void disconnectReportsState();
};

void TestDeviceClient::connectsOnItsOwnThread()
{
    DeviceClient client;
    QThread *sessionThread = nullptr;
    QThread *deliveryThread = nullptr;
    connect(&client, &DeviceClient::samplesReady, this, [&](const SampleBatch &) {
        deliveryThread = QThread::currentThread();
        sessionThread = client.findChild<QThread *>();
    });
    client.connectDevice(simOptions(ProtocolChoice::Auto));
    QTRY_COMPARE_WITH_TIMEOUT(client.state(), SessionState::Connected, kConnectTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(deliveryThread != nullptr, kConnectTimeoutMs);
    QCOMPARE(deliveryThread, QThread::currentThread()); // re-emitted on the owner's thread
    QVERIFY(sessionThread && sessionThread != QThread::currentThread());
    QVERIFY(sessionThread->isRunning());
    QCOMPARE(client.deviceInfo().protocol, WireProtocol::V2);
    QVERIFY(client.deviceInfo().simulated);
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().params.has_value(), kConnectTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(client.stats().frames > 100, kConnectTimeoutMs);
}

void TestDeviceClient::cacheIsUpdatedBeforeSignals()
{
    DeviceClient client;
    int checks = 0;
    connect(&client, &DeviceClient::stateChanged, this, [&](SessionState s, const StateDetail &) {
        QCOMPARE(client.state(), s);
        ++checks;
    });
    connect(&client, &DeviceClient::deviceInfoChanged, this, [&](const DeviceInfo &i) {
        QCOMPARE(client.deviceInfo().deviceId, i.deviceId);
        ++checks;
    });
    connect(&client, &DeviceClient::deviceTuningChanged, this, [&](const DeviceTuning &t) {
        QCOMPARE(client.deviceTuning(), t);
        QVERIFY(client.deviceTuning().params.has_value());
        ++checks;
    });
    connect(&client, &DeviceClient::statsUpdated, this, [&](const LinkStats &s) {
        QCOMPARE(client.stats().frames, s.frames);
        ++checks;
    });
    client.connectDevice(simOptions());
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().params.has_value() && client.stats().frames > 0,
                             kConnectTimeoutMs);
    QVERIFY(checks >= 5);
}

//! Each command's outcome goes to its own caller, once, and to nobody whose context is gone.
void TestDeviceClient::outcomesComeToTheirCaller()
{
    DeviceClient client;
    client.connectDevice(simOptions());
    QTRY_VERIFY_WITH_TIMEOUT(client.deviceTuning().params.has_value(), kConnectTimeoutMs);
    DeviceParams p;
    p.M_adm = 0.02;
    DeviceParams bad;
    bad.N = -1;
    QObject caller;
    QList<Outcome> pushed, read, refused;
    const auto into = [&caller](QList<Outcome> &list) {
        return CommandDone{&caller, [&list](const Outcome &o) { list.append(o); }};
    };
    client.request(request::Push{{p, std::nullopt}}, into(pushed));
    client.request(request::Read{}, into(read));
    client.request(request::Push{{bad, std::nullopt}}, into(refused));
    int late = 0;
    {
        QObject gone; // its command still runs, but nobody hears its outcome
        client.request(request::Read{}, {&gone, [&late](const Outcome &) { ++late; }});
    }
    QTRY_VERIFY_WITH_TIMEOUT(!pushed.isEmpty() && !read.isEmpty() && !refused.isEmpty(),
                             kConnectTimeoutMs);
    QCOMPARE(std::get<outcome::Done>(pushed.first().result).readBack, outcome::ReadBack::Matches);
    QVERIFY(read.first().ok());
    QVERIFY(std::holds_alternative<outcome::Invalid>(refused.first().result));
    QCOMPARE(client.deviceTuning().params.value().M_adm, double(0.02f));
    // A command without a caller runs too; afterwards each list still holds its one outcome.
    client.request(request::Read{});
    QObject last;
    bool lastDone = false;
    client.request(request::Read{}, {&last, [&lastDone](const Outcome &) { lastDone = true; }});
    QTRY_VERIFY_WITH_TIMEOUT(lastDone, kConnectTimeoutMs);
    QCOMPARE(pushed.size() + read.size() + refused.size(), 3);
    QCOMPARE(late, 0);
}

void TestDeviceClient::frozenMainThreadDoesNotStarveTheLink()
{
    // The device must not share a thread with anything the test freezes, so this uses a
    // simulator on its own thread behind a pty rather than the in-process "sim" port (whose
    // clock would stop together with the session thread it runs on).
    SimulatorThread simulator{SimulatedDevice::Config()};
    QVERIFY2(simulator.error().isEmpty(), qPrintable(simulator.error()));
    DeviceClient client;
    QList<Sample> samples;
    connect(&client, &DeviceClient::samplesReady, this,
            [&](const SampleBatch &b) { samples.append(b); });
    ConnectOptions options;
    options.port = simulator.path();
    options.protocol = ProtocolChoice::V2;
    client.connectDevice(options);
    QTRY_VERIFY_WITH_TIMEOUT(samples.size() > 200, kConnectTimeoutMs);
    client.setFeedback(0.05);
    QTRY_VERIFY_WITH_TIMEOUT(qAbs(samples.last().tau_ext - 0.05) < 1e-6, kConnectTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(client.stats().rttLastMs >= 0, kConnectTimeoutMs);
    const quint64 dropsBefore = client.stats().seqDrops;
    const double frozenFrom = samples.last().t_s;
    const qsizetype firstIndex = samples.size();

    freezeThisThread(600); // longer than the device's 200 ms feedback watchdog

    QTRY_VERIFY_WITH_TIMEOUT(!samples.isEmpty() && samples.last().t_s > frozenFrom + 0.8,
                             kConnectTimeoutMs);
    // The samples the device produced while this thread was frozen: the feedback kept
    // coming (no stale flag, τ_ext held), and no telemetry frame was lost.
    double lastT = samples[firstIndex - 1].t_s;
    double longestStep = 0;
    int stale = 0;
    for (qsizetype i = firstIndex; i < samples.size(); ++i) {
        const Sample &s = samples[i];
        longestStep = std::max(longestStep, s.t_s - lastT);
        lastT = s.t_s;
        if (s.flags & v2::kFlagFeedbackStale)
            ++stale;
        QVERIFY(qAbs(s.tau_ext - 0.05) < 1e-6);
    }
    QCOMPARE(stale, 0);
    QVERIFY2(longestStep < 0.0025, qPrintable(QString::number(longestStep)));
    QTRY_VERIFY_WITH_TIMEOUT(client.stats().framesPerSecond > 0, 1000);
    QCOMPARE(client.stats().seqDrops, dropsBefore);
    // PINGs kept going: the round trip stayed that of a live session thread.
    QVERIFY2(client.stats().rttMaxMs < 100, qPrintable(QString::number(client.stats().rttMaxMs)));
}

void TestDeviceClient::frozenMainThreadKeepsTheQueueBounded()
{
    DeviceClient client;
    int batches = 0;
    int statsUpdates = 0;
    connect(&client, &DeviceClient::samplesReady, this, [&](const SampleBatch &) { ++batches; });
    connect(&client, &DeviceClient::statsUpdated, this, [&](const LinkStats &) { ++statsUpdates; });
    client.connectDevice(simOptions());
    QTRY_VERIFY_WITH_TIMEOUT(batches > 5, kConnectTimeoutMs);
    QCOMPARE(client.droppedSampleBatches(), quint64(0));

    // Frozen until the session had to give up on delivering: without a bound it never does,
    // and every batch and statistics update would wait in this thread's queue.
    QElapsedTimer frozen;
    frozen.start();
    while (client.droppedSampleBatches() < 10 && frozen.elapsed() < 30'000)
        freezeThisThread(10);
    QVERIFY2(client.droppedSampleBatches() >= 10, "no batch was dropped while frozen");

    batches = 0;
    statsUpdates = 0;
    QCoreApplication::processEvents(); // everything that waited while frozen
    // A few more may arrive while this runs; far fewer than the seconds frozen would give.
    QVERIFY2(batches <= DeviceClient::kMaxPendingBatches + 10,
             qPrintable(QString::number(batches)));
    QVERIFY2(statsUpdates <= DeviceClient::kMaxPendingStats + 2,
             qPrintable(QString::number(statsUpdates)));
    // Delivery resumes once the thread runs again.
    batches = 0;
    QTRY_VERIFY_WITH_TIMEOUT(batches > 5, kConnectTimeoutMs);
}

void TestDeviceClient::destructorClosesRecordingAndJoins()
{
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("d.csv"));
    QPointer<QThread> thread;
    {
        DeviceClient client;
        thread = client.findChild<QThread *>();
        client.connectDevice(simOptions());
        QTRY_VERIFY_WITH_TIMEOUT(client.stats().frames > 100, kConnectTimeoutMs);
        client.startRecording(csv, QStringLiteral("tst_deviceclient"));
        QTRY_VERIFY_WITH_TIMEOUT(client.recordingStatus().active, kConnectTimeoutMs);
        // Rows reach the disk by the flush timer, without stopping the recording.
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(csv).size() > 10000,
                                 2 * RecordingWriter::kFlushIntervalMs + 500);
        QVERIFY(client.recordingStatus().active);
    } // destroyed while connected and recording
    QVERIFY(thread.isNull());
    QFile json(recordingMetadataPath(csv));
    QVERIFY(json.open(QIODevice::ReadOnly));
    const QJsonObject o = QJsonDocument::fromJson(json.readAll()).object();
    QCOMPARE(o.value(u"closed").toBool(), true);
    QCOMPARE(o.value(u"source").toString(), QStringLiteral("tst_deviceclient"));
    const RecordingReadResult r = readRecording(csv);
    QVERIFY2(r.recording, qPrintable(r.error));
    QVERIFY(r.warnings.isEmpty());
    QCOMPARE(qint64(r.recording->samples.size()), qint64(o.value(u"samples").toInteger()));
}

void TestDeviceClient::disconnectReportsState()
{
    DeviceClient client;
    QSignalSpy states(&client, &DeviceClient::stateChanged);
    client.connectDevice(simOptions());
    QTRY_COMPARE_WITH_TIMEOUT(client.state(), SessionState::Connected, kConnectTimeoutMs);
    client.disconnectDevice();
    QTRY_COMPARE(client.state(), SessionState::Disconnected);
    QCOMPARE(states.last().first().value<SessionState>(), SessionState::Disconnected);
}

QTEST_GUILESS_MAIN(TestDeviceClient)
#include "tst_deviceclient.moc"
