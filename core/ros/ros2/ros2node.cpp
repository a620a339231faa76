#include "ros/ros2/ros2node.h"

#include "realtime/realtime.h"

#include "ros/ros2/discovery.h"
#include "ros/ros2/ros2endpoints.h"

#include <dds/dds.h>

#include <unistd.h>

#include <cstdlib>
#include <limits>
#include <map>
#include <mutex>
#include <optional>

namespace hatpic::ros::ros2 {

namespace {

// The DDS domains our nodes use in this process. As rmw_cyclonedds does, the first node of a
// domain creates it with the discovery configuration and the last one deletes it; a domain
// that something else in the process created first (a plain dds_create_participant) is joined
// as it is, with its own configuration.
struct Domain
{
    dds_entity_t handle = 0; //!< ours to delete; 0 when another part of the process made it
    int nodes = 0;
    std::string config;
};

std::mutex &domainMutex()
{
    static std::mutex mutex;
    return mutex;
}

std::map<int, Domain> &domains()
{
    static std::map<int, Domain> map;
    return map;
}

void releaseDomain(int id)
{
    const std::lock_guard lock(domainMutex());
    const auto it = domains().find(id);
    if (it == domains().end() || --it->second.nodes > 0)
        return;
    if (it->second.handle > 0)
        dds_delete(it->second.handle); // with any participant still in it
    domains().erase(it);
}

// Cyclone DDS's threads on the path of a sample in and out, SCHED_FIFO at `priority`.
std::string realtimeThreadsConfig(int priority)
{
    std::string threads;
    for (const char *name : {"recv", "dq.user", "tev"})
        threads += std::string("<Thread name=\"") + name +
                   "\"><Scheduling><Class>realtime</Class><Priority>" + std::to_string(priority) +
                   "</Priority></Scheduling></Thread>";
    return "<CycloneDDS><Domain><Threads>" + threads + "</Threads></Domain></CycloneDDS>";
}

// The bound on one sample (kMaxSampleBytes), for every domain of ours.
std::string sampleSizeConfig()
{
    return "<CycloneDDS><Domain><Internal><MaxSampleSize>" + std::to_string(kMaxSampleBytes) +
           "B</MaxSampleSize></Internal></Domain></CycloneDDS>";
}

// A participant of domain `id` (configured with `config` if the domain is new to the
// process), with rmw's participant USER_DATA; 0 and `*error` set when refused.
dds_entity_t openParticipant(int id, const std::string &config, std::string *error)
{
    const auto fail = [&](const std::string &sentence) {
        if (error)
            *error = sentence;
        return dds_entity_t(0);
    };
    {
        const std::lock_guard lock(domainMutex());
        auto it = domains().find(id);
        if (it != domains().end()) {
            if (it->second.config != config)
                return fail("Another ROS 2 node of this program is in domain " +
                            std::to_string(id) +
                            " with other discovery settings (ROS_LOCALHOST_ONLY, "
                            "ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_STATIC_PEERS, CYCLONEDDS_URI "
                            "changed): close it first.");
            ++it->second.nodes;
        } else {
            dds_entity_t handle = dds_create_domain(dds_domainid_t(id), config.c_str());
            if (handle == DDS_RETCODE_PRECONDITION_NOT_MET)
                handle = 0; // made by someone else in this process: joined as it is
            else if (handle < 0)
                return fail("Cyclone DDS refused the configuration of domain " +
                            std::to_string(id) + " (" + dds_strretcode(handle) +
                            "): check CYCLONEDDS_URI and ROS_STATIC_PEERS.");
            domains()[id] = {handle, 1, config};
        }
    }
    dds_qos_t *qos = dds_create_qos();
    const std::string enclave = "enclave=/;"; // rmw's default security enclave
    dds_qset_userdata(qos, enclave.data(), enclave.size());
    const dds_entity_t participant = dds_create_participant(dds_domainid_t(id), qos, nullptr);
    dds_delete_qos(qos);
    if (participant < 0) {
        releaseDomain(id);
        return fail("Cyclone DDS refused to create the participant in domain " +
                    std::to_string(id) + ": " + dds_strretcode(participant) + ".");
    }
    return participant;
}

class Ros2Node final : public Node
{
public:
    Ros2Node(int domain, dds_entity_t participant, std::string where)
        : m_domain(domain), m_participant(participant), m_where(std::move(where))
    {}
    ~Ros2Node() override
    {
        dds_delete(m_participant);
        releaseDomain(m_domain);
    }

