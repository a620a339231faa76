#include "rosendpoints.h"

#include "rosmessages.h"

#include <dds/dds.h>

namespace hatpic::bridge {

namespace {

using JointState = sensor_msgs_msg_dds__JointState_;
using TwistStamped = geometry_msgs_msg_dds__TwistStamped_;
using PoseStamped = geometry_msgs_msg_dds__PoseStamped_;
using WrenchStamped = geometry_msgs_msg_dds__WrenchStamped_;
using WrenchMsg = geometry_msgs_msg_dds__Wrench_;

constexpr int kTakeBatch = 16;

std::string ddsError(const char *what, dds_return_t rc)
{
    return std::string("Cyclone DDS refused to create the ") + what + ": " + dds_strretcode(rc) +
           ".";
}

std_msgs_msg_dds__Header_ header(const ReferenceMessages &m, const std::string &frameId)
{
    std_msgs_msg_dds__Header_ h{};
    h.stamp.sec = m.stamp.sec;
    h.stamp.nanosec = m.stamp.nanosec;
    h.frame_id = const_cast<char *>(frameId.c_str()); // dds_write only reads it
    return h;
}

RosEndpoints::Wrench wrenchOf(const WrenchMsg &w)
{
    return {w.force.x, w.force.y, w.force.z, w.torque.x, w.torque.y, w.torque.z};
}

RosEndpoints::Wrench wrenchOf(const ros::Wrench &w)
{
    return {w.force.x, w.force.y, w.force.z, w.torque.x, w.torque.y, w.torque.z};
}

} // namespace

const char *outTopicKey(OutTopic topic)
{
    switch (topic) {
    case OutTopic::JointStates:
        return "joint_states";
    case OutTopic::Twist:
        return "twist";
    case OutTopic::Pose:
        return "pose";
    case OutTopic::Feedback:
        return "feedback";
    }
    return "";
}

struct RosEndpoints::Handles
{
    dds_entity_t participant = 0;
    std::array<dds_entity_t, kOutTopicCount> writers{};
    dds_entity_t wrenchReader = 0;
    dds_entity_t unstampedReader = 0;

    static void onData(dds_entity_t reader, void *arg)
    {
        static_cast<RosEndpoints *>(arg)->takeWrenches(reader);
    }
};

RosEndpoints::RosEndpoints(const BridgeSettings &settings, WrenchHandler onWrench)
    : m_settings(settings), m_onWrench(std::move(onWrench)), m_h(std::make_unique<Handles>())
{}

RosEndpoints::~RosEndpoints()
{
    m_subscriptions.clear(); // waits for a handler call in progress
    for (auto &publisher : m_publishers)
        publisher.reset();
    m_node.reset();
    if (m_h->participant > 0)
        dds_delete(m_h->participant); // waits for listener calls in progress
}

std::unique_ptr<RosEndpoints> RosEndpoints::open(const BridgeSettings &settings,
                                                 WrenchHandler onWrench, std::string *error)
{
    std::unique_ptr<RosEndpoints> endpoints(new RosEndpoints(settings, std::move(onWrench)));
    const std::string problem = endpoints->create();
    if (!problem.empty()) {
        if (error)
            *error = problem;
        return nullptr;
    }
    return endpoints;
}

std::string RosEndpoints::create()
{
    if (m_settings.rosVersion == 1)
        return createOnNode();
    Handles &h = *m_h;
    h.participant = dds_create_participant(dds_domainid_t(m_settings.domainId), nullptr, nullptr);
    if (h.participant < 0)
        return ddsError("participant", h.participant);

    // The QoS of ros.md, set explicitly on every reader and writer.
    dds_qos_t *qos = dds_create_qos();
    dds_qset_reliability(qos,
                         m_settings.qos == QosProfile::Reliable ? DDS_RELIABILITY_RELIABLE
                                                                : DDS_RELIABILITY_BEST_EFFORT,
                         DDS_MSECS(100));
    dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, m_settings.depth);
    const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
    dds_qset_data_representation(qos, 1, &xcdr1);

