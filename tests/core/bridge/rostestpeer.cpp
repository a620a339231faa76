#include "rostestpeer.h"

#include "rostestmessages.h"

#include <dds/dds.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>

namespace hatpic::test {

namespace {

constexpr int kBatch = 64;

template<typename T, typename Copy> void takeAll(dds_entity_t reader, Copy copy)
{
    for (;;) {
        void *samples[kBatch] = {};
        dds_sample_info_t infos[kBatch];
        const dds_return_t n = dds_take(reader, samples, infos, kBatch, kBatch);
        if (n <= 0)
            return;
        for (int i = 0; i < n; ++i) {
            if (infos[i].valid_data)
                copy(*static_cast<const T *>(samples[i]));
        }
        dds_return_loan(reader, samples, n);
    }
}

TimeGot timeOf(const std_msgs_msg_dds__Header_ &h)
{
    return {h.stamp.sec, h.stamp.nanosec};
}

std::array<double, 3> vec(const geometry_msgs_msg_dds__Vector3_ &v)
{
    return {v.x, v.y, v.z};
}

// The QoS rmw_cyclonedds gives an endpoint (create_readwrite_qos), written here independently
// of core/ros: keep last `depth`, reliable (max blocking infinite) or best effort, volatile
// or transient local with a durability service of the same history.
dds_qos_t *rmwQos(bool reliable, bool transientLocal, int depth)
{
    dds_qos_t *qos = dds_create_qos();
    dds_qset_writer_data_lifecycle(qos, false);
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, depth);
    if (reliable)
        dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_INFINITY);
    else
        dds_qset_reliability(qos, DDS_RELIABILITY_BEST_EFFORT, 0);
    if (transientLocal) {
        dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
        dds_qset_durability_service(qos, 0, DDS_HISTORY_KEEP_LAST, depth, DDS_LENGTH_UNLIMITED,
                                    DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
    } else {
        dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
    }
    dds_qset_liveliness(qos, DDS_LIVELINESS_AUTOMATIC, DDS_INFINITY);
    return qos;
}

// The endpoints a built-in topic reader has seen since the last call, appended to `seen`.
void takeEndpoints(dds_entity_t reader, std::vector<EndpointSeen> &seen)
{
    for (;;) {
        void *samples[32] = {};
        dds_sample_info_t infos[32];
        const dds_return_t n = dds_take(reader, samples, infos, 32, 32);
        if (n <= 0)
            return;
        for (int i = 0; i < n; ++i) {
            if (!infos[i].valid_data)
                continue;
            const auto *e = static_cast<const dds_builtintopic_endpoint_t *>(samples[i]);
            EndpointSeen endpoint{e->topic_name, e->type_name, {}, false};
            void *data = nullptr;
            size_t size = 0;
            if (dds_qget_userdata(e->qos, &data, &size) && data) {
                endpoint.userData.assign(static_cast<const char *>(data), size);
                dds_free(data);
            }
            dds_reliability_kind_t kind{};
            endpoint.reliable =
                dds_qget_reliability(e->qos, &kind, nullptr) && kind == DDS_RELIABILITY_RELIABLE;
            seen.push_back(std::move(endpoint));
        }
        dds_return_loan(reader, samples, n);
    }
}

} // namespace

void confineDdsToLoopback()
{
    ::setenv("CYCLONEDDS_URI",
             "<CycloneDDS><Domain Id=\"any\"><General><Interfaces>"
             "<NetworkInterface name=\"lo\"/></Interfaces>"
             "<AllowMulticast>false</AllowMulticast></General>"
             "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
             "<MaxAutoParticipantIndex>40</MaxAutoParticipantIndex>"
             "<Peers><Peer Address=\"127.0.0.1\"/></Peers></Discovery>"
             "</Domain></CycloneDDS>",
             1);
}

