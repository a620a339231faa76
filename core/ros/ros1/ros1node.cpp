#include "ros/ros1/ros1node.h"

#include "ros/ros1/ros1messages.h"
#include "ros/ros1/ros1runtime.h"

#include <ros/init.h>

#include <algorithm>
#include <type_traits>

namespace hatpic::ros::ros1 {

namespace {

class Ros1Publisher final : public Publisher
{
public:
    Ros1Publisher(Runtime &runtime, std::shared_ptr<PublisherSlot> slot)
        : m_runtime(runtime), m_slot(std::move(slot))
    {}
    ~Ros1Publisher() override { m_runtime.remove(m_slot); }

    bool publish(const Message &message) override
    {
        PublisherSlot &slot = *m_slot;
        if (typeOf(message) != slot.type) {
            ++slot.errors;
            return false;
        }
        // roscpp's publish() only queues the message for each subscriber's connection.
        const std::lock_guard lock(slot.mutex);
        if (!slot.publisher || !::ros::ok()) {
            ++slot.errors; // no master reached yet, or the node was shut down
            return false;
        }
        std::visit(
            [&](const auto &m) {
                if constexpr (!std::is_same_v<std::decay_t<decltype(m)>, JointJog>)
                    slot.publisher.publish(toRos(m));
            },
            message); // a JointJog publisher is refused in prepare()
        ++slot.written;
        return true;
    }
    std::uint64_t written() const override { return m_slot->written; }
    std::uint64_t writeErrors() const override { return m_slot->errors; }

private:
    Runtime &m_runtime;
    std::shared_ptr<PublisherSlot> m_slot;
};

class Ros1Subscription final : public Subscription
{
public:
    Ros1Subscription(Runtime &runtime, std::shared_ptr<SubscriptionSlot> slot)
        : m_runtime(runtime), m_slot(std::move(slot))
    {}
    ~Ros1Subscription() override { m_runtime.remove(m_slot); } // no handler call after it

private:
    Runtime &m_runtime;
    std::shared_ptr<SubscriptionSlot> m_slot;
};

class Ros1Node final : public Node
{
public:
    explicit Ros1Node(Runtime &runtime) : m_runtime(runtime) { m_runtime.attach(); }
    ~Ros1Node() override { m_runtime.detach(); }
    Ros1Node(const Ros1Node &) = delete;
    Ros1Node &operator=(const Ros1Node &) = delete;

    std::unique_ptr<Publisher> advertise(const std::string &topic, MessageType type, const Qos &qos,
                                         std::string *error) override
    {
        auto slot = std::make_shared<PublisherSlot>();
        if (!prepare(*slot, topic, type, qos, error))
            return nullptr;
        m_runtime.add(slot);
        return std::make_unique<Ros1Publisher>(m_runtime, std::move(slot));
    }

    std::unique_ptr<Subscription> subscribe(const std::string &topic, MessageType type,
                                            const Qos &qos, MessageHandler handler,
                                            std::string *error) override
    {
        auto slot = std::make_shared<SubscriptionSlot>();
        if (!handler) {
            if (error)
                *error = "A subscription to " + topic + " needs a handler.";
            return nullptr;
        }
        if (!prepare(*slot, topic, type, qos, error))
            return nullptr;
        slot->handler = std::move(handler);
        m_runtime.add(slot);
        return std::make_unique<Ros1Subscription>(m_runtime, std::move(slot));
    }

    std::string where() const override
    {
        return "ROS 1, master " + m_runtime.masterUri() + " (node " + m_runtime.nodeName() + ")";
    }

private:
    // The slot's resolved topic, type and queue; false with `*error` when ROS 1 refuses them.
    template<typename Slot>
    bool prepare(Slot &slot, const std::string &topic, MessageType type, const Qos &qos,
                 std::string *error)
    {
        if (!hasRos1Type(type)) {
            if (error)
                *error = std::string(rosTypeName(type)) +
                         " is ROS 2 only: Debian has no ROS 1 control_msgs (topic " + topic + ").";
            return false;
        }
        slot.topic = m_runtime.resolve(topic, error);
        if (slot.topic.empty())
            return false;
        if (const std::string conflict = m_runtime.typeConflict(slot.topic, type);
            !conflict.empty()) {
            if (error)
                *error = conflict;
            return false;
        }
        slot.type = type;
        slot.queueSize = std::max(1, qos.depth); // ROS 1 has no QoS but the queue
        return true;
    }

    Runtime &m_runtime;
};

} // namespace

std::unique_ptr<Node> openNode(const NodeOptions &options, std::string *error)
{
    Runtime *runtime = Runtime::acquire(options.name, options.nameSpace, error);
    if (!runtime)
        return nullptr;
    return std::make_unique<Ros1Node>(*runtime);
}

} // namespace hatpic::ros::ros1
