// bench_bridge [--ros 1|2] [--seconds S] [--steps N] [--domain ID] [--feedback-rate HZ]
//              [--load N] [--hogs busy|stress-ng] [--peer-realtime] [--windows K]
//
// The robot path as users run it: `hatpic-sim` on a pseudo-terminal, `hatpic-bridge --port
// <pty> --rate 1000` on it, and the robot, a node made through the project's ROS layer
// (ros/node.h) in a process of its own (this program again, with --as-peer), which takes every
// figure below. It runs at normal priority, as a user's ROS node does (HATPIC_REALTIME=0 in its
// environment: none of its threads real-time); --peer-realtime lets it make its middleware's
// threads real-time as the bridge does, which is what this bench measured before 2026-12-06. ROS 2
// runs in a private DDS domain (default 81) with CYCLONEDDS_URI binding Cyclone DDS to `lo` without
// multicast; ROS 1 (--ros 1) starts a roscore of its own on a free port with ROS_MASTER_URI,
// ROS_IP, ROS_HOME and ROS_LOG_DIR set for every process. Run it inside /work/bin/isolated (or any
// network namespace of its own) on a shared machine.
//
//   knob → topic: every JointState that arrives on /hatpic/joint_states during S seconds
//     (default 10): its arrival (host wall clock) minus its header.stamp, which the bridge
//     sets to the host's wall-clock time at which the sample's frame was decoded
//     (bridge.cpp, referencemessages.cpp). So it is decode → publish → middleware → our
//     handler; the device → pseudo-terminal → decode part is not in it (the device's clock is
//     not the host's).
//   wrench round trip: a WrenchStamped on /wrench_estimation stepping force.z between +0.5 and
//     −0.5 N every 100 ms, N steps (default 100); from just before publish() to the first
//     /hatpic/feedback message whose torque.z (the τ_ext the device reports in its telemetry)
//     is the new value (gain 0.154: ±0.077 N·m). ROS 2: once with a reliable publisher (ROS
//     2's default QoS), once best effort; ROS 1 has no QoS (TCPROS).
//   CPU: hatpic-bridge's utime + stime (/proc/PID/stat) over each window, as % of one core.
//   --load N: N CPU-bound processes run for the whole measurement (as a robot host running a
//     simulator or a build), started once the topic flows: --hogs busy (the default) N shells
//     `sh -c 'while :; do :; done'`, the plainest hog; --hogs stress-ng `stress-ng --cpu N`.
//     --windows K: the knob → topic window and the wrench steps K times, one row each, and the
//     worst of them (performance.md § The loop with the CPU busy). The bridge and hatpic-sim
//     run as they start by themselves: real-time where allowed.
// Prints one plain table; exit 1 when a program does not start or nothing arrives. The peer's
// probes, round trips, CPU windows and rows are in benchpeer.h.
#include "benchpeer.h"
#include "ros/node.h"

#ifdef HATPIC_BENCH_ROS1
#include "roscore.h"
#endif

#include <QCoreApplication>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

using namespace hatpic;
using namespace hatpic::bench;
using namespace std::chrono_literals;