struct RosTestPeer::Entities
{
    dds_entity_t domain = 0, participant = 0, joint = 0, twist = 0, bestEffortTwist = 0,
                 unstampedTwist = 0, pose = 0, feedback = 0, wrench = 0, unstamped = 0,
                 publications = 0, subscriptions = 0, enable = 0, jog = 0, twistOut = 0, imu = 0,
                 axis = 0, axisIndex = 0;
    std::string twistTopic; //!< "rt/…/hatpic/twist", for twistOut

    dds_entity_t topic(const dds_topic_descriptor_t *desc, const char *name) const
    {
        return dds_create_topic(participant, desc, name, nullptr, nullptr);
    }
};

RosTestPeer::RosTestPeer(int domain, const std::string &domainConfig, const std::string &ns)
    : m_e(std::make_unique<Entities>())
{
    const auto under = [&ns](const char *name) { return "rt" + ns + name; };
    Entities &e = *m_e;
    if (!domainConfig.empty()) {
        e.domain = dds_create_domain(dds_domainid_t(domain), domainConfig.c_str());
        if (e.domain < 0)
            return;
    }
    e.participant = dds_create_participant(dds_domainid_t(domain), nullptr, nullptr);
    // ROS 2's default subscription (reliable, volatile), deep enough to keep all for a test.
    dds_qos_t *qos = rmwQos(true, false, 1000);
    const auto reader = [&](const dds_topic_descriptor_t *desc, const std::string &name) {
        return dds_create_reader(e.participant, e.topic(desc, name.c_str()), qos, nullptr);
    };
    e.joint = reader(&sensor_msgs_msg_dds__JointState__desc, under("/hatpic/joint_states"));
    e.twistTopic = under("/hatpic/twist");
    e.twist = reader(&geometry_msgs_msg_dds__TwistStamped__desc, e.twistTopic);
    e.unstampedTwist = reader(&geometry_msgs_msg_dds__Twist__desc, kTwistUnstampedTopic);
    e.pose = reader(&geometry_msgs_msg_dds__PoseStamped__desc, under("/hatpic/pose"));
    e.feedback = reader(&geometry_msgs_msg_dds__WrenchStamped__desc, under("/hatpic/feedback"));
    e.jog = reader(&control_msgs_msg_dds__JointJog__desc, kJointJogTopic);
    e.imu = reader(&sensor_msgs_msg_dds__Imu__desc, under("/hatpic/imu"));
    dds_delete_qos(qos);
    qos = rmwQos(false, false, 1000); // a sensor-data subscription
    e.bestEffortTwist = reader(&geometry_msgs_msg_dds__TwistStamped__desc, under("/hatpic/twist"));
    dds_delete_qos(qos);
    // The published driver's wrench publisher, as every sensor-data publisher: best effort,
    // transient local, keep last 1.
    qos = rmwQos(false, true, 1);
    e.wrench = dds_create_writer(
        e.participant,
        e.topic(&geometry_msgs_msg_dds__WrenchStamped__desc, under("/wrench_estimation").c_str()),
        qos, nullptr);
    e.unstamped = dds_create_writer(e.participant,
                                    e.topic(&geometry_msgs_msg_dds__Wrench__desc, kUnstampedTopic),
                                    qos, nullptr);
    dds_delete_qos(qos);
    qos = rmwQos(true, false, 1); // a teleop node's dead man: reliable, keep last 1
    e.enable = dds_create_writer(
        e.participant, e.topic(&std_msgs_msg_dds__Bool__desc, kEnableTopic), qos, nullptr);
    e.axis = dds_create_writer(e.participant, e.topic(&std_msgs_msg_dds__String__desc, kAxisTopic),
                               qos, nullptr);
    e.axisIndex = dds_create_writer(
        e.participant, e.topic(&std_msgs_msg_dds__UInt8__desc, kAxisIndexTopic), qos, nullptr);
    dds_delete_qos(qos);
    e.publications =
        dds_create_reader(e.participant, DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr);
    e.subscriptions =
        dds_create_reader(e.participant, DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, nullptr, nullptr);
}

