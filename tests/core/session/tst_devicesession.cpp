// DeviceSession driven directly on the test thread: finding the device. Both protocols
// detected (auto and forced) on the in-process simulator ("sim") and over real pseudo-terminals
// (openpty + QSerialPort), the failed detection's detail, the HELLO without 'i', the rates
// detection listens and asks at, a port that does not open, the caller's link, a stalled port.
// The commands: tst_devicesessioncommands; samples, statistics, recording and reconnecting:
// tst_devicesessionstream.
#include "link/seriallink.h"
#include "protocol/v2codec.h"
#include "session/devicesession.h"
#include "sessionharness.h"
#include "sim/simlink.h"
#include "sim/simulateddevice.h"
#include "sim/simulatorhost.h"
#include "simulatoroptions.h"

#include <QSignalSpy>
#include <QSocketNotifier>
#include <QTest>

#include <fcntl.h>
#include <memory>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

//! The master side of a pseudo-terminal that the test plays the device on.
class PtyPeer
{
public:
    PtyPeer()
    {
        char name[256] = {};
        int slave = -1;
        if (::openpty(&m_master, &slave, name, nullptr, nullptr) == 0) {
            ::close(slave);
            ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
            m_path = QString::fromLocal8Bit(name);
            m_notifier = std::make_unique<QSocketNotifier>(m_master, QSocketNotifier::Read);
            QObject::connect(m_notifier.get(), &QSocketNotifier::activated, [this] {
                char buf[4096];
                const ssize_t n = ::read(m_master, buf, sizeof buf);
                if (n > 0)
                    m_received.append(buf, n);
            });
        }
    }
    ~PtyPeer()
    {
        m_notifier.reset();
        if (m_master >= 0)
            ::close(m_master);
    }
    bool isValid() const { return m_master >= 0; }
    QString path() const { return m_path; }
    QByteArray received() const { return m_received; }
    //! Baud rate the client side has set (a pty's two ends share one termios) [bit/s].
    speed_t baud() const
    {
        termios t{};
        return ::tcgetattr(m_master, &t) == 0 ? ::cfgetospeed(&t) : B0;
    }

private:
    int m_master = -1;
    QString m_path;
    QByteArray m_received;
    std::unique_ptr<QSocketNotifier> m_notifier;
};

} // namespace

class TestDeviceSession : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void detectsProtocol_data();
    void detectsProtocol();
    void detectionFailsOnSilentPty();
    void helloOnPtyHasNoLetterI();
    void autoDetectionListensAtLegacyRateThenAsksAtV2Rate();
    void detectsOverPty_data();
    void detectsOverPty();
    void openFailureNamesThePort();
    void theLinkIsTheCallers();
    void stalledPortKeepsWriteBufferBounded();
};

void TestDeviceSession::detectsProtocol_data()
{
    QTest::addColumn<int>("deviceProtocol");
    QTest::addColumn<int>("choice");
    QTest::newRow("auto finds v2") << int(WireProtocol::V2) << int(ProtocolChoice::Auto);
    QTest::newRow("auto finds legacy") << int(WireProtocol::Legacy) << int(ProtocolChoice::Auto);
    QTest::newRow("forced v2") << int(WireProtocol::V2) << int(ProtocolChoice::V2);
    QTest::newRow("forced legacy") << int(WireProtocol::Legacy) << int(ProtocolChoice::Legacy);
    // A forced protocol makes the built-in simulator speak it, whatever its config says: the
    // tuner's and hatpicctl's "--port sim --protocol legacy" leave the config at v2.
    QTest::newRow("forced legacy, simulator configured v2")
        << int(WireProtocol::V2) << int(ProtocolChoice::Legacy);
}

