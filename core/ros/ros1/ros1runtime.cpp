#include "ros/ros1/ros1runtime.h"

#include "ros/ros1/ros1master.h"
#include "ros/ros1/ros1messages.h"

#include "realtime/realtime.h"

#include <pthread.h>
#include <sched.h>

#include <ros/console.h>
#include <ros/init.h>
#include <ros/master.h>
#include <ros/names.h>
#include <ros/network.h>
#include <ros/node_handle.h>
#include <ros/this_node.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>

namespace hatpic::ros::ros1 {

namespace {

constexpr std::chrono::milliseconds kProbeTimeout{300};

std::mutex g_acquireMutex;
//! The process's runtime. Never deleted: roscpp cannot start again after it shut down, so the
//! runtime lives as long as the process (and stays reachable for leak checkers).
Runtime *g_runtime = nullptr;

// Empty, or why ROS_MASTER_URI cannot be used (roscpp would abort the process on it).
std::string masterUriProblem()
{
    const char *value = std::getenv("ROS_MASTER_URI");
    if (!value)
        return {};
    const std::string uri = value;
    std::string host;
    std::uint32_t port = 0;
    if (uri.rfind("http://", 0) == 0 && ::ros::network::splitURI(uri, host, port) &&
        !host.empty() && port > 0 && port < 65536)
        return {};
    return "ROS_MASTER_URI must be http://HOST:PORT, got '" + uri + "'.";
}

template<typename Slot> void eraseSlot(std::vector<std::shared_ptr<Slot>> &slots, const Slot *slot)
{
    slots.erase(std::remove_if(slots.begin(), slots.end(),
                               [slot](const auto &s) { return s.get() == slot; }),
                slots.end());
}

template<typename Slot>
bool hasSlot(const std::vector<std::shared_ptr<Slot>> &slots, const Slot *slot)
{
    return std::any_of(slots.begin(), slots.end(),
                       [slot](const auto &s) { return s.get() == slot; });
}

} // namespace

void SubscriptionSlot::deliver(const Message &message)
{
    const std::lock_guard lock(mutex);
    if (handler)
        handler(message);
}

Runtime::Runtime(std::string name, std::string nameSpace)
    : m_name(std::move(name)), m_nameSpace(std::move(nameSpace))
{}

Runtime *Runtime::acquire(const std::string &name, const std::string &nameSpace, std::string *error)
{
    const auto fail = [error](const std::string &sentence) -> Runtime * {
        if (error)
            *error = sentence;
        return nullptr;
    };
    const std::lock_guard lock(g_acquireMutex);
    if (g_runtime) {
        if (g_runtime->m_name != name || g_runtime->m_nameSpace != nameSpace)
            return fail("ROS 1 allows one node per process, and this process's node is " +
                        g_runtime->nodeName() + ": it cannot also be '" + name + "'" +
                        (nameSpace.empty() ? "" : " in '" + nameSpace + "'") + ".");
        if (g_runtime->state() == State::Dead)
            return fail("This process's ROS 1 node " + g_runtime->nodeName() +
                        " was shut down by its master, and roscpp cannot start it again: "
                        "restart the program.");
        return g_runtime;
    }
    if (const std::string problem = masterUriProblem(); !problem.empty())
        return fail(problem);
    try {
        // "__ns" as a remapping, as `_ns:=` on a command line: it wins over ROS_NAMESPACE.
        ::ros::M_string remappings;
        if (!nameSpace.empty())
            remappings["__ns"] = nameSpace;
        ::ros::init(remappings, name, ::ros::init_options::NoSigintHandler);
    } catch (const std::exception &e) {
        return fail("roscpp refused the node '" + name + "': " + e.what() +
                    " (check ROS_NAMESPACE).");
    }
    // Master calls made while it is gone give up instead of waiting for ever (they run on the
    // runtime's thread, which must keep checking).
    ::ros::master::setRetryTimeout(::ros::WallDuration(kMasterRetryTimeoutS));
    g_runtime = new Runtime(name, nameSpace);
    std::atexit(&Runtime::atExit); // before roscpp's last handler, registered by ros::init
    g_runtime->m_thread = std::thread(&Runtime::run, g_runtime);
    return g_runtime;
}

std::string Runtime::masterUri() const
{
    return ::ros::master::getURI();
}

std::string Runtime::nodeName() const
{
    return ::ros::this_node::getName();
}

std::string Runtime::resolve(const std::string &topic, std::string *error) const
{
    std::string why;
    try {
        if (!topic.empty() && ::ros::names::validate(topic, why))
            return ::ros::names::resolve(topic);
    } catch (const std::exception &e) {
        why = e.what();
    }
    if (error)
        *error =
            "'" + topic + "' is not a ROS 1 topic name" + (why.empty() ? "" : ": " + why) + ".";
    return {};
}

std::string Runtime::typeConflict(const std::string &topic, MessageType type) const
{
    const std::lock_guard lock(m_mutex);
    const auto clash = [&](const auto &slots) -> std::string {
        for (const auto &s : slots) {
            if (s->topic == topic && s->type != type)
                return "ROS 1 allows one type per topic in a node: " + topic + " is already " +
                       rosTypeName1(s->type) + " here, not " + rosTypeName1(type) + ".";
        }
        return {};
    };
    std::string problem = clash(m_publishers);
    return problem.empty() ? clash(m_subscriptions) : problem;
}

void Runtime::add(const std::shared_ptr<PublisherSlot> &slot)
{
    const std::lock_guard lock(m_mutex);
    m_publishers.push_back(slot);
    m_newPublishers.push_back(slot);
    m_wake.notify_all();
}

void Runtime::add(const std::shared_ptr<SubscriptionSlot> &slot)
{
    const std::lock_guard lock(m_mutex);
    m_subscriptions.push_back(slot);
    m_newSubscriptions.push_back(slot);
    m_wake.notify_all();
}

void Runtime::remove(const std::shared_ptr<PublisherSlot> &slot)
{
    const std::lock_guard lock(m_mutex);
    eraseSlot(m_publishers, slot.get());
    eraseSlot(m_newPublishers, slot.get());
    const std::lock_guard slotLock(slot->mutex);
    if (slot->publisher) {
        // Unadvertising talks to the master: the runtime's thread does it.
        m_retiredPublishers.push_back(slot->publisher);
        slot->publisher = ::ros::Publisher();
        m_wake.notify_all();
    }
}

void Runtime::remove(const std::shared_ptr<SubscriptionSlot> &slot)
{
    {
        const std::lock_guard handlerLock(slot->mutex); // waits for a handler that runs
        slot->handler = nullptr;
    }
    const std::lock_guard lock(m_mutex);
    eraseSlot(m_subscriptions, slot.get());
    eraseSlot(m_newSubscriptions, slot.get());
    if (slot->subscriber) {
        m_retiredSubscribers.push_back(slot->subscriber);
        slot->subscriber = ::ros::Subscriber();
        m_wake.notify_all();
    }
}

void Runtime::attach()
{
    const std::lock_guard lock(m_mutex);
    if (m_users++ == 0) {
        m_checkNow = true; // what became of the master meanwhile is checked at once
        m_wake.notify_all();
    }
}

void Runtime::detach()
{
    const std::lock_guard lock(m_mutex);
    --m_users;
}

void Runtime::atExit()
{
    if (g_runtime)
        g_runtime->stopForExit();
}

void Runtime::stopForExit()
{
    {
        const std::lock_guard lock(m_mutex);
        if (m_stopping)
            return;
        m_stopping = true;
        m_wake.notify_all();
    }
    if (m_thread.joinable() && m_thread.get_id() != std::this_thread::get_id())
        m_thread.join();
    if (m_spinner)
        m_spinner->stop();
    if (!m_handle || !::ros::ok())
        return; // never registered, or shut down by its master (which dropped it)
    if (m_state != State::Connected || !masterReachable(kProbeTimeout)) {
        // No master to unregister from (a call to one that is gone could wait for TCP's
        // timeout): roscpp's exit handler ends the node, and its master calls give up at once.
        ::ros::master::setRetryTimeout(::ros::WallDuration(0.001));
        return;
    }
    // roscpp's own exit handler (Debian's 1.15: atexitCallback in init.cpp) shuts down without
    // its topic and service managers, so it unregisters nothing: the node, /rosout and the
    // logger services stayed on the master. ros::shutdown() here, while those managers still
    // exist (they were made before this handler was registered), unregisters everything.
    ::ros::shutdown();
}

void Runtime::run()
{
    std::unique_lock lock(m_mutex);
    while (!m_stopping) {
        const bool check =
            m_users > 0 && (m_checkNow || std::chrono::steady_clock::now() >= m_nextCheck);
        m_checkNow = false;
        lock.unlock();
        if (check) {
            checkMaster();
            m_nextCheck = std::chrono::steady_clock::now() + kCheckInterval;
        }
        if (m_state == State::Connected)
            createPending();
        dropRetired();
        lock.lock();
        const auto woken = [this] {
            const bool pending = !m_newPublishers.empty() || !m_newSubscriptions.empty();
            return m_stopping || (m_checkNow && m_users > 0) ||
                   (pending && m_state == State::Connected) || !m_retiredPublishers.empty() ||
                   !m_retiredSubscribers.empty();
        };
        if (m_users > 0)
            m_wake.wait_until(lock, m_nextCheck, woken);
        else
            m_wake.wait(lock, woken); // no master to watch for no one
    }
}

void Runtime::checkMaster()
{
    const std::string uri = masterUri();
    const char *how = std::getenv("ROS_MASTER_URI") ? "ROS_MASTER_URI" : "the default";
    if (m_state == State::Dead)
        return;
    if (!m_handle) {
        if (masterReachable(kProbeTimeout) && ::ros::master::check()) {
            start();
        } else if (!m_waitingTold) {
            ROS_WARN("No ROS 1 master at %s (%s): %s tries again every second.", uri.c_str(), how,
                     nodeName().c_str());
            m_waitingTold = true;
        }
        return;
    }
    if (!::ros::ok()) {
        m_state = State::Dead;
        // roscpp turned its logging off inside ros::shutdown(): ROS_ERROR would say nothing.
        // So stderr directly, and a program whose node is its purpose ends, non-zero: a node
        // its master shut down cannot start again (roscpp), and running on with frozen
        // counters helps no one. The master has already dropped the node.
        const bool exit = exitsWhenShutDownByMaster();
        std::fprintf(stderr,
                     "%s: The ROS 1 node %s was shut down by its master at %s (another node took "
                     "its name); %s.\n",
                     program_invocation_short_name, nodeName().c_str(), uri.c_str(),
                     exit ? "exiting" : "restart the program to use ROS 1 again");
        std::fflush(stdout);
        std::fflush(stderr);
        if (exit)
            std::_Exit(kExitShutDownByMaster);
        return;
    }
    const MasterLookup lookup =
        masterReachable(kProbeTimeout) ? lookupSelf() : MasterLookup::Unreachable;
    switch (lookup) {
    case MasterLookup::Unreachable:
        if (m_state == State::Connected) {
            ROS_WARN("Lost the ROS 1 master at %s: %s keeps its connections and tries again "
                     "every second.",
                     uri.c_str(), nodeName().c_str());
            m_state = State::Lost;
        }
        break;
    case MasterLookup::Ours:
        if (m_state == State::Lost) {
            ROS_INFO("The ROS 1 master at %s answers again.", uri.c_str());
            m_state = State::Connected;
        }
        if (m_registerAgain)
            registerAgain();
        break;
    case MasterLookup::Unknown:
        registerAgain();
        m_state = State::Connected;
        break;
    case MasterLookup::Other:
        break; // the master shuts this node down; the next check says so
    }
}

void Runtime::start()
{
    // roscpp's threads (the poll thread that reads every connection, and the spinner's that
    // runs the handlers, below) inherit this thread's scheduling as they are created: made
    // real-time for their creation where the system allows it, this thread then goes back.
    sched_param normal{};
    int normalPolicy = SCHED_OTHER;
    pthread_getschedparam(pthread_self(), &normalPolicy, &normal);
    m_realtimeProblem = realtime::makeThreadRealtime();
    ::ros::start();
    if (!::ros::ok()) {
        pthread_setschedparam(pthread_self(), normalPolicy, &normal);
        m_state = State::Dead;
        return;
    }
    // roscpp's exit handler (registered by ros::init) and its managers (made by now) come
    // before this one, which therefore runs first: it stops this thread and the spinner, then
    // shuts roscpp down while its managers still exist, so that it unregisters (stopForExit).
    std::atexit(&Runtime::atExit);
    m_handle = std::make_unique<::ros::NodeHandle>();
    if (!setNoDelayOnListener())
        ROS_WARN("Cannot set TCP_NODELAY for the subscribers of %s's topics: messages to them may "
                 "wait for Nagle's algorithm.",
                 nodeName().c_str());
    m_spinner = std::make_unique<::ros::AsyncSpinner>(1, &m_queue);
    m_spinner->start();
    pthread_setschedparam(pthread_self(), normalPolicy, &normal);
    if (!m_realtimeProblem.empty())
        ROS_WARN("%s's callback threads: %s.", nodeName().c_str(), m_realtimeProblem.c_str());
    m_state = State::Connected;
    ROS_INFO("%s is registered with the ROS 1 master at %s.", nodeName().c_str(),
             masterUri().c_str());
}

void Runtime::createPending()
{
    std::vector<std::shared_ptr<PublisherSlot>> publishers;
    std::vector<std::shared_ptr<SubscriptionSlot>> subscriptions;
    {
        const std::lock_guard lock(m_mutex);
        publishers.swap(m_newPublishers);
        subscriptions.swap(m_newSubscriptions);
    }
    for (const auto &slot : publishers)
        createPublisher(slot);
    for (const auto &slot : subscriptions)
        createSubscriber(slot);
}

void Runtime::createPublisher(const std::shared_ptr<PublisherSlot> &slot)
{
    ::ros::Publisher publisher;
    try {
        publisher = visitType(slot->type, [&](auto tag) {
            ::ros::AdvertiseOptions options;
            options.template init<typename decltype(tag)::Type>(slot->topic,
                                                                std::uint32_t(slot->queueSize));
            return m_handle->advertise(options);
        });
    } catch (const std::exception &e) {
        ROS_ERROR("Cannot publish %s: %s", slot->topic.c_str(), e.what());
    }
    const std::lock_guard lock(m_mutex);
    if (!hasSlot(m_publishers, slot.get())) {
        if (publisher)
            m_retiredPublishers.push_back(publisher); // removed meanwhile
        return;
    }
    const std::lock_guard slotLock(slot->mutex);
    slot->publisher = publisher;
}

void Runtime::createSubscriber(const std::shared_ptr<SubscriptionSlot> &slot)
{
    ::ros::Subscriber subscriber;
    const std::weak_ptr<SubscriptionSlot> target = slot;
    try {
        subscriber = visitType(slot->type, [&](auto tag) {
            using M = typename decltype(tag)::Type;
            // The node never hears its own publications: roscpp names the publisher of each
            // message by its caller id (the connection header's, or the node's own for a
            // message published in this process), and this node's are dropped.
            const std::string self = nodeName();
            const boost::function<void(const ::ros::MessageEvent<M const> &)> callback =
                [target, self](const ::ros::MessageEvent<M const> &event) {
                    if (event.getPublisherName() == self)
                        return;
                    if (const auto s = target.lock())
                        s->deliver(Message(fromRos(*event.getConstMessage())));
                };
            ::ros::SubscribeOptions options;
            options.template initByFullCallbackType<const ::ros::MessageEvent<M const> &>(
                slot->topic, std::uint32_t(slot->queueSize), callback);
            options.transport_hints = ::ros::TransportHints().tcpNoDelay();
            options.callback_queue = &m_queue;
            return m_handle->subscribe(options);
        });
    } catch (const std::exception &e) {
        ROS_ERROR("Cannot subscribe to %s: %s", slot->topic.c_str(), e.what());
    }
    const std::lock_guard lock(m_mutex);
    if (!hasSlot(m_subscriptions, slot.get())) {
        if (subscriber)
            m_retiredSubscribers.push_back(subscriber);
        return;
    }
    slot->subscriber = subscriber;
}

void Runtime::dropRetired()
{
    std::vector<::ros::Publisher> publishers;
    std::vector<::ros::Subscriber> subscribers;
    {
        const std::lock_guard lock(m_mutex);
        publishers.swap(m_retiredPublishers);
        subscribers.swap(m_retiredSubscribers);
    }
    // Leaving scope unregisters them with the master (when no other handle shares the topic).
}

void Runtime::registerAgain()
{
    std::vector<std::pair<std::string, std::string>> subscriptions;
    {
        const std::lock_guard lock(m_mutex);
        for (const auto &s : m_subscriptions) {
            const std::pair<std::string, std::string> entry{s->topic, rosTypeName1(s->type)};
            if (s->subscriber &&
                std::find(subscriptions.begin(), subscriptions.end(), entry) == subscriptions.end())
                subscriptions.push_back(entry);
        }
    }
    const Registration r = ros1::registerAgain(subscriptions);
    m_registerAgain = r.refused > 0;
    ROS_WARN("The ROS 1 master at %s did not know %s (it restarted): registered %d topics "
             "published and %d subscribed with it again%s.",
             masterUri().c_str(), nodeName().c_str(), r.publishers, r.subscriptions,
             r.refused ? ", some refused; trying again in a second" : "");
}

} // namespace hatpic::ros::ros1
