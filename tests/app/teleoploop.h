// The teleoperation loop of robot.md run as a user runs it — hatpic-sim (a hand on the
// simulated knob), hatpic-bridge and hatpic-robot-sim as three real processes on loopback —
// and a ROS node that watches it: the parts tst_teleoploop and bench/bench_teleop share.
// Header-only; needs hatpic::ros, Qt Core and an event loop on the calling thread (QProcess).
#pragma once

#include "ros/node.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFileInfo>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace hatpic::test {

//! The host's monotonic clock [s]: the time base of every Watcher::Point.
inline double monotonic()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

//! Runs the calling thread's event loop for `seconds`.
inline void spinFor(double seconds)
{
    QEventLoop loop;
    QTimer::singleShot(std::max(0, int(seconds * 1000)), &loop, &QEventLoop::quit);
    loop.exec();
}

//! What a node on the loop's topics sees: θ from /hatpic/joint_states, τ_ext (the device's)
//! from /hatpic/feedback, x from /robot/pose and F_e (= −force.x) from /wrench_estimation,
//! each with its arrival time [s, monotonic()]. The handlers run on the middleware's threads;
//! read the series through window() or points(), which lock.
class Watcher
{
public:
    struct Point
    {
        double t;     //!< arrival [s, monotonic()]
        double value; //!< θ [rad], τ_ext [N·m], x [m] or F_e [N]
    };
    using Series = std::vector<Point> Watcher::*;

    //! Opens the node `name` and subscribes to the loop's topics, under the namespace `ns`
    //! ("/knob2") when given; empty, or why not.
    QString open(ros::RosVersion version, int domain, const std::string &name,
                 const std::string &ns = {})
    {
        std::string why;
        m_node = ros::Node::open({version, name, domain, {}}, &why);
        if (!m_node)
            return QString::fromStdString(why);
        const auto add = [&](const char *topic, ros::MessageType type, std::vector<Point> *into,
                             auto read) {
            auto sub = m_node->subscribe(
                ns + topic, type, ros::Qos::matchAny(),
                [this, into, read](const ros::Message &m) {
                    const std::lock_guard lock(m_mutex);
                    if (const auto value = read(m))
                        into->push_back({monotonic(), *value});
                },
                &why);
            if (sub)
                m_subs.push_back(std::move(sub));
            return sub != nullptr || !m_subs.empty();
        };
        const bool ok = add("/hatpic/joint_states", ros::MessageType::JointState, &m_theta,
                            [](const ros::Message &m) -> std::optional<double> {
                                const auto *js = std::get_if<ros::JointState>(&m);
                                if (!js || js->position.empty())
                                    return std::nullopt;
                                return js->position.front();
                            }) &&
                        add("/hatpic/feedback", ros::MessageType::WrenchStamped, &m_tau,
                            [](const ros::Message &m) -> std::optional<double> {
                                const auto *w = std::get_if<ros::WrenchStamped>(&m);
                                return w ? std::optional(w->wrench.torque.z) : std::nullopt;
                            }) &&
                        add("/robot/pose", ros::MessageType::PoseStamped, &m_x,
                            [](const ros::Message &m) -> std::optional<double> {
                                const auto *p = std::get_if<ros::PoseStamped>(&m);
                                return p ? std::optional(p->pose.position.x) : std::nullopt;
                            }) &&
                        add("/wrench_estimation", ros::MessageType::WrenchStamped, &m_wallForce,
                            [](const ros::Message &m) -> std::optional<double> {
                                const auto *w = std::get_if<ros::WrenchStamped>(&m);
                                return w ? std::optional(-w->wrench.force.x) : std::nullopt;
                            });
        return ok && m_subs.size() == 4 ? QString() : QString::fromStdString(why);
    }
    void close()
    {
        m_subs.clear();
        m_node.reset();
    }

    //! The values of a series that arrived in [from, to] (monotonic seconds).
    std::vector<double> window(Series series, double from, double to) const
    {
        const std::lock_guard lock(m_mutex);
        std::vector<double> out;
        for (const Point &p : this->*series) {
            if (p.t >= from && p.t <= to)
                out.push_back(p.value);
        }
        return out;
    }
    //! A copy of a whole series, in arrival order.
    std::vector<Point> points(Series series) const
    {
        const std::lock_guard lock(m_mutex);
        return this->*series;
    }
    std::size_t count(Series series) const
    {
        const std::lock_guard lock(m_mutex);
        return (this->*series).size();
    }

    std::vector<Point> m_theta, m_tau, m_x, m_wallForce; // guarded by m_mutex

private:
    mutable std::mutex m_mutex;
    std::unique_ptr<ros::Node> m_node;
    std::vector<std::unique_ptr<ros::Subscription>> m_subs;
};

struct Stats
{
    double mean = NAN;
    double min = NAN;
    double max = NAN;
    std::size_t n = 0;
    double spread() const { return max - min; }
};

inline Stats statsOf(const std::vector<double> &v)
{
    Stats s;
    s.n = v.size();
    if (v.empty())
        return s;
    double sum = 0;
    s.min = s.max = v.front();
    for (double x : v) {
        sum += x;
        s.min = std::min(s.min, x);
        s.max = std::max(s.max, x);
    }
    s.mean = sum / double(v.size());
    return s;
}

