#include "rosendpoints.h"

#include "model/params.h"

#include <tuple>

namespace hatpic::bridge {

namespace {

RosEndpoints::Wrench wrenchOf(const ros::Wrench &w)
{
    RosEndpoints::Wrench r;
    r.values = {w.force.x, w.force.y, w.force.z, w.torque.x, w.torque.y, w.torque.z};
    return r;
}

RosEndpoints::Wrench wrenchOf(const ros::WrenchStamped &w)
{
    RosEndpoints::Wrench r = wrenchOf(w.wrench);
    if (w.header.stamp != ros::Time{})
        r.stamp = ros::seconds(w.header.stamp);
    return r;
}

} // namespace

const char *outTopicKey(OutTopic topic)
{
    switch (topic) {
    case OutTopic::JointStates:
        return "joint_states";
    case OutTopic::Twist:
        return "twist";
    case OutTopic::TwistUnstamped:
        return "twist_unstamped";
    case OutTopic::Pose:
        return "pose";
    case OutTopic::Feedback:
        return "feedback";
    case OutTopic::JointJog:
        return "joint_jog";
    case OutTopic::Imu:
        return "imu";
    }
    return "";
}

RosEndpoints::RosEndpoints(const BridgeSettings &settings, Handlers handlers)
    : m_settings(settings), m_jointNames(jointNames(settings.jointName)),
      m_handlers(std::move(handlers))
{}

RosEndpoints::~RosEndpoints()
{
    m_subscriptions.clear(); // waits for a handler call in progress
    for (auto &publisher : m_publishers)
        publisher.reset();
    m_node.reset();
}

std::unique_ptr<RosEndpoints> RosEndpoints::open(const BridgeSettings &settings, Handlers handlers,
                                                 std::string *error)
{
    std::unique_ptr<RosEndpoints> endpoints(new RosEndpoints(settings, std::move(handlers)));
    const std::string problem = endpoints->create();
    if (!problem.empty()) {
        if (error)
            *error = problem;
        return nullptr;
    }
    return endpoints;
}

ros::Qos RosEndpoints::writerQos(const BridgeSettings &settings)
{
    ros::Qos qos = ros::Qos::defaults();
    qos.reliability = settings.qos == QosProfile::Reliable ? ros::Qos::Reliability::Reliable
                                                           : ros::Qos::Reliability::BestEffort;
    qos.depth = settings.depth;
    return qos;
}

std::string RosEndpoints::resolved(const BridgeSettings &settings, std::string Topics::*topic)
{
    const auto version = settings.rosVersion == 1 ? ros::RosVersion::Ros1 : ros::RosVersion::Ros2;
    return topicInNamespace(settings.topics.*topic, Topics{}.*topic,
                            ros::effectiveNamespace(version, settings.nodeNamespace));
}

std::string RosEndpoints::create()
{
    std::string error;
    ros::NodeOptions options;
    options.version = m_settings.rosVersion == 1 ? ros::RosVersion::Ros1 : ros::RosVersion::Ros2;
    options.name = "hatpic_bridge";
    options.domainId = m_settings.domainId;
    options.nameSpace = m_settings.nodeNamespace;
    m_node = ros::Node::open(options, &error);
    if (!m_node)
        return error;

    const std::pair<OutTopic, ros::MessageType> out[] = {
        {OutTopic::JointStates, ros::MessageType::JointState},
        {OutTopic::Twist, ros::MessageType::TwistStamped},
        {OutTopic::TwistUnstamped, ros::MessageType::Twist},
        {OutTopic::Pose, ros::MessageType::PoseStamped},
        {OutTopic::Feedback, ros::MessageType::WrenchStamped},
        {OutTopic::JointJog, ros::MessageType::JointJog},
        {OutTopic::Imu, ros::MessageType::Imu}};
    std::string Topics::*const names[] = {
        &Topics::jointStates, &Topics::twist,    &Topics::twistUnstamped,
        &Topics::pose,        &Topics::feedback, &Topics::jointJog,
        &Topics::imu};
    static_assert(std::size(out) == kOutTopicCount && std::size(names) == kOutTopicCount);
    for (int i = 0; i < kOutTopicCount; ++i) {
        const std::string name = resolved(m_settings, names[i]);
        if (name.empty())
            continue;
        auto &publisher = m_publishers[int(out[i].first)];
        publisher = m_node->advertise(name, out[i].second, writerQos(m_settings), &error);
        if (!publisher)
            return error;
    }

    // Every wrench, stamped or not, goes to the one handler.
    const auto handler = [this](const ros::Message &message) {
        if (const auto *stamped = std::get_if<ros::WrenchStamped>(&message)) {
            Wrench w = wrenchOf(*stamped);
            w.echo = isEcho(stamped->header);
            m_handlers.wrench(w);
        } else if (const auto *wrench = std::get_if<ros::Wrench>(&message))
            m_handlers.wrench(wrenchOf(*wrench));
    };
    const auto enableHandler = [this](const ros::Message &message) {
        if (const auto *b = std::get_if<ros::Bool>(&message))
            m_handlers.enable(b->data);
    };
    const auto axisHandler = [this](const ros::Message &message) {
        m_handlers.axis(axisRequest(message));
    };
    const std::tuple<std::string Topics::*, ros::MessageType, ros::MessageHandler> in[] = {
        {&Topics::wrench, ros::MessageType::WrenchStamped, handler},
        {&Topics::wrenchUnstamped, ros::MessageType::Wrench, handler},
        {&Topics::enable, ros::MessageType::Bool, enableHandler},
        {&Topics::axis, ros::MessageType::String, axisHandler},
        {&Topics::axisIndex, ros::MessageType::UInt8, axisHandler}};
    for (const auto &[topic, type, onMessage] : in) {
        const std::string name = resolved(m_settings, topic);
        if (name.empty())
            continue;
        auto subscription = m_node->subscribe(name, type, ros::Qos::matchAny(), onMessage, &error);
        if (!subscription)
            return error;
        m_subscriptions.push_back(std::move(subscription));
    }
    return {};
}

RosEndpoints::AxisRequest RosEndpoints::axisRequest(const ros::Message &message)
{
    AxisRequest request;
    if (const auto *s = std::get_if<ros::String>(&message)) {
        const auto first = s->data.find_first_not_of(" \t\r\n");
        const auto last = s->data.find_last_not_of(" \t\r\n");
        const std::string text =
            first == std::string::npos ? std::string() : s->data.substr(first, last - first + 1);
        request.axis = Component::parse(text);
        request.text = echoedText(text);
    } else if (const auto *u = std::get_if<ros::UInt8>(&message)) {
        request.axis = Component::fromSlot(u->data);
        request.text = std::to_string(u->data);
    }
    return request;
}

void RosEndpoints::publish(const ReferenceMessages &m)
{
    const ros::Header header{m.stamp, m_settings.frameId};
    // Builds a message only for a topic that has a publisher.
    const auto send = [this](OutTopic topic, const auto &make) {
        if (const auto &publisher = m_publishers[int(topic)])
            publisher->publish(make());
    };
    // One joint per knob (ros.md § A board's knobs), built only for a topic that publishes.
    const auto joints = [&m](const std::array<double, kMaxAxes> &values) {
        return std::vector<double>(values.begin(), values.begin() + m.joints);
    };
    const auto names = [this, &m] {
        return std::vector<std::string>(m_jointNames.begin(), m_jointNames.begin() + m.joints);
    };
    send(OutTopic::JointStates, [&] {
        return ros::JointState{header, names(), joints(m.position), joints(m.velocity),
                               joints(m.effort)};
    });
    const ros::Twist twist{{m.twist[0], m.twist[1], m.twist[2]},
                           {m.twist[3], m.twist[4], m.twist[5]}};
    send(OutTopic::Twist, [&] { return ros::TwistStamped{header, twist}; });
    send(OutTopic::TwistUnstamped, [&] { return twist; });
    send(OutTopic::Pose, [&] {
        const auto &p = m.posePosition;
        const auto &o = m.poseOrientation;
        return ros::PoseStamped{header, {{p[0], p[1], p[2]}, {o[0], o[1], o[2], o[3]}}};
    });
    if (m_publishers[int(OutTopic::Feedback)] && !m_settings.topics.wrench.empty())
        rememberFeedback(m.stamp); // before it can come back
    send(OutTopic::Feedback, [&] {
        return ros::WrenchStamped{header, {{0, 0, 0}, {0, 0, m.feedbackTorque}}};
    });
    send(OutTopic::JointJog, [&] {
        return ros::JointJog{header, names(), {}, joints(m.jointJogVelocity), 0};
    });
    if (m.tilt) { // a board with a tilt sensor: its orientation, nothing else known
        send(OutTopic::Imu, [&] {
            const auto &q = *m.tilt;
            ros::Imu imu;
            imu.header = header;
            imu.orientation = {q[0], q[1], q[2], q[3]};
            imu.angularVelocityCovariance[0] = -1; // not given
            imu.linearAccelerationCovariance[0] = -1;
            return imu;
        });
    }
}

void RosEndpoints::rememberFeedback(const ros::Time &stamp)
{
    const std::lock_guard lock(m_echoMutex);
    const double now = ros::seconds(stamp);
    while (!m_feedbackStamps.empty() &&
           (ros::seconds(m_feedbackStamps.front()) < now - kEchoMemoryS ||
            m_feedbackStamps.size() > std::size_t(kEchoMemoryS * kMaxPublishRateHz))) {
        m_feedbackStampSet.erase({m_feedbackStamps.front().sec, m_feedbackStamps.front().nanosec});
        m_feedbackStamps.pop_front();
    }
    if (m_feedbackStampSet.insert({stamp.sec, stamp.nanosec}).second)
        m_feedbackStamps.push_back(stamp);
}

bool RosEndpoints::isEcho(const ros::Header &header)
{
    if (header.frameId != m_settings.frameId)
        return false;
    const std::lock_guard lock(m_echoMutex);
    return m_feedbackStampSet.contains({header.stamp.sec, header.stamp.nanosec});
}

std::uint64_t RosEndpoints::written(OutTopic topic) const
{
    const auto &publisher = m_publishers[int(topic)];
    return publisher ? publisher->written() : 0;
}

std::uint64_t RosEndpoints::writeErrors() const
{
    std::uint64_t errors = 0;
    for (const auto &publisher : m_publishers)
        errors += publisher ? publisher->writeErrors() : 0;
    return errors;
}

std::string RosEndpoints::where() const
{
    return m_node->where();
}

} // namespace hatpic::bridge
