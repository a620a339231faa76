#include "robotsim/robotsimulator.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace hatpic::robot {

namespace {

using Clock = std::chrono::steady_clock;

double monotonicSeconds()
{
    return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

ros::Time wallTime()
{
    return ros::timeFromSeconds(
        std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count());
}

double component(const ros::Twist &twist, bridge::Component c)
{
    const ros::Vector3 &v = c.angular ? twist.angular : twist.linear;
    return c.index == 0 ? v.x : c.index == 1 ? v.y : v.z;
}

void setComponent(ros::Wrench &wrench, bridge::Component c, double value)
{
    ros::Vector3 &v = c.angular ? wrench.torque : wrench.force;
    (c.index == 0 ? v.x : c.index == 1 ? v.y : v.z) = value;
}

//! The robot's pose for position x along `c`: a translation, or a rotation by x about it.
ros::Pose poseAlong(bridge::Component c, double x)
{
    ros::Pose pose;
    if (!c.angular) {
        (c.index == 0 ? pose.position.x : c.index == 1 ? pose.position.y : pose.position.z) = x;
        return pose;
    }
    ros::Quaternion &q = pose.orientation;
    (c.index == 0 ? q.x : c.index == 1 ? q.y : q.z) = std::sin(x / 2);
    q.w = std::cos(x / 2);
    return pose;
}

} // namespace

RobotSimulator::RobotSimulator(const RobotSimSettings &settings)
    : m_settings(settings),
      m_end({settings.robot, settings.faults, settings.seed, settings.rateHz, settings.staleAfter})
{}

std::unique_ptr<RobotSimulator> RobotSimulator::start(const RobotSimSettings &settings,
                                                      std::string *error)
{
    const auto fail = [error](std::string why) {
        if (error)
            *error = std::move(why);
        return nullptr;
    };
    if (const auto violations = validate(settings); !violations.empty())
        return fail(violations.front() + ".");

    std::unique_ptr<RobotSimulator> sim(new RobotSimulator(settings));
    std::string why;
    sim->m_node = ros::Node::open(settings.node, &why);
    if (!sim->m_node)
        return fail(why);
    // A topic at its default, or relative, goes under the node's namespace (as the bridge's).
    const std::string ns = ros::effectiveNamespace(settings.node.version, settings.node.nameSpace);
    const auto placed = [&](std::string RobotSimSettings::*topic) {
        return bridge::topicInNamespace(settings.*topic, RobotSimSettings{}.*topic, ns);
    };
    if (!settings.wrenchTopic.empty()) {
        // As a wrench estimator publishes its sensor-data stream.
        sim->m_wrenchOut =
            sim->m_node->advertise(placed(&RobotSimSettings::wrenchTopic),
                                   ros::MessageType::WrenchStamped, ros::Qos::matchAny(), &why);
        if (!sim->m_wrenchOut)
            return fail(why);
    }
    if (!settings.poseTopic.empty()) {
        sim->m_poseOut =
            sim->m_node->advertise(placed(&RobotSimSettings::poseTopic),
                                   ros::MessageType::PoseStamped, ros::Qos::defaults(), &why);
        if (!sim->m_poseOut)
            return fail(why);
    }
    RobotSimulator *self = sim.get();
    sim->m_twistIn = sim->m_node->subscribe(
        placed(&RobotSimSettings::twistTopic), ros::MessageType::TwistStamped, ros::Qos::matchAny(),
        [self](const ros::Message &m) { self->onTwist(m); }, &why);
    if (!sim->m_twistIn)
        return fail(why);
    sim->m_thread = std::thread([self] { self->run(); });
    return sim;
}

RobotSimulator::~RobotSimulator()
{
    m_stop = true;
    if (m_thread.joinable())
        m_thread.join();
    m_twistIn.reset(); // no onTwist() after this
    m_wrenchOut.reset();
    m_poseOut.reset();
    m_node.reset();
}

void RobotSimulator::onTwist(const ros::Message &message)
{
    const auto *twist = std::get_if<ros::TwistStamped>(&message);
    if (!twist)
        return;
    const double v = component(twist->twist, m_settings.axis);
    const std::lock_guard lock(m_mutex);
    m_end.twistSent(v, monotonicSeconds());
}

RobotSimulator::Status RobotSimulator::status() const
{
    const std::lock_guard lock(m_mutex);
    Status s = m_status;
    s.dropped = m_end.dropped();
    return s;
}

void RobotSimulator::run()
{
    constexpr auto kStep = std::chrono::microseconds(1000);
    constexpr auto kMaxLag = std::chrono::milliseconds(100); // beyond this, skip ahead
    auto next = Clock::now();
    while (!m_stop) {
        std::this_thread::sleep_until(next);
        next += kStep;
        const auto now = Clock::now();
        if (now - next > kMaxLag) {
            const std::lock_guard lock(m_mutex);
            m_status.overruns += std::uint64_t((now - next) / kStep);
            next = now;
        }
        const double t = monotonicSeconds();
        std::vector<ros::WrenchStamped> due;
        ros::PoseStamped pose;
        bool output = false;
        {
            const std::lock_guard lock(m_mutex);
            output = m_end.step(
                t,
                [&](const RobotModel &model) {
                    ros::WrenchStamped wrench;
                    wrench.header = {wallTime(), m_settings.frameId};
                    setComponent(wrench.wrench, m_settings.axis, model.estimatedForce());
                    pose.header = wrench.header;
                    pose.pose = poseAlong(m_settings.axis, model.position());
                    return wrench;
                },
                [&](const ros::WrenchStamped &w) { due.push_back(w); });
            const RobotModel &model = m_end.model();
            m_status.x = model.position();
            m_status.v = model.velocity();
            m_status.vRef = m_end.vRef();
            m_status.wallForce = model.wallForce();
            m_status.stale = m_end.stale();
            m_status.twistsIn = m_end.twistsIn();
        }
        // Published outside the lock: status() never waits for the middleware.
        for (const ros::WrenchStamped &w : due) {
            if (m_wrenchOut && m_wrenchOut->publish(w)) {
                const std::lock_guard lock(m_mutex);
                ++m_status.wrenchesOut;
            }
        }
        if (output && m_poseOut && m_poseOut->publish(pose)) {
            const std::lock_guard lock(m_mutex);
            ++m_status.posesOut;
        }
    }
}

namespace {

//! `value` in 4 significant digits, a negligible one as 0.
std::string statusNumber(double value)
{
    if (std::abs(value) < RobotSimulator::kNegligible)
        value = 0; // also −0
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

} // namespace

std::string RobotSimulator::Status::line() const
{
    std::string out = "x " + statusNumber(x) + " m, v " + statusNumber(v) + " m/s, v_ref " +
                      statusNumber(vRef) + " m/s, F_e " + statusNumber(wallForce) +
                      " N | twists in " + std::to_string(twistsIn) + ", wrenches out " +
                      std::to_string(wrenchesOut) + ", poses out " + std::to_string(posesOut) +
                      (stale ? ", stale" : "") + ", dropped " + std::to_string(dropped);
    if (overruns > 0)
        out += ", steps late " + std::to_string(overruns);
    return out;
}

} // namespace hatpic::robot
