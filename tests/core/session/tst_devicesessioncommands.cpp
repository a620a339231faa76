// DeviceSession driven directly on the test thread, against the in-process simulator ("sim"):
// its commands. Push and read-back, ZERO, SAVE, SET_STREAM, host-side validation, the device's
// rejection leaving the parameters unchanged, lost commands retried and timing out, legacy
// commands unsupported, commands while disconnected, feedback and its watchdog.
#include "session/devicesession.h"
#include "session/sessionwording.h"
#include "sessionharness.h"
#include "sim/simlink.h"
#include "sim/simulateddevice.h"
#include "simulatoroptions.h"

#include <QTest>

#include <cmath>

using namespace hatpic;
using namespace hatpic::test;
using namespace Qt::StringLiterals;

namespace {

//! A failed outcome in words, for a test's failure message.
QString statusText(const Outcome &o)
{
    return SessionWording::commandFailure(o);
}

} // namespace

class TestDeviceSessionCommands : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void pushParamsReadsBack();
    void invalidParamsAreRefusedOnTheHost();
    void rejectionLeavesDeviceParamsUnchanged();
    void lostCommandIsRetried_data();
    void lostCommandIsRetried();
    void legacyCommandsAreUnsupported_data();
    void legacyCommandsAreUnsupported();
    void commandsWhenDisconnected();
    void feedbackReachesTheDevice();
    void feedbackWatchdog();
};

void TestDeviceSessionCommands::pushParamsReadsBack()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2));
    QTRY_VERIFY_WITH_TIMEOUT(!h.params.isEmpty(), kConnectTimeoutMs);
    DeviceParams p;
    p.K_max = 0.6;
    p.K_min = 0.2;
    p.N = 0.12;
    h.send(7, request::Push{{p, std::nullopt}});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(7), kCommandWaitMs);
    const Outcome r = h.results.at(7);
    QVERIFY2(r.ok(), qPrintable(statusText(r)));
    QCOMPARE(std::get<outcome::Done>(r.result).readBack, outcome::ReadBack::Matches);
    QCOMPARE(h.params.last().K_max, double(0.6f));
    QCOMPARE(h.params.last().K_min, double(0.2f));
    QCOMPARE(h.params.last().N, double(0.12f));
    QCOMPARE(test::simLinkOf(h.session)->device()->params().K_max, double(0.6f));

    // ZERO makes the current angle θ0; the read-back shows it.
    h.send(8, request::Zero{});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(8), kCommandWaitMs);
    QVERIFY2(h.results.at(8).ok(), qPrintable(statusText(h.results.at(8))));
    QCOMPARE(h.params.last().theta0, test::simLinkOf(h.session)->device()->params().theta0);

    h.send(9, request::Save{});
    h.send(10, request::Stream{500});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(10), kCommandWaitMs);
    QVERIFY(h.results.at(9).ok());
    QVERIFY(h.results.at(10).ok());
    QTRY_COMPARE_WITH_TIMEOUT(test::simLinkOf(h.session)->device()->streamRate(), quint16(500),
                              kCommandWaitMs);
}

void TestDeviceSessionCommands::invalidParamsAreRefusedOnTheHost()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(!h.params.isEmpty(), kConnectTimeoutMs);
    DeviceParams p;
    p.K_min = 0.9; // > K_max
    p.Q_dz = 0.5;  // > N
    h.send(1, request::Push{{p, std::nullopt}});
    QTRY_VERIFY(h.results.contains(1));
    const Outcome r = h.results.at(1);
    const auto *invalid = std::get_if<outcome::Invalid>(&r.result);
    QVERIFY2(invalid, qPrintable(statusText(r)));
    const QString problems = invalid->problems.join(u"; "_s);
    QVERIFY2(problems.contains(u"K_min") && problems.contains(u"Q_dz"), qPrintable(problems));
    QCOMPARE(test::simLinkOf(h.session)->device()->params(), asFloat(DeviceParams()));
}

void TestDeviceSessionCommands::rejectionLeavesDeviceParamsUnchanged()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(!h.params.isEmpty(), kConnectTimeoutMs);
    DeviceParams good;
    good.K_max = 0.5;
    h.send(1, request::Push{{good, std::nullopt}});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(1), kCommandWaitMs);
    QVERIFY(h.results.at(1).ok());

    h.session.setValidateBeforeSending(false);
    DeviceParams bad = good;
    bad.K_min = 0.1;
    bad.K_max = 60; // above 50: the device names field 3
    h.send(2, request::Push{{bad, std::nullopt}});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(2), kCommandWaitMs);
    const Outcome r = h.results.at(2);
    const auto *refused = std::get_if<outcome::Refused>(&r.result);
    QVERIFY2(refused, qPrintable(statusText(r)));
    QCOMPARE(refused->status, v2::AckStatus::OutOfRange);
    QCOMPARE(refused->field, 3);
    QCOMPARE(refused->step, CommandKind::SetParams);
    QVERIFY(!refused->applied.params); // its first step: nothing was applied

    h.send(3, request::Read{});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(3), kCommandWaitMs);
    QCOMPARE(h.params.last().K_max, double(0.5f));
    QCOMPARE(h.params.last().K_min, double(float(DeviceParams().K_min)));
}

void TestDeviceSessionCommands::lostCommandIsRetried_data()
{
    QTest::addColumn<int>("dropped");
    QTest::addColumn<bool>("succeeds");
    QTest::newRow("one copy lost") << 1 << true;
    QTest::newRow("three copies lost") << 3 << true;
    QTest::newRow("all four copies lost") << 4 << false;
}