RosTestPeer::~RosTestPeer()
{
    if (m_e->participant > 0)
        dds_delete(m_e->participant);
    if (m_e->domain > 0)
        dds_delete(m_e->domain);
}

bool RosTestPeer::isValid() const
{
    const Entities &e = *m_e;
    for (const dds_entity_t h :
         {e.participant, e.joint, e.twist, e.bestEffortTwist, e.unstampedTwist, e.pose, e.feedback,
          e.wrench, e.unstamped, e.publications, e.subscriptions, e.enable, e.jog, e.axis,
          e.axisIndex}) {
        if (h <= 0)
            return false;
    }
    return true;
}

bool RosTestPeer::wrenchMatched(bool unstamped) const
{
    dds_publication_matched_status_t status{};
    return dds_get_publication_matched_status(unstamped ? m_e->unstamped : m_e->wrench, &status) ==
               DDS_RETCODE_OK &&
           status.current_count > 0;
}

bool RosTestPeer::twistMatched() const
{
    dds_subscription_matched_status_t status{};
    return dds_get_subscription_matched_status(m_e->twist, &status) == DDS_RETCODE_OK &&
           status.current_count > 0;
}

void RosTestPeer::publishWrench(double forceZ, double torqueZ, double stampSeconds,
                                const std::string &frame)
{
    geometry_msgs_msg_dds__WrenchStamped_ w{};
    const double whole = std::floor(stampSeconds);
    w.header.stamp.sec = std::int32_t(whole);
    w.header.stamp.nanosec = std::uint32_t(std::min(999999999.0, (stampSeconds - whole) * 1e9));
    w.header.frame_id = const_cast<char *>(frame.c_str());
    w.wrench.force.z = forceZ;
    w.wrench.torque.z = torqueZ;
    dds_write(m_e->wrench, &w);
}

void RosTestPeer::publishWrench(const std::array<double, 3> &force,
                                const std::array<double, 3> &torque)
{
    geometry_msgs_msg_dds__WrenchStamped_ w{};
    w.header.frame_id = const_cast<char *>("robot");
    w.wrench.force = {force[0], force[1], force[2]};
    w.wrench.torque = {torque[0], torque[1], torque[2]};
    dds_write(m_e->wrench, &w);
}

void RosTestPeer::publishTwist(double linearX, const std::string &frame)
{
    Entities &e = *m_e;
    if (e.twistOut <= 0) {
        dds_qos_t *qos = rmwQos(true, false, 1);
        e.twistOut = dds_create_writer(
            e.participant,
            e.topic(&geometry_msgs_msg_dds__TwistStamped__desc, e.twistTopic.c_str()), qos,
            nullptr);
        dds_delete_qos(qos);
    }
    geometry_msgs_msg_dds__TwistStamped_ t{};
    t.header.frame_id = const_cast<char *>(frame.c_str());
    t.twist.linear.x = linearX;
    dds_write(e.twistOut, &t);
}

void RosTestPeer::publishUnstampedWrench(double forceZ)
{
    geometry_msgs_msg_dds__Wrench_ w{};
    w.force.z = forceZ;
    dds_write(m_e->unstamped, &w);
}

void RosTestPeer::publishEnable(bool enabled)
{
    const std_msgs_msg_dds__Bool_ b{enabled};
    dds_write(m_e->enable, &b);
}

void RosTestPeer::publishAxis(const std::string &name)
{
    const std_msgs_msg_dds__String_ s{const_cast<char *>(name.c_str())};
    dds_write(m_e->axis, &s);
}

void RosTestPeer::publishAxisIndex(std::uint8_t index)
{
    const std_msgs_msg_dds__UInt8_ u{index};
    dds_write(m_e->axisIndex, &u);
}

bool RosTestPeer::axisMatched(bool index) const
{
    dds_publication_matched_status_t status{};
    return dds_get_publication_matched_status(index ? m_e->axisIndex : m_e->axis, &status) ==
               DDS_RETCODE_OK &&
           status.current_count > 0;
}

