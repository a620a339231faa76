// The link's state tag, identity, banner and status-bar figures.
#include "connection/linkbanner.h"
#include "connection/linkstatswidget.h"
#include "connection/linkstatuswidget.h"

#include <QLabel>
#include <QTest>
#include <QToolButton>

using namespace hatpic;

class TestLinkWidgets : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void stateTag_data();
    void stateTag();
    void identity_data();
    void identity();
    void banner_data();
    void banner();
    void startHintForTheSimulator();
    void stats();
};

void TestLinkWidgets::stateTag_data()
{
    QTest::addColumn<SessionState>("state");
    QTest::addColumn<QString>("text");
    QTest::newRow("disconnected") << SessionState::Disconnected << QStringLiteral("disconnected");
    QTest::newRow("detecting") << SessionState::Detecting << QStringLiteral("detecting…");
    QTest::newRow("connected") << SessionState::Connected << QStringLiteral("connected");
    QTest::newRow("lost") << SessionState::Lost << QStringLiteral("LINK LOST");
}

void TestLinkWidgets::stateTag()
{
    QFETCH(SessionState, state);
    QFETCH(QString, text);
    LinkStatusWidget widget;
    widget.setState(state);
    QCOMPARE(widget.stateText(), text);
}

void TestLinkWidgets::identity_data()
{
    QTest::addColumn<DeviceInfo>("info");
    QTest::addColumn<QStringList>("parts");
    DeviceInfo v2;
    v2.protocolVersion = 2;
    v2.firmware = QStringLiteral("hatpic 2.1");
    v2.deviceId = 0xBEEF;
    v2.port = QStringLiteral("/dev/ttyUSB0");
    v2.baud = 921600;
    QTest::newRow("v2 device") << v2
                               << QStringList{QStringLiteral("protocol v2"),
                                              QStringLiteral("firmware hatpic 2.1"),
                                              QStringLiteral("id 0x0000BEEF"),
                                              QStringLiteral("/dev/ttyUSB0 @ 921600")};
    DeviceInfo legacy;
    legacy.protocol = WireProtocol::Legacy;
    legacy.firmware = QStringLiteral("published firmware (legacy)");
    legacy.port = QStringLiteral("/dev/ttyACM0");
    legacy.baud = 115200;
    QTest::newRow("legacy device")
        << legacy
        << QStringList{QStringLiteral("legacy protocol"), QStringLiteral("/dev/ttyACM0 @ 115200")};
    DeviceInfo sim = v2;
    sim.simulated = true;
    sim.port = QStringLiteral("sim");
    QTest::newRow("simulator") << sim << QStringList{QStringLiteral("Simulated HATPIC")};
}

void TestLinkWidgets::identity()
{
    QFETCH(DeviceInfo, info);
    QFETCH(QStringList, parts);
    LinkStatusWidget widget;
    QCOMPARE(widget.identityText(), QStringLiteral("no device"));
    widget.setDeviceInfo(info);
    for (const QString &part : std::as_const(parts))
        QVERIFY2(widget.identityText().contains(part), qPrintable(widget.identityText()));
    widget.setDeviceInfo(std::nullopt);
    QCOMPARE(widget.identityText(), QStringLiteral("no device"));
}

void TestLinkWidgets::banner_data()
{
    QTest::addColumn<SessionState>("state");
    QTest::addColumn<StateDetail>("detail");
    QTest::addColumn<QString>("contains"); // empty: hidden
    QTest::addColumn<QString>("details");  // the system's text, kept out of the sentence
    const QString ioctl = QStringLiteral("Inappropriate ioctl for device");
    StateDetail cut{state::LinkFailed{ioctl}, QStringLiteral("/dev/ttyUSB0"), false, 921600};
    QTest::newRow("lost: link failed")
        << SessionState::Lost << cut << QStringLiteral("was cut") << ioctl;
    StateDetail silent{state::Silent{2000}, cut.port, false, 921600};
    QTest::newRow("lost: silent") << SessionState::Lost << silent
                                  << QStringLiteral("stopped sending data")
                                  << QStringLiteral("2 s");
    const QString denied = QStringLiteral("Permission denied");
    StateDetail open{state::OpenFailed{denied}, cut.port, false, 921600};
    QTest::newRow("failed to open") << SessionState::Disconnected << open
                                    << QStringLiteral("Could not open /dev/ttyUSB0") << denied;
    StateDetail none;
    // Disconnected by the user (or never connected): how to start (issue 27).
    QTest::newRow("user disconnected")
        << SessionState::Disconnected << none
        << QStringLiteral("Press Connect (Ctrl+K) to open /dev/ttyUSB0") << QString();
    StateDetail connected;
    connected.why = state::ConnectedV2{};
    QTest::newRow("connected") << SessionState::Connected << connected << QString() << QString();
}

