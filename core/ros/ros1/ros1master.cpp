#include "ros/ros1/ros1master.h"

#include <ros/connection_manager.h>
#include <ros/master.h>
#include <ros/names.h>
#include <ros/network.h>
#include <ros/publication.h>
#include <ros/service_manager.h>
#include <ros/this_node.h>
#include <ros/topic_manager.h>
#include <ros/xmlrpc_manager.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace hatpic::ros::ros1 {

namespace {

using XmlRpc::XmlRpcValue;

// A method of this node's own XML-RPC server (the slave API), as the master would call it.
bool callSelf(const std::string &method, const XmlRpcValue &args, XmlRpcValue &payload)
{
    const ::ros::XMLRPCManagerPtr &manager = ::ros::XMLRPCManager::instance();
    std::string host;
    std::uint32_t port = 0;
    if (!::ros::network::splitURI(manager->getServerURI(), host, port))
        return false;
    XmlRpc::XmlRpcClient *client = manager->getXMLRPCClient(host, int(port), "/");
    XmlRpcValue response;
    const bool ok = client->execute(method.c_str(), args, response) &&
                    manager->validateXmlrpcResponse(method, response, payload);
    manager->releaseXMLRPCClient(client);
    return ok;
}

// The XML-RPC URIs of the publishers `topic`'s subscription is connected to (getBusInfo).
std::vector<std::string> connectedPublishers(const std::string &topic)
{
    XmlRpcValue args, info;
    args[0] = ::ros::this_node::getName();
    std::vector<std::string> uris;
    if (!callSelf("getBusInfo", args, info) || info.getType() != XmlRpcValue::TypeArray)
        return uris;
    for (int i = 0; i < info.size(); ++i) {
        XmlRpcValue &c = info[i];
        if (c.getType() != XmlRpcValue::TypeArray || c.size() < 5)
            continue;
        if (c[1].getType() == XmlRpcValue::TypeString &&
            c[2].getType() == XmlRpcValue::TypeString &&
            c[4].getType() == XmlRpcValue::TypeString && std::string(c[2]) == "i" &&
            std::string(c[4]) == topic)
            uris.push_back(std::string(c[1]));
    }
    return uris;
}

int portOf(const sockaddr_storage &address)
{
    if (address.ss_family == AF_INET) {
        sockaddr_in in;
        std::memcpy(&in, &address, sizeof in);
        return ntohs(in.sin_port);
    }
    if (address.ss_family == AF_INET6) {
        sockaddr_in6 in6;
        std::memcpy(&in6, &address, sizeof in6);
        return ntohs(in6.sin6_port);
    }
    return -1;
}

} // namespace

bool masterReachable(std::chrono::milliseconds timeout)
{
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo *list = nullptr;
    const std::string port = std::to_string(::ros::master::getPort());
    if (::getaddrinfo(::ros::master::getHost().c_str(), port.c_str(), &hints, &list) != 0)
        return false;
    bool reached = false;
    for (const addrinfo *a = list; a && !reached; a = a->ai_next) {
        const int fd =
            ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
        if (fd < 0)
            continue;
        if (::connect(fd, a->ai_addr, a->ai_addrlen) == 0) {
            reached = true;
        } else if (errno == EINPROGRESS) {
            pollfd p{fd, POLLOUT, 0};
            if (::poll(&p, 1, int(timeout.count())) == 1) {
                int error = 0;
                socklen_t length = sizeof error;
                reached =
                    ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length) == 0 && error == 0;
            }
        }
        ::close(fd);
    }
    ::freeaddrinfo(list);
    return reached;
}

MasterLookup lookupSelf()
{
    XmlRpcValue args, response, payload;
    args[0] = ::ros::this_node::getName();
    args[1] = ::ros::this_node::getName();
    if (::ros::master::execute("lookupNode", args, response, payload, false)) {
        const bool ours = payload.getType() == XmlRpcValue::TypeString &&
                          std::string(payload) == ::ros::XMLRPCManager::instance()->getServerURI();
        return ours ? MasterLookup::Ours : MasterLookup::Other;
    }
    // An answer with an error code ("unknown node") rather than none at all.
    const bool answered = response.getType() == XmlRpcValue::TypeArray && response.size() >= 1 &&
                          response[0].getType() == XmlRpcValue::TypeInt;
    return answered ? MasterLookup::Unknown : MasterLookup::Unreachable;
}