void TestDeviceSession::detectsProtocol()
{
    QFETCH(int, deviceProtocol);
    QFETCH(int, choice);
    Harness h;
    QSignalSpy info(&h.session, &DeviceSession::deviceInfoChanged);
    h.session.connectDevice(simOptions(WireProtocol(deviceProtocol), ProtocolChoice(choice)));
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    QCOMPARE(info.count(), 1);
    const DeviceInfo di = info.first().first().value<DeviceInfo>();
    if (ProtocolChoice(choice) == ProtocolChoice::Legacy)
        deviceProtocol = int(WireProtocol::Legacy);
    QCOMPARE(int(di.protocol), deviceProtocol);
    QVERIFY(di.simulated);
    QCOMPARE(di.port, QStringLiteral("sim"));
    if (WireProtocol(deviceProtocol) == WireProtocol::V2) {
        QCOMPARE(di.protocolVersion, quint8(2));
        QCOMPARE(di.deviceId, SimulatedDevice::Config().deviceId);
        QVERIFY(di.canSetParams());
        QTRY_VERIFY_WITH_TIMEOUT(!h.params.isEmpty(), kCommandWaitMs); // GET_PARAMS at connect
        QCOMPARE(h.params.first(), asFloat(DeviceParams()));
    } else {
        QCOMPARE(di.protocolVersion, quint8(0));
        QVERIFY(!di.canSetParams());
        QVERIFY(h.params.isEmpty());
    }
    // Opening → Detecting → Connected, in that order.
    QVERIFY(h.states.size() >= 3);
    QCOMPARE(h.states[0].first, SessionState::Opening);
    QCOMPARE(h.states[1].first, SessionState::Detecting);
    QCOMPARE(h.states.last().first, SessionState::Connected);
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() >= 3, kConnectTimeoutMs);
    h.session.disconnectDevice();
    QCOMPARE(h.session.state(), SessionState::Disconnected);
}

void TestDeviceSession::detectionFailsOnSilentPty()
{
    PtyPeer peer;
    QVERIFY(peer.isValid());
    Harness h;
    ConnectOptions o;
    o.port = peer.path();
    o.baud = 115200;
    h.session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Disconnected, kConnectTimeoutMs);
    QVERIFY(h.sawState(SessionState::Detecting));
    const StateDetail error = h.detailOf(SessionState::Disconnected);
    QCOMPARE(error.port, peer.path());
    QCOMPARE(error.baud, 115200);
    const auto *noAnswer = error.as<state::NoAnswer>();
    QVERIFY(noAnswer);
    QCOMPARE(noAnswer->listenBaud, 0); // the baud was given: no second rate
    QCOMPARE(noAnswer->legacyFrames, 0);
    QCOMPARE(noAnswer->legacyFramesNeeded, ProtocolDetector::kLegacyFramesNeeded);
    QCOMPARE(noAnswer->listenMs, ProtocolDetector::kListenMs);
    QCOMPARE(noAnswer->helloWaitMs, ProtocolDetector::kHelloWaitMs);
}

void TestDeviceSession::helloOnPtyHasNoLetterI()
{
    // The HELLO sent during detection must not contain 'i', whatever seq the session is at.
    PtyPeer peer;
    QVERIFY(peer.isValid());
    Harness h;
    ConnectOptions o;
    o.port = peer.path();
    for (int round = 0; round < 2; ++round) {
        h.session.connectDevice(o);
        QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Disconnected, kConnectTimeoutMs);
    }
    const QByteArray sent = peer.received();
    QVERIFY(!sent.isEmpty());
    QVERIFY(!sent.contains('i'));
    v2::FrameDecoder decoder(v2::Direction::FromHost);
    QList<v2::Frame> frames;
    decoder.feed(sent, frames);
    // Each detection sends its HELLO kHelloSends times (led by a delimiter, issue 10 #6).
    QCOMPARE(frames.size(), 2 * ProtocolDetector::kHelloSends);
    for (const v2::Frame &f : frames)
        QVERIFY(std::holds_alternative<v2::Hello>(f.message));
}

void TestDeviceSession::autoDetectionListensAtLegacyRateThenAsksAtV2Rate()
{
    // With no baud given, a published-firmware device (115200) and a v2 device (921600) must
    // both be found: listen at 115200, then switch to 921600 before sending HELLO.
    PtyPeer peer;
    QVERIFY(peer.isValid());
    Harness h;
    QList<QPair<StateDetail, speed_t>> seen;
    QObject::connect(&h.session, &DeviceSession::stateChanged,
                     [&](SessionState s, const StateDetail &detail) {
                         if (s == SessionState::Detecting)
                             seen.append({detail, peer.baud()});
                     });
    ConnectOptions o;
    o.port = peer.path();
    h.session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Disconnected, kConnectTimeoutMs);
    QCOMPARE(seen.size(), 2);
    QVERIFY(seen[0].first.is<state::Listening>());
    QCOMPARE(seen[0].second, speed_t(B115200));
    QVERIFY(seen[1].first.is<state::SendingHello>());
    QCOMPARE(seen[1].second, speed_t(B921600));
    const StateDetail failure = h.detailOf(SessionState::Disconnected);
    QVERIFY(failure.is<state::NoAnswer>());
    QCOMPARE(failure.as<state::NoAnswer>()->listenBaud, 115200);
    QCOMPARE(failure.baud, 921600);
}