void TestDeviceSessionCommands::lostCommandIsRetried()
{
    QFETCH(int, dropped);
    QFETCH(bool, succeeds);
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(!h.params.isEmpty(), kConnectTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(!h.samples.isEmpty(), kConnectTimeoutMs); // connect sequence done
    const quint64 retriesBefore = h.session.stats().retries;
    test::simLinkOf(h.session)->dropHostFrames(dropped, quint8(v2::MessageType::SetParams));
    DeviceParams p;
    p.K_max = 0.7;
    h.send(1, request::Push{{p, std::nullopt}});
    QTRY_VERIFY_WITH_TIMEOUT(h.results.contains(1), kCommandWaitMs);
    const Outcome r = h.results.at(1);
    QCOMPARE(test::simLinkOf(h.session)->droppedHostFrames(), dropped);
    QCOMPARE(h.session.stats().retries - retriesBefore, quint64(std::min(dropped, 3)));
    if (succeeds) {
        QVERIFY2(r.ok(), qPrintable(statusText(r)));
        QCOMPARE(test::simLinkOf(h.session)->device()->params().K_max, double(0.7f));
    } else {
        const auto *timedOut = std::get_if<outcome::TimedOut>(&r.result);
        QVERIFY2(timedOut, qPrintable(statusText(r)));
        QCOMPARE(timedOut->step, CommandKind::SetParams);
        QCOMPARE(timedOut->attempts, CommandQueue::kCommandRetries + 1);
        QCOMPARE(timedOut->intervalMs, CommandQueue::kCommandTimeoutMs);
        QCOMPARE(test::simLinkOf(h.session)->device()->params().K_max,
                 double(float(DeviceParams().K_max)));
    }
}

void TestDeviceSessionCommands::legacyCommandsAreUnsupported_data()
{
    QTest::addColumn<QString>("command");
    QTest::newRow("push") << QStringLiteral("push");
    QTest::newRow("read") << QStringLiteral("read");
    QTest::newRow("zero") << QStringLiteral("zero");
    QTest::newRow("save") << QStringLiteral("save");
    QTest::newRow("stream") << QStringLiteral("stream");
}

void TestDeviceSessionCommands::legacyCommandsAreUnsupported()
{
    QFETCH(QString, command);
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::Legacy, ProtocolChoice::Legacy));
    QTRY_COMPARE_WITH_TIMEOUT(h.session.state(), SessionState::Connected, kConnectTimeoutMs);
    if (command == u"push")
        h.send(1, request::Push{{DeviceParams(), std::nullopt}});
    else if (command == u"read")
        h.send(1, request::Read{});
    else if (command == u"zero")
        h.send(1, request::Zero{});
    else if (command == u"save")
        h.send(1, request::Save{});
    else
        h.send(1, request::Stream{100});
    QTRY_VERIFY(h.results.contains(1));
    const Outcome refused = h.results.at(1);
    const auto *unsupported = std::get_if<outcome::Unsupported>(&refused.result);
    QVERIFY(unsupported);
    QCOMPARE(unsupported->why, command == u"stream" ? outcome::Unsupported::Why::FixedRate
                                                    : outcome::Unsupported::Why::NoParameters);
    // Host parameters still apply.
    HostParams host;
    host.v_max = 3;
    host.ref_deadzone = false;
    h.session.setHostParams(host);
    const qsizetype before = h.samples.size();
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > before, kConnectTimeoutMs);
    const Sample &s = h.samples.last();
    QCOMPARE(s.v_ref, referenceVelocity(host, DeviceParams(), s.theta));
}

void TestDeviceSessionCommands::commandsWhenDisconnected()
{
    Harness h;
    h.send(1, request::Read{});
    h.send(2, request::Push{{DeviceParams(), std::nullopt}});
    QVERIFY(std::holds_alternative<outcome::NotConnected>(h.results.at(1).result));
    QVERIFY(std::holds_alternative<outcome::NotConnected>(h.results.at(2).result));
}

void TestDeviceSessionCommands::feedbackReachesTheDevice()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(!h.samples.isEmpty(), kConnectTimeoutMs);
    h.session.setFeedback(0.1);
    QTRY_VERIFY_WITH_TIMEOUT(!h.samples.isEmpty() && qAbs(h.samples.last().tau_ext - 0.1) < 1e-6,
                             kCommandWaitMs);
    QCOMPARE(h.samples.last().flags & v2::kFlagFeedbackStale, 0);
}

void TestDeviceSessionCommands::feedbackWatchdog()
{
    Harness h;
    h.session.connectDevice(simOptions(WireProtocol::V2, ProtocolChoice::V2));
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.size() > 300, kConnectTimeoutMs);
    h.session.setFeedback(0.05);
    QTRY_VERIFY_WITH_TIMEOUT(qAbs(h.samples.last().tau_ext - 0.05) < 1e-6, kCommandWaitMs);
    // With the stream running the device never went stale.
    for (const Sample &s : std::as_const(h.samples))
        QCOMPARE(s.flags & v2::kFlagFeedbackStale, 0);

    h.session.setFeedbackPaused(true);
    QTRY_VERIFY_WITH_TIMEOUT(h.samples.last().flags & v2::kFlagFeedbackStale, kCommandWaitMs);
    QCOMPARE(h.samples.last().tau_ext, 0.0); // a stale device drops τ_ext
    h.session.setFeedbackPaused(false);
    QTRY_VERIFY_WITH_TIMEOUT(!(h.samples.last().flags & v2::kFlagFeedbackStale), kCommandWaitMs);
}

QTEST_GUILESS_MAIN(TestDeviceSessionCommands)
#include "tst_devicesessioncommands.moc"