namespace {

struct Options
{
    ros::RosVersion ros = ros::RosVersion::Ros2;
    double seconds = 10;                //!< knob → topic window [s]
    int steps = 100;                    //!< wrench steps per QoS
    int domain = 81;                    //!< ROS 2's private DDS domain
    std::optional<double> feedbackRate; //!< passed on as --feedback-rate [Hz]
    int load = 0;                       //!< N CPU hogs during the measurement
    bool stressNg = false;              //!< the hogs: stress-ng --cpu N, else busy shells
    bool peerRealtime = false;          //!< the peer's middleware threads real-time
    int windows = 1;                    //!< measurement windows
    qint64 peerOf[2] = {0, 0};          //!< --as-peer BRIDGE_PID SIM_PID: the measuring peer
};

std::optional<Options> parseOptions(int argc, char *argv[])
{
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string name = argv[i];
        if (name == "--peer-realtime") {
            o.peerRealtime = true;
            continue;
        }
        if (name == "--as-peer" && i + 2 < argc) {
            o.peerOf[0] = std::atoll(argv[++i]);
            o.peerOf[1] = std::atoll(argv[++i]);
            continue;
        }
        if (i + 1 >= argc) {
            std::fprintf(stderr, "bench_bridge: %s needs a value.\n", name.c_str());
            return std::nullopt;
        }
        const char *value = argv[++i];
        if (name == "--ros" && (std::string(value) == "1" || std::string(value) == "2")) {
            o.ros = std::string(value) == "1" ? ros::RosVersion::Ros1 : ros::RosVersion::Ros2;
        } else if (name == "--seconds" && std::atof(value) > 0) {
            o.seconds = std::atof(value);
        } else if (name == "--steps" && std::atoi(value) > 0) {
            o.steps = std::atoi(value);
        } else if (name == "--domain" && std::atoi(value) >= 0) {
            o.domain = std::atoi(value);
        } else if (name == "--feedback-rate" && std::atof(value) > 0) {
            o.feedbackRate = std::atof(value);
        } else if (name == "--load" && std::atoi(value) >= 0) {
            o.load = std::atoi(value);
        } else if (name == "--hogs" &&
                   (std::string(value) == "busy" || std::string(value) == "stress-ng")) {
            o.stressNg = std::string(value) == "stress-ng";
        } else if (name == "--windows" && std::atoi(value) > 0) {
            o.windows = std::atoi(value);
        } else {
            std::fprintf(stderr,
                         "bench_bridge: bad option %s %s; usage: bench_bridge [--ros 1|2] "
                         "[--seconds S] [--steps N] [--domain ID] [--feedback-rate HZ] "
                         "[--load N] [--hogs busy|stress-ng] [--peer-realtime] [--windows K]\n",
                         name.c_str(), value);
            return std::nullopt;
        }
    }
    return o;
}

QByteArray loadAverage()
{
    QFile file(QStringLiteral("/proc/loadavg"));
    if (!file.open(QIODevice::ReadOnly))
        return "?";
    const QList<QByteArray> parts = file.readAll().split(' ');
    return parts.size() >= 3 ? parts[0] + ' ' + parts[1] + ' ' + parts[2] : QByteArray("?");
}

QByteArray tail(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll().right(1500) : QByteArray();
}

// A program this bench started: its output in a file of the run's directory, stopped by its
// process id.
class Child
{
public:
    explicit Child(const QString &logPath) : m_log(logPath)
    {
        m_process.setProcessChannelMode(QProcess::MergedChannels);
    }
    ~Child() { stop(); }

    //! Starts it, its output going to the log file; with `firstLine`, its output stays in a
    //! pipe instead (output() reads it) and the first line is read into `firstLine` (≤ 10 s).
    bool start(const QString &program, const QStringList &arguments, QByteArray *firstLine)
    {
        if (!firstLine)
            m_process.setStandardOutputFile(m_log);
        m_process.start(program, arguments);
        if (!m_process.waitForStarted(5000))
            return false;
        if (firstLine) {
            while (!m_process.canReadLine() && m_process.waitForReadyRead(10000)) {
            }
            *firstLine = m_process.readLine().trimmed();
        }
        return m_process.state() == QProcess::Running;
    }
    qint64 pid() const { return m_process.processId(); }
    bool running() const { return m_process.state() == QProcess::Running; }
    QByteArray output() { return m_process.readAll() + tail(m_log); }

    void stop()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        ::kill(pid_t(pid()), SIGINT);
        if (!m_process.waitForFinished(10000)) {
            m_process.kill();
            m_process.waitForFinished(2000);
        }
    }

private:
    QProcess m_process;
    QString m_log;
};

void confineToLoopback(int domain)
{
    qputenv("CYCLONEDDS_URI",
            "<CycloneDDS><Domain Id=\"any\"><General><Interfaces><NetworkInterface name=\"lo\"/>"
            "</Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery>"
            "<ParticipantIndex>auto</ParticipantIndex><Peers><Peer Address=\"127.0.0.1\"/>"
            "</Peers></Discovery></Domain></CycloneDDS>");
    qputenv("ROS_DOMAIN_ID", QByteArray::number(domain));
}

int fail(const char *what, Child *child = nullptr)
{
    std::fprintf(stderr, "bench_bridge: %s\n", what);
    if (child)
        std::fprintf(stderr, "%s\n", child->output().constData());
    return 1;
}