void TestDeviceSession::detectsOverPty_data()
{
    QTest::addColumn<int>("protocol");
    QTest::newRow("v2") << int(WireProtocol::V2);
    QTest::newRow("legacy") << int(WireProtocol::Legacy);
}

void TestDeviceSession::detectsOverPty()
{
    QFETCH(int, protocol);
    SimulatedDevice::Config config;
    config.protocol = WireProtocol(protocol);
    SimulatorHost host(config);
    const QString error = host.start();
    QVERIFY2(error.isEmpty(), qPrintable(error));
    Harness h;
    ConnectOptions o;
    o.port = host.slavePath();
    o.baud = config.protocol == WireProtocol::Legacy ? 115200 : 921600;
    h.session.connectDevice(o);
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    QCOMPARE(int(h.session.deviceInfo().protocol), protocol);
    QVERIFY(!h.session.deviceInfo().simulated);
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() >= 3, kConnectTimeoutMs);
    if (config.protocol == WireProtocol::V2) {
        h.session.setFeedback(0.02);
        QTRY_VERIFY_WITH_TIMEOUT(qAbs(h.samples.last().tau_ext - 0.02) < 1e-6, kCommandWaitMs);
    }
    h.session.disconnectDevice();
}

void TestDeviceSession::openFailureNamesThePort()
{
    Harness h;
    ConnectOptions o;
    o.port = QStringLiteral("/dev/hatpic-does-not-exist");
    h.session.connectDevice(o);
    QCOMPARE(h.session.state(), SessionState::Disconnected);
    const StateDetail error = h.detailOf(SessionState::Disconnected);
    QCOMPARE(error.port, o.port);
    QVERIFY(error.is<state::OpenFailed>());
    QVERIFY(!error.as<state::OpenFailed>()->error.isEmpty());
    QVERIFY(h.sawState(SessionState::Opening));
}

// The session reads nothing into the port's name: "sim" without a link is a serial port that
// does not exist, and whether the device is simulated is what its link says.
void TestDeviceSession::theLinkIsTheCallers()
{
    {
        Harness h;
        ConnectOptions o;
        o.port = QString::fromUtf16(kSimPortName);
        h.session.connectDevice(o);
        QCOMPARE(h.session.state(), SessionState::Disconnected);
        const StateDetail error = h.detailOf(SessionState::Disconnected);
        QVERIFY(error.is<state::OpenFailed>());
        QVERIFY(!error.simulated);
    }
    // A link of the caller's own that says it is hardware: a simulator's bytes, not its name.
    struct Hardware : LinkSource
    {
        ByteLink *makeLink(qint32, QObject *parent) override { return new SimLink({}, parent); }
        bool simulated() const override { return false; }
    };
    for (const bool simulated : {false, true}) {
        Harness h;
        ConnectOptions o = test::simulatorOptions();
        if (!simulated)
            o.link = std::make_shared<Hardware>();
        o.port = u"the caller's link"_s;
        h.session.connectDevice(o);
        QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
        QCOMPARE(h.session.deviceInfo().simulated, simulated);
        QCOMPARE(h.detailOf(SessionState::Connected).simulated, simulated);
        QCOMPARE(h.detailOf(SessionState::Connected).port, o.port);
        QTRY_VERIFY_WITH_TIMEOUT(!h.samples.isEmpty(), kConnectTimeoutMs);
    }
}

void TestDeviceSession::stalledPortKeepsWriteBufferBounded()
{
    // A port that takes nothing (here: the peer never reads and no event loop runs to hand
    // QSerialPort's buffer to the kernel) must not make the host's buffer grow.
    PtyPeer peer;
    QVERIFY(peer.isValid());
    SerialLink link(peer.path(), 921600);
    QVERIFY2(link.open(), qPrintable(link.errorString()));
    const QByteArray frame = v2::encodeFrame(0, v2::SetFeedback{0.1f});
    const int writes = 100'000;
    for (int i = 0; i < writes; ++i)
        link.write(frame);
    QVERIFY2(link.bytesToWrite() <= SerialLink::kMaxPendingWriteBytes,
             qPrintable(QString::number(link.bytesToWrite())));
    QVERIFY(link.droppedWrites() > 0);
}

QTEST_GUILESS_MAIN(TestDeviceSession)
#include "tst_devicesession.moc"
