// ConnectionBar: the sources added (the simulator) first, options from the controls with the
// chosen source's link, typed paths and names, state.
#include "connection/connectionbar.h"
#include "sim/simulatedjoystick.h"

#include <QComboBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

using namespace hatpic;

namespace {

// A bar as the window makes it: the simulated joystick added as its first source, "sim".
struct Bar
{
    std::shared_ptr<SimulatedJoystick> simulator = std::make_shared<SimulatedJoystick>();
    ConnectionBar bar;
    Bar() { bar.addSource(QStringLiteral("Simulated HATPIC"), QStringLiteral("sim"), simulator); }
};

} // namespace

class TestConnectionBar : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void simulatorIsFirst();
    void sourcesComeBeforeThePorts();
    void optionsFromControls_data();
    void optionsFromControls();
    void typedPathIsUsed();
    void buttonFollowsState_data();
    void buttonFollowsState();
    void refreshKeepsChoice();
};

void TestConnectionBar::simulatorIsFirst()
{
    Bar b;
    ConnectionBar &bar = b.bar;
    QVERIFY(!bar.listedPorts().isEmpty());
    QCOMPARE(bar.listedPorts().constFirst(), QStringLiteral("sim"));
    QCOMPARE(bar.portBox()->itemText(0), QStringLiteral("Simulated HATPIC"));
    QCOMPARE(bar.port(), QStringLiteral("sim"));
    QCOMPARE(bar.baud(), 0);
    QCOMPARE(bar.protocol(), ProtocolChoice::Auto);
    QCOMPARE(bar.options().link, std::static_pointer_cast<LinkSource>(b.simulator));
}

void TestConnectionBar::sourcesComeBeforeThePorts()
{
    Bar b;
    ConnectionBar &bar = b.bar;
    bar.setOptions(QStringLiteral("/dev/ttyGONE1"), 0, ProtocolChoice::Auto);
    const auto second = std::make_shared<SimulatedJoystick>();
    bar.addSource(QStringLiteral("Second knob"), QStringLiteral("sim2"), second);
    bar.refreshPorts();
    QCOMPARE(bar.listedPorts().mid(0, 3),
             (QStringList{QStringLiteral("sim"), QStringLiteral("sim2"),
                          QStringLiteral("/dev/ttyGONE1")}));
    QCOMPARE(bar.port(), QStringLiteral("/dev/ttyGONE1")); // adding one keeps the choice
    QVERIFY(!bar.options().link);                          // a serial port: no link
    bar.setOptions(QStringLiteral("sim2"), 0, ProtocolChoice::Auto);
    QCOMPARE(bar.options().link, std::static_pointer_cast<LinkSource>(second));
    QCOMPARE(bar.sourceNamed(QStringLiteral("sim")),
             std::static_pointer_cast<LinkSource>(b.simulator));
    QVERIFY(!bar.sourceNamed(QStringLiteral("/dev/ttyGONE1")));
}

void TestConnectionBar::optionsFromControls_data()
{
    QTest::addColumn<QString>("port");
    QTest::addColumn<int>("baud");
    QTest::addColumn<ProtocolChoice>("protocol");
    QTest::newRow("simulator, defaults") << QStringLiteral("sim") << 0 << ProtocolChoice::Auto;
    QTest::newRow("usb serial, v2 at 1 Mbaud")
        << QStringLiteral("/dev/ttyUSB7") << 1000000 << ProtocolChoice::V2;
    QTest::newRow("legacy at 115200")
        << QStringLiteral("/dev/ttyACM3") << 115200 << ProtocolChoice::Legacy;
    QTest::newRow("unusual baud") << QStringLiteral("/dev/pts/9") << 250000 << ProtocolChoice::Auto;
}

void TestConnectionBar::optionsFromControls()
{
    QFETCH(QString, port);
    QFETCH(int, baud);
    QFETCH(ProtocolChoice, protocol);
    Bar b;
    ConnectionBar &bar = b.bar;
    bar.setOptions(port, baud, protocol);
    const ConnectOptions options = bar.options();
    QCOMPARE(options.port, port);
    QCOMPARE(bool(options.link), port == QStringLiteral("sim")); // the source's link, or none
    QCOMPARE(options.baud, baud);
    QCOMPARE(options.protocol, protocol);
    QSignalSpy spy(&bar, &ConnectionBar::connectRequested);
    QTest::mouseClick(bar.connectButton(), Qt::LeftButton);
    QCOMPARE(spy.size(), 1);
    QCOMPARE(spy.at(0).at(0).value<ConnectOptions>().port, port);
}

void TestConnectionBar::typedPathIsUsed()
{
    Bar b;
    ConnectionBar &bar = b.bar;
    bar.portBox()->setEditText(QStringLiteral("/tmp/my-sim-link"));
    QCOMPARE(bar.port(), QStringLiteral("/tmp/my-sim-link"));
    QVERIFY(!bar.options().link);
    bar.portBox()->setEditText(QStringLiteral("sim")); // a source's name, typed
    QCOMPARE(bar.port(), QStringLiteral("sim"));
    QCOMPARE(bar.options().link, std::static_pointer_cast<LinkSource>(b.simulator));
}

void TestConnectionBar::buttonFollowsState_data()
{
    QTest::addColumn<SessionState>("state");
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("editable");
    QTest::newRow("disconnected") << SessionState::Disconnected << QStringLiteral("Connect")
                                  << true;
    QTest::newRow("opening") << SessionState::Opening << QStringLiteral("Disconnect") << false;
    QTest::newRow("connected") << SessionState::Connected << QStringLiteral("Disconnect") << false;
    QTest::newRow("lost, reconnecting")
        << SessionState::Lost << QStringLiteral("Disconnect") << false;
}

void TestConnectionBar::buttonFollowsState()
{
    QFETCH(SessionState, state);
    QFETCH(QString, text);
    QFETCH(bool, editable);
    ConnectionBar bar;
    bar.setState(state);
    QCOMPARE(bar.connectButton()->text(), text);
    QCOMPARE(bar.portBox()->isEnabled(), editable);
    QSignalSpy connectSpy(&bar, &ConnectionBar::connectRequested);
    QSignalSpy disconnectSpy(&bar, &ConnectionBar::disconnectRequested);
    bar.toggleConnection();
    QCOMPARE(connectSpy.size(), editable ? 1 : 0);
    QCOMPARE(disconnectSpy.size(), editable ? 0 : 1);
}

void TestConnectionBar::refreshKeepsChoice()
{
    Bar b;
    ConnectionBar &bar = b.bar;
    bar.setOptions(QStringLiteral("/dev/ttyGONE0"), 0, ProtocolChoice::Auto);
    bar.refreshPorts(); // the port is not on the system, but it is the user's choice
    QCOMPARE(bar.port(), QStringLiteral("/dev/ttyGONE0"));
    QCOMPARE(bar.listedPorts().constFirst(), QStringLiteral("sim"));
}

QTEST_MAIN(TestConnectionBar)
#include "tst_connectionbar.moc"
