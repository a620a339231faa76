#include "ros/ros2/ros2endpoints.h"

#include "ros/ros2/ros2convert.h"
#include "ros/ros2/typehash.h"
#include "ros/ros2/typetable.h"

#include <atomic>

namespace hatpic::ros::ros2 {

namespace {

constexpr int kTakeBatch = 16;

std::string refused(const std::string &what, dds_return_t rc)
{
    return "Cyclone DDS refused to create the " + what + ": " + dds_strretcode(rc) + ".";
}

//! The topic entity for `topic` of `type`, with the QoS of an endpoint `what`; 0 and
//! `*error` set when refused.
dds_entity_t createTopic(dds_entity_t participant, const std::string &topic, MessageType type,
                         const std::string &what, std::string *error)
{
    const dds_entity_t t = dds_create_topic(participant, descriptorOf(type),
                                            ddsTopicName(topic).c_str(), nullptr, nullptr);
    if (t < 0 && error)
        *error = refused("topic of the " + what, t);
    return t < 0 ? 0 : t;
}

std::string typeHashOf(MessageType type)
{
    const TypeDef *def = findType(rosTypeName(type));
    return def ? typeHashUserData(*def) : std::string();
}

std::string describe(const char *kind, const std::string &topic, MessageType type)
{
    return std::string(kind) + " of " + topic + " (" + rosTypeName(type) + ")";
}

class Ros2Publisher final : public Publisher
{
public:
    Ros2Publisher(dds_entity_t topic, dds_entity_t writer, MessageType type)
        : m_topic(topic), m_writer(writer), m_type(type)
    {}
    ~Ros2Publisher() override
    {
        dds_delete(m_writer);
        dds_delete(m_topic);
    }

    bool publish(const Message &message) override
    {
        if (typeOf(message) != m_type)
            return false;
        if (writeMessage(m_writer, message) != DDS_RETCODE_OK) {
            m_writeErrors.fetch_add(1, std::memory_order_relaxed);
            return false;
        }
        m_written.fetch_add(1, std::memory_order_relaxed);
        return true;
    }
    std::uint64_t written() const override { return m_written.load(std::memory_order_relaxed); }
    std::uint64_t writeErrors() const override
    {
        return m_writeErrors.load(std::memory_order_relaxed);
    }

private:
    dds_entity_t m_topic;
    dds_entity_t m_writer;
    MessageType m_type;
    std::atomic<std::uint64_t> m_written{0};
    std::atomic<std::uint64_t> m_writeErrors{0};
};

class Ros2Subscription final : public Subscription
{
public:
    Ros2Subscription(MessageType type, MessageHandler handler)
        : m_type(type), m_handler(std::move(handler))
    {}
    ~Ros2Subscription() override
    {
        if (m_reader > 0)
            dds_delete(m_reader); // waits for a listener call in progress
        if (m_topic > 0)
            dds_delete(m_topic);
    }

    //! Creates the topic and the reader, whose listener calls take() from now on.
    bool create(dds_entity_t participant, const std::string &topic, const Qos &qos,
                std::string *error)
    {
        const std::string what = describe("reader", topic, m_type);
        m_topic = createTopic(participant, topic, m_type, what, error);
        if (m_topic == 0)
            return false;
        dds_qos_t *q = endpointQos(qos, typeHashOf(m_type));
        // A node never hears its own publications (rmw's ignore_local_publications): the
        // node's writers on this topic do not match this reader (Cyclone's ignorelocal).
        dds_qset_ignorelocal(q, DDS_IGNORELOCAL_PARTICIPANT);
        dds_listener_t *listener = dds_create_listener(this);
        dds_lset_data_available(listener, &Ros2Subscription::onData);
        const dds_entity_t reader = dds_create_reader(participant, m_topic, q, listener);
        dds_delete_listener(listener);
        dds_delete_qos(q);
        if (reader < 0) {
            if (error)
                *error = refused(what, reader);
            return false;
        }
        m_reader = reader;
        return true;
    }

private:
    static void onData(dds_entity_t reader, void *arg)
    {
        static_cast<Ros2Subscription *>(arg)->take(reader);
    }

    void take(dds_entity_t reader)
    {
        for (;;) {
            void *samples[kTakeBatch] = {};
            dds_sample_info_t infos[kTakeBatch];
            const dds_return_t n = dds_take(reader, samples, infos, kTakeBatch, kTakeBatch);
            if (n <= 0)
                return;
            for (int i = 0; i < n; ++i) {
                if (infos[i].valid_data)
                    m_handler(messageOf(m_type, samples[i]));
            }
            dds_return_loan(reader, samples, n);
        }
    }

    MessageType m_type;
    MessageHandler m_handler;
    dds_entity_t m_topic = 0;
    dds_entity_t m_reader = 0;
};

} // namespace

dds_qos_t *endpointQos(const Qos &qos, const std::string &userData)
{
    dds_qos_t *q = dds_create_qos();
    dds_qset_writer_data_lifecycle(q, false);
    dds_qset_history(q, DDS_HISTORY_KEEP_LAST, qos.depth);
    if (qos.reliability == Qos::Reliability::Reliable)
        dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, 0);
    else
        dds_qset_reliability(q, DDS_RELIABILITY_BEST_EFFORT, 0);
    if (qos.durability == Qos::Durability::TransientLocal) {
        // Cyclone keeps what a late reader gets by the durability service's history.
        dds_qset_durability(q, DDS_DURABILITY_TRANSIENT_LOCAL);
        dds_qset_durability_service(q, 0, DDS_HISTORY_KEEP_LAST, qos.depth, DDS_LENGTH_UNLIMITED,
                                    DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
    } else {
        dds_qset_durability(q, DDS_DURABILITY_VOLATILE);
    }
    dds_qset_liveliness(q, DDS_LIVELINESS_AUTOMATIC, DDS_INFINITY);
    const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
    dds_qset_data_representation(q, 1, &xcdr1);
    dds_qset_userdata(q, userData.data(), userData.size());
    return q;
}

std::unique_ptr<Publisher> makePublisher(dds_entity_t participant, const std::string &topic,
                                         MessageType type, const Qos &qos, std::string *error)
{
    const std::string what = describe("writer", topic, type);
    const dds_entity_t t = createTopic(participant, topic, type, what, error);
    if (t == 0)
        return nullptr;
    dds_qos_t *q = endpointQos(qos, typeHashOf(type));
    const dds_entity_t writer = dds_create_writer(participant, t, q, nullptr);
    dds_delete_qos(q);
    if (writer < 0) {
        dds_delete(t);
        if (error)
            *error = refused(what, writer);
        return nullptr;
    }
    return std::make_unique<Ros2Publisher>(t, writer, type);
}

std::unique_ptr<Subscription> makeSubscription(dds_entity_t participant, const std::string &topic,
                                               MessageType type, const Qos &qos,
                                               MessageHandler handler, std::string *error)
{
    auto subscription = std::make_unique<Ros2Subscription>(type, std::move(handler));
    if (!subscription->create(participant, topic, qos, error))
        return nullptr;
    return subscription;
}

} // namespace hatpic::ros::ros2
