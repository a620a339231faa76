// SimulatorHost and hatpic-sim on real pseudo-terminals, opened with a real QSerialPort.
#include "sim/simulatorhost.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QProcess>
#include <QSerialPort>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <csignal>
#include <sys/stat.h>
#include <sys/types.h>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

// A client on the slave side: a QSerialPort plus a v2 (or legacy) decoder.
class Client
{
public:
    explicit Client(const QString &path, qint32 baud = 921600)
    {
        m_port.setPortName(path);
        m_port.setBaudRate(baud);
        QObject::connect(&m_port, &QSerialPort::readyRead, [this] { read(); });
    }
    bool open() { return m_port.open(QIODevice::ReadWrite); }
    QString errorString() const { return m_port.errorString(); }
    void close() { m_port.close(); }
    void send(quint8 seq, const v2::Message &message)
    {
        m_port.write(v2::encodeFrame(seq, message));
    }
    template<typename T> int count() const
    {
        int n = 0;
        for (const v2::Frame &f : frames)
            n += std::holds_alternative<T>(f.message);
        return n;
    }

    QList<v2::Frame> frames;
    QList<legacy::Frame> legacyFrames;
    qint64 bytes = 0;

private:
    void read()
    {
        const QByteArray data = m_port.readAll();
        bytes += data.size();
        m_decoder.feed(data, frames);
        m_legacy.feed(data, legacyFrames);
    }

    QSerialPort m_port;
    v2::FrameDecoder m_decoder{v2::Direction::FromDevice};
    legacy::Decoder m_legacy;
};

} // namespace

class TestSimulatorHost : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void helloOverPty();
    void streamsInRealTime();
    void clientCanReopen();
    void unreadOutputStaysBounded();
    void legacyFramesOverPty();
    void linkReplacesSymlinkOnly();
    void binaryRunsAndStops_data();
    void binaryRunsAndStops();
    void binarySurvivesTheFileSizeLimit();
    void binaryImuBranchBoard();
    void binaryRefusesBadOptions_data();
    void binaryRefusesBadOptions();
};

void TestSimulatorHost::helloOverPty()
{
    SimulatorHost host(SimulatedDevice::Config{});
    QCOMPARE(host.start(), QString());
    QVERIFY(host.slavePath().startsWith(u"/dev/"_s));
    Client client(host.slavePath());
    QVERIFY2(client.open(), qPrintable(client.errorString()));
    client.send(0, v2::Hello{});
    QTRY_COMPARE_WITH_TIMEOUT(client.count<v2::HelloReply>(), 1, 5000);
    const auto reply = std::get<v2::HelloReply>(client.frames.first().message);
    QCOMPARE(reply.protocolVersion, quint8(2));
    QCOMPARE(reply.maxStreamHz, quint16(1000));
    QCOMPARE(reply.firmware, u"hatpic-sim 0.1"_s);
}

void TestSimulatorHost::streamsInRealTime()
{
    SimulatorHost host(SimulatedDevice::Config{});
    QCOMPARE(host.start(), QString());
    Client client(host.slavePath());
    QVERIFY2(client.open(), qPrintable(client.errorString()));
    client.send(1, v2::SetStream{1000});
    QTRY_VERIFY_WITH_TIMEOUT(client.count<v2::Telemetry>() >= 10, 5000);
    const int first = client.count<v2::Telemetry>();
    QElapsedTimer timer;
    timer.start();
    QTRY_VERIFY_WITH_TIMEOUT(client.count<v2::Telemetry>() >= first + 2000, 10000);
    // Loose: real time on a shared machine. ~1000 frames per second of wall time.
    const double rate = (client.count<v2::Telemetry>() - first) / (timer.nsecsElapsed() * 1e-9);
    QVERIFY2(rate > 500 && rate < 1500, qPrintable(QString::number(rate)));
    // The device clock in the frames advances by 1 ms per frame.
    QList<quint32> stamps;
    for (const v2::Frame &f : std::as_const(client.frames)) {
        if (const auto *t = std::get_if<v2::Telemetry>(&f.message))
            stamps.append(t->t_us);
    }
    QCOMPARE(stamps.at(100) - stamps.at(99), 1000u);
}

void TestSimulatorHost::clientCanReopen()
{
    SimulatorHost host(SimulatedDevice::Config{});
    QCOMPARE(host.start(), QString());
    for (int round = 0; round < 3; ++round) {
        Client client(host.slavePath());
        QVERIFY2(client.open(), qPrintable(client.errorString()));
        client.send(quint8(round), v2::Ping{quint32(round)});
        QTRY_COMPARE_WITH_TIMEOUT(client.count<v2::Pong>(), 1, 5000);
        client.close();
        // With no client the host keeps running (no EIO/HUP loop): time goes on.
        const double t = host.device().time();
        QTRY_VERIFY_WITH_TIMEOUT(host.device().time() > t + 0.05, 5000);
    }
}