Registration registerAgain(const std::vector<std::pair<std::string, std::string>> &subscriptions)
{
    Registration done;
    const std::string me = ::ros::this_node::getName();
    const std::string api = ::ros::XMLRPCManager::instance()->getServerURI();
    const auto call = [&](const char *method, const XmlRpcValue &args, XmlRpcValue &payload) {
        XmlRpcValue response;
        const bool ok = ::ros::master::execute(method, args, response, payload, false);
        if (!ok)
            ++done.refused;
        return ok;
    };

    std::vector<std::string> topics;
    ::ros::TopicManager::instance()->getAdvertisedTopics(topics);
    for (const std::string &topic : topics) {
        const ::ros::PublicationPtr publication =
            ::ros::TopicManager::instance()->lookupPublication(topic);
        if (!publication)
            continue;
        XmlRpcValue args, payload;
        args[0] = me;
        args[1] = topic;
        args[2] = publication->getDataType();
        args[3] = api;
        if (call("registerPublisher", args, payload))
            ++done.publishers;
    }

    const std::string serviceApi =
        "rosrpc://" + ::ros::network::getHost() + ":" +
        std::to_string(::ros::ConnectionManager::instance()->getTCPPort());
    for (const char *name : {"~get_loggers", "~set_logger_level"}) {
        const std::string service = ::ros::names::resolve(name);
        if (!::ros::ServiceManager::instance()->lookupServicePublication(service))
            continue;
        XmlRpcValue args, payload;
        args[0] = me;
        args[1] = service;
        args[2] = serviceApi;
        args[3] = api;
        if (call("registerService", args, payload))
            ++done.services;
    }

    for (const auto &[topic, type] : subscriptions) {
        XmlRpcValue args, payload;
        args[0] = me;
        args[1] = topic;
        args[2] = type;
        args[3] = api;
        if (!call("registerSubscriber", args, payload))
            continue;
        ++done.subscriptions;
        // The master's publishers, and those still connected from before (a publisher that has
        // not registered again yet keeps sending).
        std::vector<std::string> publishers = connectedPublishers(topic);
        for (int i = 0; payload.getType() == XmlRpcValue::TypeArray && i < payload.size(); ++i) {
            if (payload[i].getType() != XmlRpcValue::TypeString)
                continue;
            const std::string uri = payload[i];
            if (std::find(publishers.begin(), publishers.end(), uri) == publishers.end())
                publishers.push_back(uri);
        }
        XmlRpcValue update, list, ignored;
        list.setSize(int(publishers.size()));
        for (std::size_t i = 0; i < publishers.size(); ++i)
            list[int(i)] = publishers[i];
        update[0] = me;
        update[1] = topic;
        update[2] = list;
        if (!callSelf("publisherUpdate", update, ignored))
            ++done.refused;
    }
    return done;
}

bool setNoDelayOnListener()
{
    const int port = int(::ros::ConnectionManager::instance()->getTCPPort());
    bool set = false;
    std::error_code error;
    for (const auto &entry : std::filesystem::directory_iterator("/proc/self/fd", error)) {
        const int fd = std::atoi(entry.path().filename().c_str());
        struct stat status;
        if (::fstat(fd, &status) != 0 || !S_ISSOCK(status.st_mode))
            continue;
        int listening = 0;
        socklen_t length = sizeof listening;
        if (::getsockopt(fd, SOL_SOCKET, SO_ACCEPTCONN, &listening, &length) != 0 || !listening)
            continue;
        sockaddr_storage address{};
        socklen_t addressLength = sizeof address;
        if (::getsockname(fd, reinterpret_cast<sockaddr *>(&address), &addressLength) != 0 ||
            portOf(address) != port)
            continue;
        const int one = 1;
        if (::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one) == 0)
            set = true;
    }
    return set;
}

} // namespace hatpic::ros::ros1
