// Helpers of tst_firmwarehost: the programs as child processes and a v2 client on a real pty.
#pragma once

#include "protocol/v2codec.h"

#include <QProcess>
#include <QSerialPort>

#include <cmath>
#include <numbers>

namespace hatpic::test {

constexpr int kStartTimeoutMs = 5000;

#if defined(HATPIC_FW_HOST_PATH) && defined(HATPIC_SERVO_SIM_PATH)
inline QString hatpicFwHost()
{
    return QStringLiteral(HATPIC_FW_HOST_PATH);
}
inline QString hatpicServoSim()
{
    return QStringLiteral(HATPIC_SERVO_SIM_PATH);
}
#endif

//! hatpic-fw-host's --servo-timeout for tests that are not about timing: on a loaded machine
//! hatpic-servo-sim may answer later than the default 5 ms, and a servo that misses a reply at
//! start ends hatpic-fw-host.
inline QStringList patientBus()
{
    return {QStringLiteral("--servo-timeout"), QStringLiteral("100")};
}

//! A program run with QProcess whose first stdout line is a pty's slave path; stderr is kept.
class PtyProgram
{
public:
    PtyProgram(const QString &program, const QStringList &arguments)
    {
        m_process.setProgram(program);
        m_process.setArguments(arguments);
        QObject::connect(&m_process, &QProcess::readyReadStandardError, &m_process,
                         [this] { m_errors += m_process.readAllStandardError(); });
        m_process.start();
    }
    ~PtyProgram()
    {
        terminate();
        if (m_process.state() != QProcess::NotRunning) {
            m_process.kill();
            m_process.waitForFinished(kStartTimeoutMs);
        }
    }
    //! Waits for the slave path; empty when the program did not print one (it failed).
    QString path()
    {
        if (!m_path.isEmpty())
            return m_path;
        while (!m_process.canReadLine() && m_process.waitForReadyRead(kStartTimeoutMs)) {
        }
        if (m_process.canReadLine())
            m_path = QString::fromLocal8Bit(m_process.readLine().trimmed());
        return m_path;
    }
    //! SIGTERM and wait; true when it exited in time.
    bool terminate()
    {
        if (m_process.state() == QProcess::NotRunning)
            return true;
        m_process.terminate();
        return m_process.waitForFinished(kStartTimeoutMs);
    }
    QProcess &process() { return m_process; }
    QString errors()
    {
        m_errors += m_process.readAllStandardError();
        return QString::fromLocal8Bit(m_errors);
    }

private:
    QProcess m_process;
    QString m_path;
    QByteArray m_errors;
};

//! A protocol v2 host on the fw-host's pty: a QSerialPort and a frame decoder.
class V2Client
{
public:
    explicit V2Client(const QString &path)
    {
        m_port.setPortName(path);
        m_port.setBaudRate(921600);
        QObject::connect(&m_port, &QSerialPort::readyRead, &m_port,
                         [this] { m_decoder.feed(m_port.readAll(), frames); });
    }
    bool open() { return m_port.open(QIODevice::ReadWrite); }
    QString errorString() const { return m_port.errorString(); }
    //! Sends a command with a fresh seq; returns that seq.
    quint8 send(const v2::Message &message)
    {
        const quint8 seq = m_seq++;
        m_port.write(v2::encodeFrame(seq, message));
        return seq;
    }
    //! The ACK of command `seq`, if it came.
    std::optional<v2::Ack> ack(quint8 seq) const
    {
        for (const v2::Frame &f : frames) {
            if (const auto *a = std::get_if<v2::Ack>(&f.message); a && a->ackedSeq == seq)
                return *a;
        }
        return std::nullopt;
    }
    template<typename T> QList<T> all() const
    {
        QList<T> out;
        for (const v2::Frame &f : frames) {
            if (const auto *m = std::get_if<T>(&f.message))
                out.append(*m);
        }
        return out;
    }

    QList<v2::Frame> frames;

private:
    QSerialPort m_port;
    v2::FrameDecoder m_decoder{v2::Direction::FromDevice};
    quint8 m_seq = 1; // seq 0 would be a HELLO's
};

constexpr double kTick = 2.0 * std::numbers::pi / 4096; //!< one servo tick [rad]

} // namespace hatpic::test