void TestLinkWidgets::startHintForTheSimulator()
{
    // Told by the link, not by the name: a simulated source is tried, whatever it is called.
    for (const QString &name : {QStringLiteral("sim"), QStringLiteral("my-knob")})
        QCOMPARE(
            LinkBanner::startHint(name, true),
            QStringLiteral("Not connected. Press Connect (Ctrl+K) to try the simulated knob."));
    const QString serial = LinkBanner::startHint(QStringLiteral("/dev/ttyACM0"), false);
    QVERIFY(serial.contains(u"to open /dev/ttyACM0"));
    QVERIFY(serial.contains(u"simulated knob"));
    QVERIFY(LinkBanner::startHint(QStringLiteral("sim"), false).contains(u"to open sim"));
}

void TestLinkWidgets::banner()
{
    QFETCH(SessionState, state);
    QFETCH(StateDetail, detail);
    QFETCH(QString, contains);
    QFETCH(QString, details);
    QWidget parent;
    auto *banner = new LinkBanner(&parent);
    parent.show();
    StateDetail before;
    before.why = state::Silent{};
    banner->setState(SessionState::Lost, before, QStringLiteral("/dev/x"));
    banner->setState(state, detail, QStringLiteral("/dev/ttyUSB0"));
    QCOMPARE(banner->isVisible(), !contains.isEmpty());
    if (!contains.isEmpty()) {
        QVERIFY2(banner->text().contains(contains), qPrintable(banner->text()));
        QVERIFY(banner->text().contains(u"Reconnecting") == (state == SessionState::Lost));
    }
    if (!details.isEmpty()) {
        // The user's words in the sentence; the system's text only in the details.
        QString systemText;
        if (const auto *failed = detail.as<state::LinkFailed>())
            systemText = failed->error;
        else if (const auto *notOpened = detail.as<state::OpenFailed>())
            systemText = notOpened->error;
        QVERIFY2(systemText.isEmpty() || !banner->text().contains(systemText),
                 qPrintable(banner->text()));
        QVERIFY2(banner->detailsText().contains(details), qPrintable(banner->detailsText()));
        auto *button = banner->findChild<QToolButton *>(QStringLiteral("linkBannerDetailsButton"));
        auto *label = banner->findChild<QLabel *>(QStringLiteral("linkBannerDetails"));
        QVERIFY(button && label);
        QVERIFY(button->isVisible());
        QVERIFY(!label->isVisible());
        button->click();
        QVERIFY(label->isVisible());
    }
    // Reconnecting keeps the "lost" banner up.
    if (state == SessionState::Lost) {
        banner->setState(SessionState::Opening, {}, {});
        QVERIFY(banner->isVisible());
    }
}

void TestLinkWidgets::stats()
{
    LinkStatsWidget widget;
    QCOMPARE(widget.text(), QStringLiteral("no link"));
    LinkStats stats;
    stats.framesPerSecond = 998.6;
    stats.seqDrops = 3;
    stats.decoderDrops[static_cast<int>(v2::DropReason::Crc)] = 2;
    stats.legacyMalformed = 1;
    stats.rttLastMs = 0.5;
    stats.rttMedianMs = 0.25;
    stats.rttMaxMs = 2;
    widget.setStats(stats);
    QCOMPARE(
        widget.text(),
        QStringLiteral("999 frames/s · drops 3 · decoder errors 3 · RTT 0.50 ms (median 0.25)"));
    QVERIFY(widget.toolTip().contains(v2::dropReasonName(v2::DropReason::Crc)));
    stats.rttLastMs = -1;
    widget.setStats(stats);
    QVERIFY(widget.text().endsWith(QStringLiteral("RTT —")));
}

QTEST_MAIN(TestLinkWidgets)
#include "tst_linkwidgets.moc"
