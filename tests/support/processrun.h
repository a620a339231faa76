// A program run to its end by a test: its exit code and everything it wrote, or why it did not
// end — the one runner the program tests (hatpicctl, hatpic-bridge, hatpic-tuner) share.
#pragma once

#include <QByteArray>
#include <QElapsedTimer>
#include <QProcess>
#include <QTest>

namespace hatpic::test {

struct Run
{
    int code = -1; //!< the exit code; -1: did not start or not finish in time, -2: crashed
    QByteArray out;
    QByteArray err; //!< its stderr, or why it has no exit code
};

//! Starts `process` (program, arguments and environment set) with its stdin closed and waits
//! up to `timeoutMs` for its end; a process still running then is killed. `serving`: this
//! thread's event loop runs meanwhile (devices a test scripts on pseudo-terminals keep
//! answering); else the wait blocks it.
inline Run runToEnd(QProcess &process, int timeoutMs, bool serving = false)
{
    Run run;
    process.start();
    if (!process.waitForStarted(10000)) {
        run.err = "did not start: " + process.errorString().toUtf8();
        return run;
    }
    process.closeWriteChannel();
    bool ended = false;
    if (serving) {
        QElapsedTimer clock;
        clock.start();
        while (process.state() != QProcess::NotRunning && clock.elapsed() < timeoutMs)
            QTest::qWait(10);
        ended = process.state() == QProcess::NotRunning;
    } else {
        ended = process.waitForFinished(timeoutMs);
    }
    if (!ended) {
        process.kill();
        process.waitForFinished(5000);
        run.err = "timed out; stderr so far: " + process.readAllStandardError();
        return run;
    }
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    run.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    return run;
}

} // namespace hatpic::test