void RosTestPeer::clear()
{
    jogs.clear();
    imus.clear();
    joints.clear();
    twists.clear();
    bestEffortTwists.clear();
    unstampedTwists.clear();
    poses.clear();
    feedbacks.clear();
}

void RosTestPeer::take()
{
    takeAll<sensor_msgs_msg_dds__JointState_>(m_e->joint, [this](const auto &m) {
        JointGot g{timeOf(m.header), m.header.frame_id, {}, {}, {}, {}};
        for (std::uint32_t i = 0; i < m.name._length; ++i)
            g.names.emplace_back(m.name._buffer[i]);
        g.position.assign(m.position._buffer, m.position._buffer + m.position._length);
        g.velocity.assign(m.velocity._buffer, m.velocity._buffer + m.velocity._length);
        g.effort.assign(m.effort._buffer, m.effort._buffer + m.effort._length);
        joints.push_back(std::move(g));
    });
    const auto twistInto = [](std::vector<VectorsGot> &into) {
        return [&into](const geometry_msgs_msg_dds__TwistStamped_ &m) {
            into.push_back(
                {timeOf(m.header), m.header.frame_id, vec(m.twist.linear), vec(m.twist.angular)});
        };
    };
    takeAll<geometry_msgs_msg_dds__TwistStamped_>(m_e->twist, twistInto(twists));
    takeAll<geometry_msgs_msg_dds__TwistStamped_>(m_e->bestEffortTwist,
                                                  twistInto(bestEffortTwists));
    takeAll<geometry_msgs_msg_dds__Twist_>(m_e->unstampedTwist, [this](const auto &m) {
        unstampedTwists.push_back({{}, {}, vec(m.linear), vec(m.angular)});
    });
    takeAll<geometry_msgs_msg_dds__PoseStamped_>(m_e->pose, [this](const auto &m) {
        const auto &p = m.pose;
        poses.push_back({timeOf(m.header),
                         m.header.frame_id,
                         {p.position.x, p.position.y, p.position.z},
                         {p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w}});
    });
    takeAll<sensor_msgs_msg_dds__Imu_>(m_e->imu, [this](const auto &m) {
        const auto &q = m.orientation;
        ImuGot g{timeOf(m.header), m.header.frame_id, {q.x, q.y, q.z, q.w}, {}, {}, {}};
        std::copy(std::begin(m.orientation_covariance), std::end(m.orientation_covariance),
                  g.orientationCovariance.begin());
        std::copy(std::begin(m.angular_velocity_covariance),
                  std::end(m.angular_velocity_covariance), g.angularVelocityCovariance.begin());
        std::copy(std::begin(m.linear_acceleration_covariance),
                  std::end(m.linear_acceleration_covariance),
                  g.linearAccelerationCovariance.begin());
        imus.push_back(g);
    });
    takeAll<control_msgs_msg_dds__JointJog_>(m_e->jog, [this](const auto &m) {
        JogGot g{timeOf(m.header), {}, {}, {}, m.duration};
        for (std::uint32_t i = 0; i < m.joint_names._length; ++i)
            g.names.emplace_back(m.joint_names._buffer[i]);
        g.displacements.assign(m.displacements._buffer,
                               m.displacements._buffer + m.displacements._length);
        g.velocities.assign(m.velocities._buffer, m.velocities._buffer + m.velocities._length);
        jogs.push_back(std::move(g));
    });
    takeAll<geometry_msgs_msg_dds__WrenchStamped_>(m_e->feedback, [this](const auto &m) {
        feedbacks.push_back(
            {timeOf(m.header), m.header.frame_id, vec(m.wrench.force), vec(m.wrench.torque)});
    });
}

std::vector<EndpointSeen> RosTestPeer::publications()
{
    takeEndpoints(m_e->publications, m_publications);
    return m_publications;
}

std::vector<EndpointSeen> RosTestPeer::subscriptions()
{
    takeEndpoints(m_e->subscriptions, m_subscriptions);
    return m_subscriptions;
}

} // namespace hatpic::test