    std::unique_ptr<Publisher> advertise(const std::string &topic, MessageType type, const Qos &qos,
                                         std::string *error) override
    {
        if (!check(topic, qos, error))
            return nullptr;
        return makePublisher(m_participant, topic, type, qos, error);
    }

    std::unique_ptr<Subscription> subscribe(const std::string &topic, MessageType type,
                                            const Qos &qos, MessageHandler handler,
                                            std::string *error) override
    {
        if (!check(topic, qos, error))
            return nullptr;
        return makeSubscription(m_participant, topic, type, qos, std::move(handler), error);
    }

    std::string where() const override { return m_where; }

private:
    static bool check(const std::string &topic, const Qos &qos, std::string *error)
    {
        std::string problem;
        if (topic.empty())
            problem = "A ROS 2 topic needs a name.";
        else if (qos.depth < 1)
            problem = "The QoS depth of " + topic + " must be at least 1, got " +
                      std::to_string(qos.depth) + ".";
        if (!problem.empty() && error)
            *error = problem;
        return problem.empty();
    }

    int m_domain;
    dds_entity_t m_participant;
    std::string m_where;
};

// options.domainId, else ROS_DOMAIN_ID, else 0; nullopt when ROS_DOMAIN_ID is not a number.
std::optional<int> domainOf(const NodeOptions &options, std::string *error)
{
    if (options.domainId >= 0)
        return options.domainId;
    return domainFromEnvironment(std::numeric_limits<int>::max(), error);
}

} // namespace

std::unique_ptr<Node> openNode(const NodeOptions &options, std::string *error)
{
    const std::optional<int> domain = domainOf(options, error);
    if (!domain)
        return nullptr;
    const DiscoveryEnvironment environment = DiscoveryEnvironment::fromProcess();
    const std::optional<Discovery> discovery = discoveryFrom(environment, error);
    if (!discovery)
        return nullptr;
    // Cyclone's receive and delivery threads (where a wrench's handler runs) real-time where
    // the system allows it; CYCLONEDDS_URI, after this fragment, may say otherwise.
    // One sample's bound first: the discovery fragment and CYCLONEDDS_URI come after it.
    std::string config = sampleSizeConfig() + "," +
                         cycloneConfig(*discovery, environment.cycloneUri, long(getpid()));
    if (realtime::probeRealtime().empty())
        config = realtimeThreadsConfig(realtime::kPriority) + "," + config;
    const dds_entity_t participant = openParticipant(*domain, config, error);
    if (participant == 0)
        return nullptr;
    std::string where = "ROS 2, domain " + std::to_string(*domain) + ", discovery " +
                        discoveryRangeName(discovery->range);
    for (std::size_t i = 0; i < discovery->staticPeers.size(); ++i)
        where += (i == 0 ? " + " : ", ") + discovery->staticPeers[i];
    if (!environment.cycloneUri.empty())
        where += " (CYCLONEDDS_URI applies)";
    const std::string ns =
        options.nameSpace.starts_with('/') ? options.nameSpace.substr(1) : options.nameSpace;
    if (!ns.empty())
        where += ", node /" + ns + "/" + options.name;
    return std::make_unique<Ros2Node>(*domain, participant, std::move(where));
}

} // namespace hatpic::ros::ros2
