// The process's one ROS 1 node. roscpp allows one node per process (ros::init once, and no
// start again after ros::shutdown), so every ros1::openNode() shares this runtime: the first
// names the node, later ones must ask for the same name. It outlives the last Node (the node
// stays registered with its master, without topics, until the process ends) and is torn
// down at exit, before roscpp's own exit handler: roscpp shut down in order, so that the node,
// its topics and its logger services are unregistered from the master, as rospy's are.
//
// One thread of its own talks to the master, never the caller's: it waits for a master that
// is not there yet (a short TCP probe every second), starts roscpp once the master answers,
// creates and drops the ROS publishers and subscribers, and notices a master that restarted
// (it no longer knows this node) and registers everything with it again. Subscription
// callbacks run on an AsyncSpinner thread with a callback queue of its own.
#pragma once

#include "ros/node.h"

#include <ros/callback_queue.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/spinner.h>
#include <ros/subscriber.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace hatpic::ros::ros1 {

//! A topic published through the runtime. The ROS publisher exists once the master was reached.
struct PublisherSlot
{
    std::string topic; //!< resolved ("/ns/hatpic/twist")
    MessageType type = MessageType::JointState;
    int queueSize = 1;

    std::mutex mutex;           //!< guards `publisher` (publish() holds it while it writes)
    ::ros::Publisher publisher; //!< empty until created by the runtime's thread
    std::atomic<std::uint64_t> written{0};
    std::atomic<std::uint64_t> errors{0};
};

//! A subscription through the runtime. The ROS subscriber exists once the master was reached.
struct SubscriptionSlot
{
    std::string topic; //!< resolved
    MessageType type = MessageType::JointState;
    int queueSize = 1;

    std::mutex mutex;             //!< guards `handler`; held while it runs
    MessageHandler handler;       //!< cleared by the Subscription's destructor
    ::ros::Subscriber subscriber; //!< the runtime's (guarded by its mutex)

    void deliver(const Message &message);
};

class Runtime
{
public:
    enum class State {
        Waiting,   //!< the master has not answered yet; roscpp is initialised, not started
        Connected, //!< registered with the master
        Lost,      //!< the master stopped answering; endpoints keep their peer connections
        Dead,      //!< roscpp shut down (the master told it to); nothing more is possible
    };

    //! The process's exit code when its master shut the node down (app/common/exitcodes.h's
    //! ExitFailure): the sentence goes to stderr first.
    static constexpr int kExitShutDownByMaster = 1;
    //! The master is probed (and its registrations checked) this often.
    static constexpr std::chrono::milliseconds kCheckInterval{1000};
    //! A master call made while the master is gone gives up after this long (roscpp's retry
    //! timeout; its default is forever).
    static constexpr double kMasterRetryTimeoutS = 1.0;

    //! The runtime, initialising roscpp with `name` on the first call. Null with `*error` (one
    //! sentence) when ROS_MASTER_URI, ROS_NAMESPACE or the name is refused, when the process's
    //! node already has another name, or when roscpp was shut down.
    static Runtime *acquire(const std::string &name, const std::string &nameSpace,
                            std::string *error);
    //! The master's URI, as roscpp uses it (ROS_MASTER_URI, else http://localhost:11311).
    std::string masterUri() const;
    std::string nodeName() const; //!< resolved: "/hatpic_bridge", "/ns/hatpic_bridge"
    State state() const { return m_state; }

    //! A topic name resolved in the node's namespace; empty with `*error` when ROS 1 refuses it.
    std::string resolve(const std::string &topic, std::string *error) const;
    //! Empty, or why `topic` cannot have `type` in this process (ROS 1 allows one type per
    //! topic and node).
    std::string typeConflict(const std::string &topic, MessageType type) const;

    void add(const std::shared_ptr<PublisherSlot> &slot);
    void add(const std::shared_ptr<SubscriptionSlot> &slot);
    //! The slot's ROS endpoint is unregistered later, on the runtime's thread.
    void remove(const std::shared_ptr<PublisherSlot> &slot);
    void remove(const std::shared_ptr<SubscriptionSlot> &slot);

    //! A Node on this runtime opens (attach) and closes (detach). With none open the runtime's
    //! thread stops watching the master: it has no one to tell, and the process may be exiting,
    //! when rosconsole's objects can already be gone. The first attach checks at once.
    void attach();
    void detach();

private:
    Runtime(std::string name, std::string nameSpace);
    static void atExit();
    void stopForExit();

    void run(); //!< the runtime's thread
    void checkMaster();
    void start();
    void createPending();
    void dropRetired();
    void createPublisher(const std::shared_ptr<PublisherSlot> &slot);
    void createSubscriber(const std::shared_ptr<SubscriptionSlot> &slot);
    void registerAgain();

    const std::string m_name;      //!< as asked for, without namespace
    const std::string m_nameSpace; //!< as asked for (empty: ROS_NAMESPACE applies)
    std::string m_realtimeProblem; //!< why roscpp's threads are not real-time (runtime thread)
    std::atomic<State> m_state{State::Waiting};

    // The runtime's thread's own.
    bool m_waitingTold = false;   //!< "no master" was said
    bool m_registerAgain = false; //!< the master refused part of a registration: once more
    std::chrono::steady_clock::time_point m_nextCheck{};
    std::unique_ptr<::ros::NodeHandle> m_handle; //!< once roscpp started
    ::ros::CallbackQueue m_queue;                //!< subscription callbacks
    std::unique_ptr<::ros::AsyncSpinner> m_spinner;

    mutable std::mutex m_mutex; //!< guards what follows
    std::condition_variable m_wake;
    bool m_stopping = false;
    int m_users = 0;         //!< Nodes open on this runtime
    bool m_checkNow = false; //!< the first Node opened: check the master at once
    std::vector<std::shared_ptr<PublisherSlot>> m_publishers;
    std::vector<std::shared_ptr<SubscriptionSlot>> m_subscriptions;
    std::vector<std::shared_ptr<PublisherSlot>> m_newPublishers;
    std::vector<std::shared_ptr<SubscriptionSlot>> m_newSubscriptions;
    std::vector<::ros::Publisher> m_retiredPublishers;
    std::vector<::ros::Subscriber> m_retiredSubscribers;
    std::thread m_thread;
};

} // namespace hatpic::ros::ros1