    std::string problem;
    // The DDS topic of a ROS name; 0 (and `problem` set) when refused or already failed.
    const auto topic = [&](const std::string &name, const dds_topic_descriptor_t *desc) {
        if (name.empty() || !problem.empty())
            return dds_entity_t(0);
        const dds_entity_t t =
            dds_create_topic(h.participant, desc, ddsTopicName(name).c_str(), nullptr, nullptr);
        if (t < 0)
            problem = ddsError(("topic " + name).c_str(), t);
        return t < 0 ? dds_entity_t(0) : t;
    };
    // A reader or writer of that topic.
    const auto endpoint = [&](auto create, const char *what, const std::string &name,
                              const dds_topic_descriptor_t *desc) {
        const dds_entity_t t = topic(name, desc);
        if (t == 0)
            return dds_entity_t(0);
        const dds_entity_t e = create(h.participant, t, qos, nullptr);
        if (e < 0)
            problem = ddsError((std::string(what) + name).c_str(), e);
        return e < 0 ? dds_entity_t(0) : e;
    };
    const auto writer = [&](const std::string &name, const dds_topic_descriptor_t *desc) {
        return endpoint(&dds_create_writer, "writer of ", name, desc);
    };
    const auto reader = [&](const std::string &name, const dds_topic_descriptor_t *desc) {
        return endpoint(&dds_create_reader, "reader of ", name, desc);
    };
    h.writers[int(OutTopic::JointStates)] =
        writer(m_settings.topics.jointStates, &sensor_msgs_msg_dds__JointState__desc);
    h.writers[int(OutTopic::Twist)] =
        writer(m_settings.topics.twist, &geometry_msgs_msg_dds__TwistStamped__desc);
    h.writers[int(OutTopic::Pose)] =
        writer(m_settings.topics.pose, &geometry_msgs_msg_dds__PoseStamped__desc);
    h.writers[int(OutTopic::Feedback)] =
        writer(m_settings.topics.feedback, &geometry_msgs_msg_dds__WrenchStamped__desc);

    h.wrenchReader = reader(m_settings.topics.wrench, &geometry_msgs_msg_dds__WrenchStamped__desc);
    h.unstampedReader =
        reader(m_settings.topics.wrenchUnstamped, &geometry_msgs_msg_dds__Wrench__desc);
    dds_listener_t *listener = dds_create_listener(this);
    dds_lset_data_available(listener, &Handles::onData);
    // Listening starts once both handles are known (takeWrenches tells them apart).
    for (const dds_entity_t r : {h.wrenchReader, h.unstampedReader}) {
        if (r > 0 && problem.empty()) {
            if (const dds_return_t rc = dds_set_listener(r, listener); rc < 0)
                problem = ddsError("listener of a wrench reader", rc);
        }
    }
    dds_delete_listener(listener);
    dds_delete_qos(qos);
    return problem;
}

void RosEndpoints::takeWrenches(std::int32_t reader)
{
    void *samples[kTakeBatch] = {};
    dds_sample_info_t infos[kTakeBatch];
    for (;;) {
        const dds_return_t n = dds_take(reader, samples, infos, kTakeBatch, kTakeBatch);
        if (n <= 0)
            return;
        for (int i = 0; i < n; ++i) {
            if (!infos[i].valid_data)
                continue;
            if (reader == m_h->wrenchReader)
                m_onWrench(wrenchOf(static_cast<const WrenchStamped *>(samples[i])->wrench));
            else
                m_onWrench(wrenchOf(*static_cast<const WrenchMsg *>(samples[i])));
        }
        dds_return_loan(reader, samples, n);
    }
}

std::string RosEndpoints::createOnNode()
{
    std::string error;
    ros::NodeOptions options;
    options.version = m_settings.rosVersion == 1 ? ros::RosVersion::Ros1 : ros::RosVersion::Ros2;
    options.name = "hatpic_bridge";
    options.domainId = m_settings.domainId;
    m_node = ros::Node::open(options, &error);
    if (!m_node)
        return error;
    ros::Qos writerQos = ros::Qos::defaults(); // ROS 1 takes the depth as its queue size
    writerQos.depth = m_settings.depth;
    const std::pair<const std::string *, ros::MessageType> out[] = {
        {&m_settings.topics.jointStates, ros::MessageType::JointState},
        {&m_settings.topics.twist, ros::MessageType::TwistStamped},
        {&m_settings.topics.pose, ros::MessageType::PoseStamped},
        {&m_settings.topics.feedback, ros::MessageType::WrenchStamped}};
    static_assert(std::size(out) == kOutTopicCount);
    for (int i = 0; i < kOutTopicCount; ++i) {
        if (out[i].first->empty())
            continue;
        m_publishers[i] = m_node->advertise(*out[i].first, out[i].second, writerQos, &error);
        if (!m_publishers[i])
            return error;
    }
    // Every wrench, stamped or not, goes to the one handler.
    const auto handler = [this](const ros::Message &message) {
        if (const auto *stamped = std::get_if<ros::WrenchStamped>(&message))
            m_onWrench(wrenchOf(stamped->wrench));
        else if (const auto *wrench = std::get_if<ros::Wrench>(&message))
            m_onWrench(wrenchOf(*wrench));
    };
    const std::pair<const std::string *, ros::MessageType> in[] = {
        {&m_settings.topics.wrench, ros::MessageType::WrenchStamped},
        {&m_settings.topics.wrenchUnstamped, ros::MessageType::Wrench}};
    for (const auto &[name, type] : in) {
        if (name->empty())
            continue;
        auto subscription = m_node->subscribe(*name, type, ros::Qos::matchAny(), handler, &error);
        if (!subscription)
            return error;
        m_subscriptions.push_back(std::move(subscription));
    }
    return {};
}