void TestSimulatorHost::unreadOutputStaysBounded()
{
    SimulatedDevice::Config config;
    config.controlRateHz = 5000; // ~92 kB/s of telemetry at 921600 baud
    config.ideal = true;
    SimulatorHost host(config);
    QCOMPARE(host.start(), QString());
    {
        Client client(host.slavePath());
        QVERIFY2(client.open(), qPrintable(client.errorString()));
        client.send(1, v2::SetStream{5000});
        QTRY_VERIFY_WITH_TIMEOUT(client.count<v2::Telemetry>() > 0, 5000);
        client.close(); // streaming goes on with nobody reading
    }
    QTRY_VERIFY_WITH_TIMEOUT(host.bytesDiscarded() > 0, 30000);
    // A new client still gets through: HELLO stops the stream and is answered.
    Client client(host.slavePath());
    QVERIFY2(client.open(), qPrintable(client.errorString()));
    client.send(7, v2::Hello{});
    QTRY_COMPARE_WITH_TIMEOUT(client.count<v2::HelloReply>(), 1, 10000);
}

void TestSimulatorHost::legacyFramesOverPty()
{
    SimulatedDevice::Config config;
    config.protocol = WireProtocol::Legacy;
    SimulatorHost host(config);
    QCOMPARE(host.start(), QString());
    QCOMPARE(host.device().baud(), 115200);
    Client client(host.slavePath(), 115200);
    QVERIFY2(client.open(), qPrintable(client.errorString()));
    QTRY_VERIFY_WITH_TIMEOUT(client.legacyFrames.size() >= 3, 5000);
    QCOMPARE(client.legacyFrames.last(), (legacy::Frame{1000, 1000, 1000, 1000}));
    QCOMPARE(client.count<v2::HelloReply>(), 0);
}

void TestSimulatorHost::linkReplacesSymlinkOnly()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    SimulatorHost host(SimulatedDevice::Config{});
    QVERIFY(!host.createLink(dir.filePath(u"early"_s)).isEmpty()); // not started yet
    QCOMPARE(host.start(), QString());

    const QString stale = dir.filePath(u"stale"_s);
    QVERIFY(QFile::link(u"/nonexistent/pts/99"_s, stale));
    QCOMPARE(host.createLink(stale), QString());
    QCOMPARE(QFileInfo(stale).symLinkTarget(), host.slavePath());

    const QString regular = dir.filePath(u"regular"_s);
    QFile file(regular);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.close();
    QVERIFY(host.createLink(regular).contains(u"not a symlink"_s));
    QVERIFY(QFileInfo(regular).isFile());

    const QString fresh = dir.filePath(u"fresh"_s);
    QCOMPARE(host.createLink(fresh), QString());
    host.stop();
    QVERIFY(!QFileInfo(fresh).isSymLink()); // removed on stop
    QVERIFY(QFileInfo(stale).isSymLink());  // only the current link is ours to remove
}

void TestSimulatorHost::binaryRunsAndStops_data()
{
    QTest::addColumn<int>("signal");
    QTest::addColumn<QString>("protocol");
    QTest::addColumn<int>("exitCode"); //!< -1: ends as the signal would (crash exit)
    QTest::newRow("v2, SIGTERM") << int(SIGTERM) << u"v2"_s << 0;
    QTest::newRow("v2, SIGINT") << int(SIGINT) << u"v2"_s << 0;
    QTest::newRow("legacy, SIGTERM") << int(SIGTERM) << u"legacy"_s << 0;
    // Any other signal that would end it: the same orderly stop, then 128 + the signal…
    QTest::newRow("v2, SIGHUP") << int(SIGHUP) << u"v2"_s << 128 + SIGHUP;
    QTest::newRow("v2, SIGALRM") << int(SIGALRM) << u"v2"_s << 128 + SIGALRM;
    // …or, for a fault the event loop cannot wait for, the link removed before the end.
    QTest::newRow("v2, SIGSEGV") << int(SIGSEGV) << u"v2"_s << -1;
    QTest::newRow("v2, SIGABRT") << int(SIGABRT) << u"v2"_s << -1;
}

