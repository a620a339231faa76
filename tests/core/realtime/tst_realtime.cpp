// Real-time scheduling of the robot path's threads (core/realtime): a thread becomes SCHED_FIFO
// where the system allows it; where it does not (a thread without CAP_SYS_NICE under an rtprio
// limit of 0, as a normal user's; HATPIC_REALTIME=0) it says why in one sentence and stays as
// it was. The same for locking memory. The session's thread is made real-time as it starts.
#include "realtime/realtime.h"
#include "session/deviceclient.h"

#include <QDir>
#include <QFile>
#include <QTest>

#include <linux/capability.h>
#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <thread>

using namespace hatpic;

namespace {

//! Drops `capability` from the calling thread's effective set (capabilities are per thread on
//! Linux); true when done.
bool dropCapability(int capability)
{
    __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
    __user_cap_data_struct data[2] = {};
    if (syscall(SYS_capget, &header, data) != 0)
        return false;
    data[capability / 32].effective &= ~(1u << (capability % 32));
    return syscall(SYS_capset, &header, data) == 0;
}

//! Runs `f` on a thread of its own under `resource`'s soft limit `limit`, then restores it.
//! A "VmRSS:"-style figure of /proc/self/status [kB]; -1 when absent.
long statusKb(const char *key)
{
    QFile file(QStringLiteral("/proc/self/status"));
    if (!file.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : file.readAll().split('\n')) {
        if (line.startsWith(key))
            return line.mid(qsizetype(std::strlen(key))).trimmed().split(' ').first().toLong();
    }
    return -1;
}

template<typename F> void underLimit(int resource, rlim_t limit, F f)
{
    rlimit before{};
    getrlimit(resource, &before);
    rlimit lowered = before;
    lowered.rlim_cur = limit;
    QCOMPARE(setrlimit(resource, &lowered), 0);
    std::thread(f).join();
    setrlimit(resource, &before);
}

int policyOfThisThread()
{
    int policy = -1;
    sched_param param{};
    pthread_getschedparam(pthread_self(), &policy, &param);
    return policy;
}

} // namespace

class TestRealtime : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init() { ::unsetenv("HATPIC_REALTIME"); }

    // Allowed (this test runs as root in CI, or under an rtprio limit): SCHED_FIFO at the
    // priority asked. Not allowed: the sentence, and the thread as it was.
    void aThreadBecomesRealtimeWhereAllowed()
    {
        std::string problem;
        int priority = -1;
        std::thread([&] {
            problem = realtime::makeThreadRealtime();
            priority = realtime::threadFifoPriority();
        }).join();
        if (problem.empty())
            QCOMPARE(priority, realtime::kPriority);
        else
            QCOMPARE(priority, 0);
        QCOMPARE(realtime::probeRealtime(), problem);
    }

    // The fallback, forced: no CAP_SYS_NICE and an rtprio limit of 0, as a normal user has.
    void refusedSchedulingSaysWhyAndLeavesTheThread()
    {
        std::string problem;
        int policy = -1;
        bool dropped = false;
        underLimit(RLIMIT_RTPRIO, 0, [&] {
            dropped = dropCapability(CAP_SYS_NICE);
            problem = realtime::makeThreadRealtime();
            policy = policyOfThisThread();
        });
        QVERIFY(dropped);
        QCOMPARE(problem, std::string("real-time scheduling refused (Operation not permitted): "
                                      "allow it with CAP_SYS_NICE or an rtprio limit of at "
                                      "least 20 (/etc/security/limits.conf); running at normal "
                                      "priority"));
        QCOMPARE(policy, SCHED_OTHER);
        QVERIFY(realtime::firstTimeFor(problem));
        QVERIFY(!realtime::firstTimeFor(problem)); // said once per process
    }

    void refusedLockingSaysWhy()
    {
#if defined(__SANITIZE_ADDRESS__)
        QSKIP("AddressSanitizer intercepts mlockall() and makes it succeed without locking");
#endif
        std::string problem;
        bool dropped = false;
        underLimit(RLIMIT_MEMLOCK, 4096, [&] {
            dropped = dropCapability(CAP_IPC_LOCK);
            problem = realtime::lockMemory();
        });
        QVERIFY(dropped);
        QVERIFY2(problem.starts_with("locking memory refused (") &&
                     problem.ends_with("allow it with CAP_IPC_LOCK or a memlock limit (ulimit "
                                       "-l); running unlocked"),
                 problem.c_str());
    }

    void anUntouchedAllocationCostsNoLockedRam()
    {
#if defined(__SANITIZE_ADDRESS__)
        QSKIP("AddressSanitizer intercepts mlockall() and makes it succeed without locking");
#endif
        // A block reserved and never filled (roscpp's buffer for a frame a hostile peer only
        // announced) stays out of RAM; what is touched is resident (and locked) as usual.
        if (const std::string problem = realtime::lockMemory(); !problem.empty())
            QSKIP(problem.c_str()); // not allowed to lock here: nothing to check
        constexpr std::size_t kBlock = std::size_t(256) << 20;
        constexpr std::size_t kTouched = std::size_t(16) << 20;
        const long before = statusKb("VmRSS:");
        auto *block = static_cast<volatile char *>(std::malloc(kBlock));
        QVERIFY(block);
        const long reserved = statusKb("VmRSS:");
        for (std::size_t i = 0; i < kTouched; i += 4096)
            block[i] = 1;
        const long touched = statusKb("VmRSS:");
        std::free(const_cast<char *>(block));
        munlockall();
        QVERIFY2(reserved - before < 8 * 1024, qPrintable(QString::number(reserved - before)));
        QVERIFY2(touched - reserved >= 15 * 1024, qPrintable(QString::number(touched - reserved)));
    }

    void turnedOffByTheEnvironment()
    {
        ::setenv("HATPIC_REALTIME", "0", 1);
        int priority = -1;
        std::string problem;
        std::thread([&] {
            problem = realtime::makeThreadRealtime();
            priority = realtime::threadFifoPriority();
        }).join();
        QCOMPARE(priority, 0);
        QVERIFY(problem.starts_with("real-time scheduling turned off (HATPIC_REALTIME=0)"));
        QVERIFY(realtime::lockMemory().starts_with("memory locking turned off"));
    }

    // The session's I/O thread asks for it as it starts: SCHED_FIFO (seen by the kernel, in
    // /proc), or the sentence why not.
    void theSessionThreadAsksForIt()
    {
        const std::string expected = realtime::probeRealtime();
        DeviceClient client;
        QTRY_VERIFY(sessionThreadPolicy() >= 0);
        if (expected.empty()) {
            QTRY_COMPARE(sessionThreadPolicy(), SCHED_FIFO);
            QCOMPARE(client.realtimeProblem(), std::string());
        } else {
            QTRY_COMPARE(client.realtimeProblem(), expected);
            QCOMPARE(sessionThreadPolicy(), SCHED_OTHER);
        }
    }

private:
    //! The scheduling policy of this process's thread named "hatpic-session"; −1 when none.
    static int sessionThreadPolicy()
    {
        const QDir tasks(QStringLiteral("/proc/self/task"));
        for (const QString &tid : tasks.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
            QFile comm(tasks.filePath(tid + u"/comm"));
            if (comm.open(QIODevice::ReadOnly) && comm.readAll().trimmed() == "hatpic-session")
                return sched_getscheduler(pid_t(tid.toInt()));
        }
        return -1;
    }
};

QTEST_GUILESS_MAIN(TestRealtime)
#include "tst_realtime.moc"