//! A child program that is stopped (SIGTERM, then SIGKILL) when it goes out of scope.
class Program
{
public:
    explicit Program(const QString &path) { m_process.setProgram(path); }
    ~Program() { stop(); }

    bool start(const QStringList &arguments, const QProcessEnvironment &env)
    {
        m_process.setArguments(arguments);
        m_process.setProcessEnvironment(env);
        m_process.start();
        return m_process.waitForStarted(10000);
    }
    void stop()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.terminate();
        if (!m_process.waitForFinished(10000)) {
            m_process.kill();
            m_process.waitForFinished(5000);
        }
    }
    void kill()
    {
        m_process.kill();
        m_process.waitForFinished(5000);
    }
    QProcess &process() { return m_process; }
    //! The last 600 bytes of each of stdout and stderr so far, for a failure's report.
    QByteArray output()
    {
        m_out += m_process.readAllStandardOutput();
        m_err += m_process.readAllStandardError();
        return "stdout: " + m_out.right(600) + "\nstderr: " + m_err.right(600);
    }

    //! All of stdout so far.
    QByteArray standardOutput()
    {
        output();
        return m_out;
    }

private:
    QProcess m_process;
    QByteArray m_out, m_err;
};

//! `base` confined as the tests run ROS: a private domain, discovery on loopback only (as
//! rmw_cyclonedds reads ROS_AUTOMATIC_DISCOVERY_RANGE), no CYCLONEDDS_URI of the caller's.
inline QProcessEnvironment loopEnvironment(QProcessEnvironment base, int domain)
{
    using namespace Qt::StringLiterals;
    base.insert(u"ROS_DOMAIN_ID"_s, QString::number(domain));
    base.insert(u"ROS_AUTOMATIC_DISCOVERY_RANGE"_s, u"LOCALHOST"_s);
    base.remove(u"CYCLONEDDS_URI"_s);
    return base;
}

//! How to start one loop.
struct LoopSetup
{
    QString simPath, bridgePath, robotPath; //!< the three programs
    ros::RosVersion version = ros::RosVersion::Ros2;
    int domain = 0;              //!< the private ROS 2 domain (also the watcher's)
    QProcessEnvironment env;     //!< the children's, e.g. loopEnvironment()
    QString link;                //!< where hatpic-sim puts its pseudo-terminal (a fresh path)
    QString hand;                //!< hatpic-sim --hand, e.g. "const:0.05"
    double gain = 0.02;          //!< hatpic-bridge --gain on --component force.x [N·m/N]
    QStringList robotArguments;  //!< more for hatpic-robot-sim, e.g. {"--delay", "0.02"}
    QStringList bridgeArguments; //!< more for hatpic-bridge, e.g. {"--profile", FILE}
    QStringList simArguments;    //!< more for hatpic-sim, e.g. {"--state", FILE}
    std::string nodeName = "hatpic_teleop_watcher";
    QString nameSpace; //!< --namespace of the bridge and the robot ("knob2"); empty: none
};

//! The three programs and the watcher; destroyed robot, bridge, sim, then the watcher.
struct Loop
{
    Watcher watcher;
    std::unique_ptr<Program> sim, bridge, robot;
};

//! Opens the watcher, then starts hatpic-sim (and waits for its link), hatpic-robot-sim and
//! hatpic-bridge; empty, or why not. Sets the watcher's own ROS environment in this process.
inline QString startLoop(Loop &loop, const LoopSetup &setup)
{
    using namespace Qt::StringLiterals;
    const QString rosArg = setup.version == ros::RosVersion::Ros1 ? u"1"_s : u"2"_s;
    qputenv("ROS_DOMAIN_ID", QByteArray::number(setup.domain));
    qputenv("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST");
    const QStringList nsArguments =
        setup.nameSpace.isEmpty() ? QStringList() : QStringList{u"--namespace"_s, setup.nameSpace};
    const std::string ns =
        setup.nameSpace.isEmpty() ? std::string() : "/" + setup.nameSpace.toStdString();
    if (const QString why = loop.watcher.open(setup.version, setup.domain, setup.nodeName, ns);
        !why.isEmpty())
        return u"the watching node: "_s + why;

    loop.sim = std::make_unique<Program>(setup.simPath);
    if (!loop.sim->start(QStringList{u"--hand"_s, setup.hand, u"--link"_s, setup.link} +
                             setup.simArguments,
                         setup.env))
        return u"hatpic-sim did not start"_s;
    const double deadline = monotonic() + 10;
    while (!QFileInfo::exists(setup.link) && monotonic() < deadline)
        spinFor(0.05);
    if (!QFileInfo::exists(setup.link))
        return u"hatpic-sim made no link: "_s + QString::fromUtf8(loop.sim->output());

    loop.robot = std::make_unique<Program>(setup.robotPath);
    if (!loop.robot->start(QStringList{u"--ros"_s, rosArg} + nsArguments + setup.robotArguments,
                           setup.env))
        return u"hatpic-robot-sim did not start"_s;
    loop.bridge = std::make_unique<Program>(setup.bridgePath);
    if (!loop.bridge->start(QStringList{u"--ros"_s, rosArg, u"--port"_s, setup.link,
                                        u"--component"_s, u"force.x"_s, u"--gain"_s,
                                        QString::number(setup.gain)} +
                                nsArguments + setup.bridgeArguments,
                            setup.env))
        return u"hatpic-bridge did not start"_s;
    return {};
}

} // namespace hatpic::test
