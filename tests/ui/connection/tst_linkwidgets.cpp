// The link's state tag, identity, banner and status-bar figures.
#include "connection/linkbanner.h"
#include "connection/linkstatswidget.h"
#include "connection/linkstatuswidget.h"

#include <QTest>

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
    QTest::addColumn<QString>("detail");
    QTest::addColumn<QString>("contains"); // empty: hidden
    QTest::newRow("lost") << SessionState::Lost << QStringLiteral("Lost /dev/ttyUSB0: gone")
                          << QStringLiteral("Reconnecting");
    QTest::newRow("failed to open")
        << SessionState::Disconnected << QStringLiteral("Cannot open /dev/ttyUSB0")
        << QStringLiteral("Cannot open /dev/ttyUSB0");
    QTest::newRow("user disconnected") << SessionState::Disconnected << QString() << QString();
    QTest::newRow("connected") << SessionState::Connected << QStringLiteral("HATPIC v2")
                               << QString();
}

void TestLinkWidgets::banner()
{
    QFETCH(SessionState, state);
    QFETCH(QString, detail);
    QFETCH(QString, contains);
    QWidget parent;
    auto *banner = new LinkBanner(&parent);
    parent.show();
    banner->setState(SessionState::Lost, QStringLiteral("before"), QStringLiteral("/dev/x"));
    banner->setState(state, detail, QStringLiteral("/dev/ttyUSB0"));
    QCOMPARE(banner->isVisible(), !contains.isEmpty());
    if (!contains.isEmpty())
        QVERIFY2(banner->text().contains(contains), qPrintable(banner->text()));
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