void TestSimulatorHost::binaryRunsAndStops()
{
    QFETCH(int, signal);
    QFETCH(QString, protocol);
    QFETCH(int, exitCode);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(u"hatpic"_s);
    QVERIFY(QFile::link(u"/nonexistent/stale"_s, link)); // a stale link left behind

    QProcess sim;
    // No core file from the faults sent on purpose.
    sim.setProgram(u"/bin/sh"_s);
    sim.setArguments({u"-c"_s, u"ulimit -c 0; exec \"$0\" \"$@\""_s,
                      QStringLiteral(HATPIC_SIM_PATH), u"--protocol"_s, protocol, u"--link"_s, link,
                      u"--hand"_s, u"idle"_s, u"--seed"_s, u"3"_s});
    sim.start();
    QVERIFY2(sim.waitForStarted(5000), qPrintable(sim.errorString()));
    QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
    const QString path = QString::fromLocal8Bit(sim.readLine()).chopped(1);
    QVERIFY2(path.startsWith(u"/dev/"_s), qPrintable(path));
    QVERIFY(QFileInfo::exists(path));
    QVERIFY(QFileInfo(link).isSymLink());
    QCOMPARE(QFileInfo(link).symLinkTarget(), path);

    {
        Client client(link, protocol == u"legacy"_s ? 115200 : 921600);
        QVERIFY2(client.open(), qPrintable(client.errorString()));
        if (protocol == u"v2"_s) {
            client.send(0, v2::Hello{});
            QTRY_COMPARE_WITH_TIMEOUT(client.count<v2::HelloReply>(), 1, 5000);
        } else {
            QTRY_VERIFY_WITH_TIMEOUT(client.legacyFrames.size() >= 2, 5000);
        }
    }

    QCOMPARE(::kill(pid_t(sim.processId()), signal), 0);
    QVERIFY(sim.waitForFinished(10000));
    if (exitCode < 0) {
        QCOMPARE(sim.exitStatus(), QProcess::CrashExit);
    } else {
        QCOMPARE(sim.exitStatus(), QProcess::NormalExit);
        QCOMPARE(sim.exitCode(), exitCode);
    }
    QVERIFY(!QFileInfo(link).isSymLink()); // removed on exit
    QVERIFY(!QFileInfo::exists(link));
}

void TestSimulatorHost::binarySurvivesTheFileSizeLimit()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString state = dir.filePath(u"state.json"_s);
    QProcess sim;
    // ulimit -f 0: any write to a file passes the limit (SIGXFSZ kills by default).
    sim.start(u"/bin/sh"_s, {u"-c"_s, u"ulimit -f 0; exec \"$0\" \"$@\""_s,
                             QStringLiteral(HATPIC_SIM_PATH), u"--state"_s, state});
    QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
    const QString path = QString::fromLocal8Bit(sim.readLine()).chopped(1);
    {
        Client client(path);
        QVERIFY2(client.open(), qPrintable(client.errorString()));
        client.send(4, v2::SaveParams{});
        const auto acked = [&] {
            for (const v2::Frame &f : std::as_const(client.frames)) {
                if (const auto *ack = std::get_if<v2::Ack>(&f.message); ack && ack->ackedSeq == 4)
                    return ack->status == v2::AckStatus::StorageError;
            }
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(acked(), 5000);
        QString log;
        for (const v2::Frame &f : std::as_const(client.frames)) {
            if (const auto *l = std::get_if<v2::Log>(&f.message))
                log += v2::toQString(l->text);
        }
        QVERIFY2(log.contains(u"SAVE_PARAMS failed: cannot write profile"_s) &&
                     log.contains(u"File too large"_s),
                 qPrintable(log));
    }
    QCOMPARE(sim.state(), QProcess::Running);
    sim.terminate();
    QVERIFY(sim.waitForFinished(10000));
    QCOMPARE(sim.exitStatus(), QProcess::NormalExit);
    QCOMPARE(sim.exitCode(), 0);
}

void TestSimulatorHost::binaryImuBranchBoard()
{
    QProcess sim;
    sim.start(QStringLiteral(HATPIC_SIM_PATH),
              {u"--device"_s, u"imu-branch"_s, u"--tilt"_s, u"0.3,-0.2"_s, u"--hand-3"_s,
               u"const:0.05"_s, u"--seed"_s, u"5"_s});
    QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
    const QString path = QString::fromLocal8Bit(sim.readLine()).chopped(1);
    {
        Client client(path, 115200);
        QVERIFY2(client.open(), qPrintable(client.errorString()));
        QTRY_VERIFY_WITH_TIMEOUT(client.legacyFrames.size() >= 3, 5000);
        const legacy::Frame last = client.legacyFrames.last();
        QVERIFY(last.tilt.has_value());
        QCOMPARE(*last.tilt, (legacy::Tilt{809, 873}));
        QVERIFY2(last.c > 1010, qPrintable(QString::number(last.c))); // knob 3 pushed
        QVERIFY2(std::abs(last.a - 1000) <= 2, qPrintable(QString::number(last.a)));
    }
    sim.terminate();
    QVERIFY(sim.waitForFinished(10000));
    QCOMPARE(sim.exitCode(), 0);
    const QString err = QString::fromLocal8Bit(sim.readAllStandardError());
    QVERIFY2(err.contains(u"IMU-branch board (4 knobs), legacy protocol"_s), qPrintable(err));
}

