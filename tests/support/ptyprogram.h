// A program run as a child process whose first stdout line is a pty's path: hatpic-fw-host,
// hatpic-servo-sim and hatpic-sim as the tests that talk to them over a real pty run them.
#pragma once

#include <QProcess>
#include <QString>
#include <QStringList>

namespace hatpic::test {

constexpr int kStartTimeoutMs = 5000;

//! The programs, as the test's CMake names them.
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
    //! SIGKILL and wait: the program vanishes without a word.
    void kill()
    {
        m_process.kill();
        m_process.waitForFinished(kStartTimeoutMs);
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

} // namespace hatpic::test