// The measuring peer (--as-peer): the robot's node, in a process of its own. Prints "ready"
// once the topic flows, waits for a line on stdin (the hogs are running then), measures and
// prints the table's rows; exit 1 when nothing arrives.
int runPeer(const Options &options)
{
    const qint64 bridgePid = options.peerOf[0], simPid = options.peerOf[1];
    const bool ros1 = options.ros == ros::RosVersion::Ros1;
    KnobProbe knob; // before the node: its subscriptions call them until they are gone
    FeedbackProbe feedback;
    std::string error;
    const auto node = ros::Node::open({options.ros, "hatpic_bench", options.domain, {}}, &error);
    if (!node)
        return fail(error.c_str());
    auto joints = node->subscribe(
        "/hatpic/joint_states", ros::MessageType::JointState, ros::Qos::defaults(),
        [&knob](const ros::Message &m) { knob.onMessage(m); }, &error);
    auto feedbackSub = node->subscribe(
        "/hatpic/feedback", ros::MessageType::WrenchStamped, ros::Qos::defaults(),
        [&feedback](const ros::Message &m) { feedback.onMessage(m); }, &error);
    if (!joints || !feedbackSub)
        return fail(error.c_str());

    // The device connected and the topic matched: messages arrive. Then a second to settle.
    const auto deadline = Clock::now() + 30s;
    while (knob.seen() < 1000 && Clock::now() < deadline)
        std::this_thread::sleep_for(50ms);
    if (knob.seen() < 1000)
        return fail("no JointState arrives from hatpic-bridge");
    std::this_thread::sleep_for(1s);
    std::printf("ready\n");
    std::fflush(stdout);
    char go[16];
    if (!std::fgets(go, sizeof go, stdin))
        return fail("the bench went away");

    // The wrench round trip, per publisher QoS (ROS 1: none).
    struct Run
    {
        const char *qosName;
        ros::Qos qos;
        std::unique_ptr<ros::Publisher> publisher;
    };
    std::vector<Run> runs;
    if (ros1) {
        runs.push_back({"TCPROS", ros::Qos::defaults(), {}});
    } else {
        runs.push_back({"reliable", ros::Qos::defaults(), {}});
        runs.push_back({"best effort",
                        {ros::Qos::Reliability::BestEffort, ros::Qos::Durability::Volatile, 1},
                        {}});
    }
    for (Run &run : runs) {
        run.publisher =
            node->advertise("/wrench_estimation", ros::MessageType::WrenchStamped, run.qos, &error);
        if (!run.publisher)
            return fail(error.c_str());
    }

    struct Window
    {
        std::vector<double> knobMs;
        double knobSeconds = 0;
        double bridgeCpu = NAN, simCpu = NAN; //!< [% of one core]
        std::vector<RoundTrips> trips;        //!< per run
        std::vector<double> tripCpu;          //!< per run
    };
    std::vector<Window> windows(std::size_t(options.windows));
    for (Window &w : windows) {
        // knob → topic, with the bridge's CPU over the same window.
        knob.record(true, std::size_t(options.seconds * 1100));
        const CpuWindow knobCpu(bridgePid);
        const CpuWindow knobSimCpu(simPid);
        const auto knobStart = Clock::now();
        std::this_thread::sleep_for(std::chrono::duration<double>(options.seconds));
        knob.record(false);
        w.knobSeconds = msBetween(knobStart, Clock::now()) * 1e-3;
        w.bridgeCpu = knobCpu.percent();
        w.simCpu = knobSimCpu.percent();
        w.knobMs = knob.latencies();
        for (Run &run : runs) {
            const CpuWindow cpu(bridgePid);
            w.trips.push_back(measureRoundTrips(*run.publisher, feedback, options.steps));
            w.tripCpu.push_back(cpu.percent());
            if (!w.trips.back().warmedUp)
                return fail("the wrench never came back on /hatpic/feedback");
        }
    }

    std::printf("%-40s %7s %8s %8s %8s %8s\n", "latency [ms]", "count", "p50", "p95", "p99", "max");
    double worstKnobP99 = 0, worstTripP95 = 0, worstRate = INFINITY;
    for (std::size_t i = 0; i < windows.size(); ++i) {
        const Window &w = windows[i];
        const std::string prefix =
            windows.size() > 1 ? "[" + std::to_string(i + 1) + "] " : std::string();
        const double rate = double(w.knobMs.size()) / w.knobSeconds;
        const QByteArray note = QByteArray::number(rate, 'f', 1) + " messages/s over " +
                                QByteArray::number(w.knobSeconds, 'f', 1) + " s";
        printRow((prefix + "knob -> /hatpic/joint_states").c_str(), w.knobMs, note.constData());
        std::vector<double> sorted = w.knobMs;
        std::sort(sorted.begin(), sorted.end());
        worstKnobP99 = std::max(worstKnobP99, percentile(sorted, 0.99));
        worstRate = std::min(worstRate, rate);
        for (std::size_t r = 0; r < runs.size(); ++r) {
            const std::string name =
                prefix + "wrench (" + runs[r].qosName + ") -> /hatpic/feedback";
            const std::string lost = std::to_string(w.trips[r].lost) + " lost (none within 1 s)";
            printRow(name.c_str(), w.trips[r].ms, lost.c_str());
            std::vector<double> trip = w.trips[r].ms;
            std::sort(trip.begin(), trip.end());
            worstTripP95 = std::max(worstTripP95, percentile(trip, 0.95));
        }
        std::printf("%shatpic-bridge CPU [%% of one core]: %.1f during the joint_states window "
                    "(hatpic-sim %.1f)",
                    prefix.c_str(), w.bridgeCpu, w.simCpu);
        for (std::size_t r = 0; r < runs.size(); ++r)
            std::printf(", %.1f during the %s steps", w.tripCpu[r], runs[r].qosName);
        std::printf("\n");
    }
    if (windows.size() > 1)
        std::printf("worst of %zu windows: knob -> topic p99 %.2f ms, round trip p95 %.2f ms, "
                    "%.1f messages/s\n",
                    windows.size(), worstKnobP99, worstTripP95, worstRate);
    std::fflush(stdout);
    joints.reset();
    feedbackSub.reset();
    return 0;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv); // QProcess only; no event loop runs
    const auto options = parseOptions(argc, argv);
    if (!options)
        return 4;
    if (options->peerOf[0] > 0)
        return runPeer(*options);
    const bool ros1 = options->ros == ros::RosVersion::Ros1;
    QTemporaryDir dir;
    if (!dir.isValid())
        return fail("no temporary directory");

    const QByteArray loadStart = loadAverage();
    // ROS 1: the tests' master (tests/core/ros/roscore.h): a free port, its own ROS_HOME and
    // log directory, its process group stopped as one; its environment is this process's and
    // so the children's.
    std::unique_ptr<test::RosCore> roscore;
    QByteArray where;
    if (ros1) {
#ifdef HATPIC_BENCH_ROS1
        roscore = std::make_unique<test::RosCore>();
        roscore->exportEnvironment();
        if (const QString why = roscore->start(); !why.isEmpty())
            return fail(qPrintable(QStringLiteral("roscore: ") + why));
        where = "ROS 1, master " + roscore->uri().toLocal8Bit();
#else
        return fail("ROS 1 is not in this build of the benchmark (it needs the tests' roscore)");
#endif
    } else {
        confineToLoopback(options->domain);
        where = "ROS 2, domain " + QByteArray::number(options->domain) + ", Cyclone DDS on lo";
    }

    Child sim(dir.filePath(QStringLiteral("sim.log")));
    QByteArray pty;
    if (!sim.start(QStringLiteral(HATPIC_SIM_PATH), {}, &pty) || pty.isEmpty())
        return fail("hatpic-sim does not start", &sim);
    QStringList bridgeArguments = {
        QStringLiteral("--port"), QString::fromLocal8Bit(pty),
        QStringLiteral("--rate"), QStringLiteral("1000"),
        QStringLiteral("--ros"),  ros1 ? QStringLiteral("1") : QStringLiteral("2")};
    if (!ros1)
        bridgeArguments << QStringLiteral("--domain") << QString::number(options->domain);
    if (options->feedbackRate)
        bridgeArguments << QStringLiteral("--feedback-rate")
                        << QString::number(*options->feedbackRate);
    Child bridge(dir.filePath(QStringLiteral("bridge.log")));
    if (!bridge.start(QStringLiteral(HATPIC_BRIDGE_PATH), bridgeArguments, nullptr))
        return fail("hatpic-bridge does not start", &bridge);

    // The measuring peer: this program again, at normal priority unless --peer-realtime.
    QProcess peer;
    QProcessEnvironment peerEnvironment = QProcessEnvironment::systemEnvironment();
    if (!options->peerRealtime)
        peerEnvironment.insert(QStringLiteral("HATPIC_REALTIME"), QStringLiteral("0"));
    peer.setProcessEnvironment(peerEnvironment);
    peer.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    QStringList peerArguments = QCoreApplication::arguments().mid(1);
    peerArguments << QStringLiteral("--as-peer") << QString::number(bridge.pid())
                  << QString::number(sim.pid());
    peer.start(QCoreApplication::applicationFilePath(), peerArguments);
    if (!peer.waitForStarted(5000))
        return fail("the measuring peer does not start");
    // Its "ready", after whatever the middleware logs on stdout (roscpp's INFO lines).
    bool ready = false;
    const auto readyBy = Clock::now() + 40s;
    while (!ready && Clock::now() < readyBy && peer.state() == QProcess::Running) {
        if (peer.canReadLine())
            ready = peer.readLine().trimmed() == "ready";
        else
            peer.waitForReadyRead(1000);
    }
    if (!ready)
        return fail("the measuring peer sees no JointState from hatpic-bridge", &bridge);

    // N CPU hogs for the whole measurement: one stress-ng running N workers, or N shells.
    const int hogProcesses = options->stressNg ? std::min(options->load, 1) : options->load;
    const QString hogProgram =
        options->stressNg ? QStringLiteral("stress-ng") : QStringLiteral("sh");
    const QStringList hogArguments =
        options->stressNg
            ? QStringList{QStringLiteral("--cpu"), QString::number(options->load)}
            : QStringList{QStringLiteral("-c"), QStringLiteral("while :; do :; done")};
    std::vector<std::unique_ptr<Child>> hogs;
    for (int i = 0; i < hogProcesses; ++i) {
        hogs.push_back(std::make_unique<Child>(dir.filePath(QStringLiteral("hog%1.log").arg(i))));
        if (!hogs.back()->start(hogProgram, hogArguments, nullptr))
            return fail(options->stressNg ? "stress-ng does not start (apt-get install stress-ng)"
                                          : "sh does not start",
                        hogs.back().get());
    }
    if (options->load > 0)
        std::this_thread::sleep_for(1s); // the hogs at full speed
    peer.write("go\n");
    peer.waitForBytesWritten(1000);
    // A window: its seconds, then two QoS × steps of at most 1 s each (lost ones), and 10 s.
    const int budgetMs =
        int(options->windows * (options->seconds + 2.0 * options->steps * 1.0 + 10) * 1000);
    const bool finished = peer.waitForFinished(budgetMs);
    for (auto &hog : hogs)
        hog->stop();
    const QByteArray loadEnd = loadAverage();
    const QByteArray table = peer.readAllStandardOutput();
    if (!finished || peer.exitCode() != 0) {
        peer.kill();
        peer.waitForFinished(2000);
        return fail(QByteArray("the measuring peer failed: " + table).constData(), &bridge);
    }

    std::printf("bench_bridge: %s; hatpic-sim on %s; hatpic-bridge --rate 1000", where.constData(),
                pty.constData());
    if (options->feedbackRate)
        std::printf(" --feedback-rate %g", *options->feedbackRate);
    if (options->load > 0)
        std::printf(options->stressNg ? "; stress-ng --cpu %d" : "; %d busy shells", options->load);
    std::printf("; the peer %s\n",
                options->peerRealtime ? "real-time where allowed" : "at normal priority");
    std::printf("load average %s at the start, %s at the end; %ld cores online\n",
                loadStart.constData(), loadEnd.constData(), sysconf(_SC_NPROCESSORS_ONLN));
    std::fwrite(table.constData(), 1, std::size_t(table.size()), stdout);

    bridge.stop();
    sim.stop();
    if (roscore)
        roscore->stop();
    return 0;
}