void TestSimulatorHost::binaryRefusesBadOptions_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("messagePart");
    QTest::newRow("unknown protocol") << QStringList{u"--protocol"_s, u"v3"_s} << u"v3"_s;
    QTest::newRow("rate zero") << QStringList{u"--rate"_s, u"0"_s} << u"control rate"_s;
    QTest::newRow("rate below the watchdog's 10 Hz")
        << QStringList{u"--rate"_s, u"5"_s} << u"from 10 to 20000"_s;
    QTest::newRow("rate not a number") << QStringList{u"--rate"_s, u"fast"_s} << u"fast"_s;
    QTest::newRow("baud not a number") << QStringList{u"--baud"_s, u"abc"_s} << u"baud"_s;
    QTest::newRow("bad hand spec") << QStringList{u"--hand"_s, u"sine:1"_s} << u"sine:A:F"_s;
    QTest::newRow("negative seed") << QStringList{u"--seed"_s, u"-1"_s} << u"seed"_s;
    QTest::newRow("unknown option") << QStringList{u"--colour"_s} << u"colour"_s;
    QTest::newRow("fault spec") << QStringList{u"--faults"_s, u"dup=0.1,delay=0.1:20"_s}
                                << u"Fault spec item \"delay=0.1:20\": delay's duration"_s;
    QTest::newRow("missing value") << QStringList{u"--rate"_s} << u"rate"_s;
    QTest::newRow("positional argument") << QStringList{u"extra"_s} << u"extra"_s;
    QTest::newRow("unknown board")
        << QStringList{u"--device"_s, u"arm"_s} << u"--device: must be knob or imu-branch"_s;
    QTest::newRow("tilt on a single knob")
        << QStringList{u"--tilt"_s, u"0.1,0"_s} << u"need --device imu-branch"_s;
    QTest::newRow("hand-2 on a single knob")
        << QStringList{u"--hand-2"_s, u"idle"_s} << u"need --device imu-branch"_s;
    QTest::newRow("imu-branch over v2")
        << QStringList{u"--device"_s, u"imu-branch"_s, u"--protocol"_s, u"v2"_s}
        << u"legacy frames"_s;
    QTest::newRow("tilt beyond a quarter turn")
        << QStringList{u"--device"_s, u"imu-branch"_s, u"--tilt"_s, u"2,0"_s} << u"--tilt"_s;
    QTest::newRow("tilt not two numbers")
        << QStringList{u"--device"_s, u"imu-branch"_s, u"--tilt"_s, u"0.1"_s} << u"ROLL,PITCH"_s;
    QTest::newRow("bad hand-4") << QStringList{u"--device"_s, u"imu-branch"_s, u"--hand-4"_s,
                                               u"sine:1"_s}
                                << u"--hand-4: "_s;
    // A pipe as the state file once blocked open() before signals were handled (issue 10).
    static QTemporaryDir dir;
    const QString fifo = dir.filePath(u"state.fifo"_s);
    if (!QFileInfo::exists(fifo))
        ::mkfifo(QFile::encodeName(fifo).constData(), 0600);
    QTest::newRow("state file is a pipe")
        << QStringList{u"--state"_s, fifo} << u"not a regular file"_s;
    QTest::newRow("state file is a folder")
        << QStringList{u"--state"_s, dir.path()} << u"not a regular file"_s;
}

void TestSimulatorHost::binaryRefusesBadOptions()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, messagePart);
    QProcess sim;
    sim.start(QStringLiteral(HATPIC_SIM_PATH), arguments);
    QVERIFY(sim.waitForFinished(10000));
    QCOMPARE(sim.exitStatus(), QProcess::NormalExit);
    QCOMPARE(sim.exitCode(), 4);
    QCOMPARE(sim.readAllStandardOutput(), QByteArray());
    const QString err = QString::fromLocal8Bit(sim.readAllStandardError()).trimmed();
    QVERIFY2(err.contains(messagePart), qPrintable(err));
    QVERIFY2(!err.contains(QLatin1Char('\n')), qPrintable(err)); // one sentence
}

QTEST_GUILESS_MAIN(TestSimulatorHost)
#include "tst_simulatorhost.moc"
