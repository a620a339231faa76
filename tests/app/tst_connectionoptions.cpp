// The connection options every program shares (app/common/connectionoptions.h): their bounds,
// their sentences, and the rule that --faults and --seed need --port sim.
#include "common/connectionoptions.h"
#include "simulatoroptions.h"

#include <QCommandLineParser>
#include <QTest>

using namespace hatpic;
using namespace Qt::StringLiterals;

class TestConnectionOptions : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void baud_data();
    void baud();
    void protocol_data();
    void protocol();
    void seed_data();
    void seed();
    void faults();
    void readsAParser_data();
    void readsAParser();
};

void TestConnectionOptions::baud_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("expected"); // 0: refused
    QTest::newRow("lowest") << u"300"_s << 300;
    QTest::newRow("highest") << u"4000000"_s << 4000000;
    QTest::newRow("v2's default") << u"921600"_s << 921600;
    QTest::newRow("spaces around") << u" 115200 "_s << 115200;
    QTest::newRow("below the lowest") << u"299"_s << 0;
    QTest::newRow("above the highest") << u"4000001"_s << 0;
    QTest::newRow("zero") << u"0"_s << 0;
    QTest::newRow("negative") << u"-9600"_s << 0;
    QTest::newRow("a word") << u"fast"_s << 0;
    QTest::newRow("a fraction") << u"9600.5"_s << 0;
    QTest::newRow("empty") << QString() << 0;
}

void TestConnectionOptions::baud()
{
    QFETCH(QString, text);
    QFETCH(int, expected);
    QString error;
    const std::optional<qint32> baud = parseBaud(text, &error);
    if (expected == 0) {
        QVERIFY(!baud);
        QCOMPARE(error, u"--baud must be a whole number of baud from 300 to 4000000, got '"_s +
                            text + u"'."_s);
    } else {
        QCOMPARE(baud, std::optional<qint32>(expected));
        QVERIFY(error.isEmpty());
    }
}

void TestConnectionOptions::protocol_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("allowAuto");
    QTest::addColumn<int>("expected"); // -1: refused
    QTest::addColumn<QString>("error");
    QTest::newRow("auto") << u"auto"_s << true << int(ProtocolChoice::Auto) << QString();
    QTest::newRow("v2") << u"v2"_s << true << int(ProtocolChoice::V2) << QString();
    QTest::newRow("legacy, any case")
        << u"Legacy"_s << true << int(ProtocolChoice::Legacy) << QString();
    QTest::newRow("unknown") << u"v3"_s << true << -1
                             << u"--protocol must be auto, v2 or legacy, got 'v3'."_s;
    QTest::newRow("auto where one device speaks")
        << u"auto"_s << false << -1 << u"--protocol must be v2 or legacy, got 'auto'."_s;
}

void TestConnectionOptions::protocol()
{
    QFETCH(QString, text);
    QFETCH(bool, allowAuto);
    QFETCH(int, expected);
    QFETCH(QString, error);
    QString got;
    const std::optional<ProtocolChoice> choice = parseProtocol(text, &got, allowAuto);
    QCOMPARE(choice.has_value(), expected >= 0);
    if (choice)
        QCOMPARE(int(*choice), expected);
    QCOMPARE(got, error);
}

void TestConnectionOptions::seed_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("ok");
    QTest::newRow("zero") << u"0"_s << true;
    QTest::newRow("largest") << u"18446744073709551615"_s << true;
    QTest::newRow("negative") << u"-1"_s << false;
    QTest::newRow("beyond 64 bits") << u"18446744073709551616"_s << false;
    QTest::newRow("a word") << u"x"_s << false;
}

void TestConnectionOptions::seed()
{
    QFETCH(QString, text);
    QFETCH(bool, ok);
    QString error;
    const std::optional<quint64> seed = parseSeed(text, &error);
    QCOMPARE(seed.has_value(), ok);
    QCOMPARE(error, ok ? QString()
                       : u"--seed must be a non-negative whole number, got '"_s + text + u"'."_s);
}

void TestConnectionOptions::faults()
{
    QString error;
    QVERIFY(parseFaults(u"drop=0.01,cut=30s:2s"_s, &error));
    QVERIFY(error.isEmpty());
    QVERIFY(!parseFaults(u"drop=2"_s, &error));
    QVERIFY2(error.startsWith(u"--faults: "_s) && error.contains(u"drop"_s), qPrintable(error));
}

void TestConnectionOptions::readsAParser_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("error"); // empty: accepted
    QTest::newRow("sim with faults and seed")
        << QStringList{u"--port"_s, u"sim"_s, u"--faults"_s, u"drop=0.1"_s, u"--seed"_s, u"7"_s}
        << QString();
    QTest::newRow("a port with a baud and a protocol")
        << QStringList{u"-p"_s,     u"/dev/ttyUSB0"_s, u"-b"_s,
                       u"115200"_s, u"--protocol"_s,   u"legacy"_s}
        << QString();
    QTest::newRow("faults off the sim port")
        << QStringList{u"--port"_s, u"/dev/null"_s, u"--faults"_s, u"drop=0.1"_s}
        << u"--faults and --seed act on the built-in simulated joystick: use them with --port "
           "sim (hatpic-sim has its own)."_s;
    QTest::newRow("seed off the sim port")
        << QStringList{u"--port"_s, u"/dev/null"_s, u"--seed"_s, u"1"_s}
        << u"--faults and --seed act on the built-in simulated joystick: use them with --port "
           "sim (hatpic-sim has its own)."_s;
    QTest::newRow("bad baud first")
        << QStringList{u"--port"_s, u"sim"_s, u"--baud"_s, u"1"_s, u"--protocol"_s, u"x"_s}
        << u"--baud must be a whole number of baud from 300 to 4000000, got '1'."_s;
}

void TestConnectionOptions::readsAParser()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, error);
    QCommandLineParser parser;
    for (ConnectionOption o :
         {ConnectionOption::Port, ConnectionOption::Baud, ConnectionOption::Protocol,
          ConnectionOption::Faults, ConnectionOption::Seed})
        parser.addOption(connectionOption(o));
    QVERIFY2(parser.parse(QStringList{u"program"_s} + arguments), qPrintable(parser.errorText()));
    ConnectOptions options;
    QString got;
    QCOMPARE(readConnectionOptions(parser, options, &got), error.isEmpty());
    QCOMPARE(got, error);
    if (error.isEmpty() && arguments.contains(u"-b"_s)) {
        QCOMPARE(options.port, u"/dev/ttyUSB0"_s);
        QCOMPARE(options.baud, 115200);
        QCOMPARE(options.protocol, ProtocolChoice::Legacy);
    }
    if (!error.isEmpty())
        return;
    // "sim" is the program's own simulated joystick, made here; any other port is the session's
    // serial port.
    QCOMPARE(options.link != nullptr, options.port == u"sim"_s);
    if (options.link) {
        QVERIFY(options.link->simulated());
        if (arguments.contains(u"--seed"_s))
            QCOMPARE(test::joystickOf(options)->config().seed, quint64(7));
    }
}

QTEST_GUILESS_MAIN(TestConnectionOptions)
#include "tst_connectionoptions.moc"
