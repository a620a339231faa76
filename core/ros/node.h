// One ROS node, whichever ROS carries it: ROS 2 (Cyclone DDS, on the wire as rmw_cyclonedds
// puts it) or ROS 1 (Debian's roscpp). What HATPIC's programs publish and subscribe goes
// through this interface only, so a topic, a type, a QoS or a discovery rule is implemented
// once per ROS and shared by hatpic-bridge, the tuner's Bridge panel and hatpic-robot-sim.
#pragma once

#include "ros/messages.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace hatpic::ros {

enum class RosVersion { Ros1, Ros2 };
const char *rosVersionName(RosVersion version); //!< "ROS 1", "ROS 2"

//! ROS 2's domain as the environment names it: ROS_DOMAIN_ID, or 0 when unset or empty. The
//! one reading of that variable (hatpic-bridge, hatpic-robot-sim, the Bridge panel, the nodes).
//! nullopt with `*error` one sentence ("ROS_DOMAIN_ID must be a whole number from 0 to 232, got
//! '300'.") when it is not a whole number from 0 to `maxId`.
std::optional<int> domainFromEnvironment(int maxId, std::string *error);

//! ROS 1: when its master shuts the process's node down (another node took its name), the
//! process says so on stderr and exits 1 — for programs whose node is their purpose
//! (hatpic-bridge, hatpic-robot-sim). Without it (the tuner) the sentence goes to stderr and
//! the node stays dead until the program restarts.
void setExitWhenShutDownByMaster(bool exit);
bool exitsWhenShutDownByMaster();

//! A topic's quality of service. ROS 2 maps it onto DDS QoS as rmw_cyclonedds does; ROS 1 has
//! none (TCPROS is reliable and volatile) and takes `depth` as the queue size.
struct Qos
{
    enum class Reliability { Reliable, BestEffort };
    enum class Durability { Volatile, TransientLocal };

    Reliability reliability = Reliability::Reliable;
    Durability durability = Durability::Volatile;
    int depth = 10; //!< keep last N (≥ 1)

    //! rmw's default profile: reliable, volatile, keep last 10.
    static Qos defaults() { return {}; }
    //! What a reader needs to match any publisher (reliable or best effort, volatile or
    //! transient local) and to see only the newest message: best effort, volatile, keep last 1.
    static Qos matchAny() { return {Reliability::BestEffort, Durability::Volatile, 1}; }

    friend bool operator==(const Qos &, const Qos &) = default;
};

struct NodeOptions
{
    RosVersion version = RosVersion::Ros2;
    //! The node's name without namespace ("hatpic_bridge"). ROS 2: not announced (no
    //! ros_discovery_info), so `ros2 node list` does not show it (ros.md § Discovery).
    std::string name;
    int domainId = -1; //!< ROS 2: the DDS domain; −1: ROS_DOMAIN_ID, else 0
    //! The node's namespace ("knob1"); empty: the root, or on ROS 1 ROS_NAMESPACE. Topic names
    //! given to advertise() and subscribe() are taken as they are (resolve them first).
    std::string nameSpace = {};
};

//! The namespace a node of `version` is in when NodeOptions::nameSpace is `given`: `given`
//! when not empty, else on ROS 1 ROS_NAMESPACE (as roscpp reads it), else empty (the root).
std::string effectiveNamespace(RosVersion version, const std::string &given);

//! Publishes one topic. publish() may be called from any thread, one call at a time; it does
//! not block on the network. written() and writeErrors() may be read from any thread.
class Publisher
{
public:
    virtual ~Publisher() = default;
    //! False when the middleware refused it (counted in writeErrors()) or the message is not of
    //! the type the publisher was made for.
    virtual bool publish(const Message &message) = 0;
    virtual std::uint64_t written() const = 0;     //!< messages handed to the middleware
    virtual std::uint64_t writeErrors() const = 0; //!< refused ones
};

//! A subscription: its handler runs on a middleware thread for every message that arrives,
//! never after the destructor returned. A message from a publisher of the same process may
//! be handed over on the publishing thread, inside its publish(). The handler must not
//! destroy its own subscription.
class Subscription
{
public:
    virtual ~Subscription() = default;
};

using MessageHandler = std::function<void(const Message &)>;

class Node
{
public:
    virtual ~Node() = default; //!< publishers and subscriptions must be gone before the node

    //! Opens a node of options.version (its environment applies: ROS 2's ROS_DOMAIN_ID,
    //! ROS_LOCALHOST_ONLY, ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_STATIC_PEERS, CYCLONEDDS_URI;
    //! ROS 1's ROS_MASTER_URI, ROS_IP/ROS_HOSTNAME, ROS_NAMESPACE). Null with `*error` one
    //! sentence when the middleware refuses, or when that ROS is not built in.
    static std::unique_ptr<Node> open(const NodeOptions &options, std::string *error);
    //! Whether this build has that ROS.
    static bool isAvailable(RosVersion version);

    //! A publisher of `type` on the ROS topic `topic` ("/hatpic/twist"); null with `*error`.
    virtual std::unique_ptr<Publisher> advertise(const std::string &topic, MessageType type,
                                                 const Qos &qos, std::string *error) = 0;
    //! A subscription to `topic`; `handler` gets each message of `type`. Null with `*error`.
    virtual std::unique_ptr<Subscription> subscribe(const std::string &topic, MessageType type,
                                                    const Qos &qos, MessageHandler handler,
                                                    std::string *error) = 0;

    //! Where the node is, for people: "ROS 2, domain 42", "ROS 1, master http://127.0.0.1:11311".
    virtual std::string where() const = 0;
};

} // namespace hatpic::ros