void RosEndpoints::publishOnNode(const ReferenceMessages &m)
{
    const ros::Header header{{m.stamp.sec, m.stamp.nanosec}, m_settings.frameId};
    // Builds a message only for a topic that has a publisher.
    const auto send = [this](OutTopic topic, const auto &make) {
        if (const auto &publisher = m_publishers[int(topic)])
            publisher->publish(make());
    };
    send(OutTopic::JointStates, [&] {
        return ros::JointState{
            header, {m_settings.jointName}, {m.position}, {m.velocity}, {m.effort}};
    });
    send(OutTopic::Twist, [&] {
        return ros::TwistStamped{
            header, {{m.twist[0], m.twist[1], m.twist[2]}, {m.twist[3], m.twist[4], m.twist[5]}}};
    });
    send(OutTopic::Pose, [&] {
        const auto &p = m.posePosition;
        const auto &o = m.poseOrientation;
        return ros::PoseStamped{header, {{p[0], p[1], p[2]}, {o[0], o[1], o[2], o[3]}}};
    });
    send(OutTopic::Feedback, [&] {
        return ros::WrenchStamped{header, {{0, 0, 0}, {0, 0, m.feedbackTorque}}};
    });
}

std::uint64_t RosEndpoints::written(OutTopic topic) const
{
    if (!m_node)
        return m_written[int(topic)];
    const auto &publisher = m_publishers[int(topic)];
    return publisher ? publisher->written() : 0;
}

std::uint64_t RosEndpoints::writeErrors() const
{
    std::uint64_t errors = m_writeErrors;
    for (const auto &publisher : m_publishers)
        errors += publisher ? publisher->writeErrors() : 0;
    return errors;
}

std::string RosEndpoints::where() const
{
    return m_node ? m_node->where() : "ROS 2, domain " + std::to_string(m_settings.domainId);
}

void RosEndpoints::publish(const ReferenceMessages &m)
{
    if (m_node) {
        publishOnNode(m);
        return;
    }
    const auto write = [this](OutTopic topic, const void *sample) {
        const dds_entity_t w = m_h->writers[int(topic)];
        if (w <= 0)
            return;
        if (dds_write(w, sample) == DDS_RETCODE_OK)
            ++m_written[int(topic)];
        else
            ++m_writeErrors;
    };

    char *names[] = {const_cast<char *>(m_settings.jointName.c_str())};
    double position = m.position, velocity = m.velocity, effort = m.effort;
    JointState joint{};
    joint.header = header(m, m_settings.frameId);
    joint.name = {1, 1, names, false};
    joint.position = {1, 1, &position, false};
    joint.velocity = {1, 1, &velocity, false};
    joint.effort = {1, 1, &effort, false};
    write(OutTopic::JointStates, &joint);

    TwistStamped twist{};
    twist.header = header(m, m_settings.frameId);
    twist.twist.linear = {m.twist[0], m.twist[1], m.twist[2]};
    twist.twist.angular = {m.twist[3], m.twist[4], m.twist[5]};
    write(OutTopic::Twist, &twist);

    PoseStamped pose{};
    pose.header = header(m, m_settings.frameId);
    pose.pose.position = {m.posePosition[0], m.posePosition[1], m.posePosition[2]};
    pose.pose.orientation = {m.poseOrientation[0], m.poseOrientation[1], m.poseOrientation[2],
                             m.poseOrientation[3]};
    write(OutTopic::Pose, &pose);

    WrenchStamped feedback{};
    feedback.header = header(m, m_settings.frameId);
    feedback.wrench.torque.z = m.feedbackTorque;
    write(OutTopic::Feedback, &feedback);
}

} // namespace hatpic::bridge
