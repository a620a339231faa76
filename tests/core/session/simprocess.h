// hatpic-sim as a child process on a pseudo-terminal, for the session tests that talk to it
// (tst_sessionpty, tst_sessioneffects).
#pragma once

#include <QProcess>
#include <QString>
#include <QStringList>

namespace hatpic::test {

constexpr int kStartTimeoutMs = 5000;

//! hatpic-sim as a child process; the first line it prints is the pty's slave path.
class SimProcess
{
public:
    explicit SimProcess(const QStringList &arguments)
    {
#ifdef HATPIC_SIM_PATH
        m_process.setProgram(QStringLiteral(HATPIC_SIM_PATH));
        m_process.setArguments(arguments);
        m_process.setProcessChannelMode(QProcess::SeparateChannels);
        m_process.start();
#else
        Q_UNUSED(arguments);
#endif
    }
    ~SimProcess()
    {
        stop();
    }

    //! Waits for the slave path; empty when the program did not start.
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
    void kill()
    {
        m_process.kill();
        m_process.waitForFinished(kStartTimeoutMs);
    }
    void stop()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.terminate();
        if (!m_process.waitForFinished(kStartTimeoutMs))
            kill();
    }
    QString errors()
    {
        return QString::fromLocal8Bit(m_process.readAllStandardError());
    }

private:
    QProcess m_process;
    QString m_path;
};

} // namespace hatpic::test
