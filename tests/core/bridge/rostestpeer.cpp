#include "rostestpeer.h"

#include "rostestmessages.h"

#include <dds/dds.h>

#include <cstdlib>

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
    dds_entity_t participant = 0, joint = 0, twist = 0, pose = 0, feedback = 0, wrench = 0,
                 unstamped = 0, publications = 0;

    dds_entity_t topic(const dds_topic_descriptor_t *desc, const char *name) const
    {
        return dds_create_topic(participant, desc, name, nullptr, nullptr);
    }
};

RosTestPeer::RosTestPeer(int domain) : m_e(std::make_unique<Entities>())
{
    Entities &e = *m_e;
    e.participant = dds_create_participant(dds_domainid_t(domain), nullptr, nullptr);
    dds_qos_t *qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1000);
    const auto reader = [&](const dds_topic_descriptor_t *desc, const char *name) {
        return dds_create_reader(e.participant, e.topic(desc, name), qos, nullptr);
    };
    e.joint = reader(&sensor_msgs_msg_dds__JointState__desc, "rt/hatpic/joint_states");
    e.twist = reader(&geometry_msgs_msg_dds__TwistStamped__desc, "rt/hatpic/twist");
    e.pose = reader(&geometry_msgs_msg_dds__PoseStamped__desc, "rt/hatpic/pose");
    e.feedback = reader(&geometry_msgs_msg_dds__WrenchStamped__desc, "rt/hatpic/feedback");
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 10);
    e.wrench = dds_create_writer(
        e.participant, e.topic(&geometry_msgs_msg_dds__WrenchStamped__desc, "rt/wrench_estimation"),
        qos, nullptr);
    e.unstamped = dds_create_writer(e.participant,
                                    e.topic(&geometry_msgs_msg_dds__Wrench__desc, kUnstampedTopic),
                                    qos, nullptr);
    dds_delete_qos(qos);
    e.publications =
        dds_create_reader(e.participant, DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr);
}

RosTestPeer::~RosTestPeer()
{
    if (m_e->participant > 0)
        dds_delete(m_e->participant);
}

bool RosTestPeer::isValid() const
{
    const Entities &e = *m_e;
    return e.participant > 0 && e.joint > 0 && e.twist > 0 && e.pose > 0 && e.feedback > 0 &&
           e.wrench > 0 && e.unstamped > 0 && e.publications > 0;
}

bool RosTestPeer::wrenchMatched(bool unstamped) const
{
    dds_publication_matched_status_t status{};
    return dds_get_publication_matched_status(unstamped ? m_e->unstamped : m_e->wrench, &status) ==
               DDS_RETCODE_OK &&
           status.current_count > 0;
}

void RosTestPeer::publishWrench(double forceZ, double torqueZ)
{
    geometry_msgs_msg_dds__WrenchStamped_ w{};
    w.header.frame_id = const_cast<char *>("robot");
    w.wrench.force.z = forceZ;
    w.wrench.torque.z = torqueZ;
    dds_write(m_e->wrench, &w);
}

void RosTestPeer::publishUnstampedWrench(double forceZ)
{
    geometry_msgs_msg_dds__Wrench_ w{};
    w.force.z = forceZ;
    dds_write(m_e->unstamped, &w);
}

void RosTestPeer::clear()
{
    joints.clear();
    twists.clear();
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
    takeAll<geometry_msgs_msg_dds__TwistStamped_>(m_e->twist, [this](const auto &m) {
        twists.push_back(
            {timeOf(m.header), m.header.frame_id, vec(m.twist.linear), vec(m.twist.angular)});
    });
    takeAll<geometry_msgs_msg_dds__PoseStamped_>(m_e->pose, [this](const auto &m) {
        const auto &p = m.pose;
        poses.push_back({timeOf(m.header),
                         m.header.frame_id,
                         {p.position.x, p.position.y, p.position.z},
                         {p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w}});
    });
    takeAll<geometry_msgs_msg_dds__WrenchStamped_>(m_e->feedback, [this](const auto &m) {
        feedbacks.push_back(
            {timeOf(m.header), m.header.frame_id, vec(m.wrench.force), vec(m.wrench.torque)});
    });
}

std::vector<std::pair<std::string, std::string>> RosTestPeer::publications()
{
    void *samples[32] = {};
    dds_sample_info_t infos[32];
    const dds_return_t n = dds_take(m_e->publications, samples, infos, 32, 32);
    for (int i = 0; i < n; ++i) {
        if (!infos[i].valid_data)
            continue;
        const auto *e = static_cast<const dds_builtintopic_endpoint_t *>(samples[i]);
        m_seen.emplace_back(e->topic_name, e->type_name);
    }
    if (n > 0)
        dds_return_loan(m_e->publications, samples, n);
    return m_seen;
}

} // namespace hatpic::test
