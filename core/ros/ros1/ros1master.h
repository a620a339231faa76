// What the ROS 1 runtime asks of the master and of roscpp beyond its usual API: a probe with a
// short timeout, whether the master still knows this node, registering everything again with
// a master that restarted, and TCP_NODELAY for the connections of our publishers. Called on
// the runtime's thread only (or at exit, once it has ended).
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace hatpic::ros::ros1 {

//! Whether a TCP connection to the master's host and port opens within `timeout` (roscpp's own
//! master calls wait for the master without limit).
bool masterReachable(std::chrono::milliseconds timeout);

enum class MasterLookup {
    Unreachable, //!< no answer
    Ours,        //!< the master knows this node at this process's XML-RPC URI
    Unknown,     //!< the master does not know this node: it restarted (or never had it)
    Other,       //!< another process registered this node's name (the master shuts us down)
};
//! The master's lookupNode of this node.
MasterLookup lookupSelf();

struct Registration
{
    int publishers = 0;    //!< topics advertised (roscpp's own /rosout included)
    int subscriptions = 0; //!< topics subscribed
    int services = 0;      //!< roscpp's logger services
    int refused = 0;       //!< calls the master refused or did not answer
};
//! Registers with the master again every topic this node advertises, roscpp's logger services
//! and `subscriptions` (resolved topic, ROS 1 type), and connects each subscription to the
//! publishers the master names besides those it is connected to already.
Registration registerAgain(const std::vector<std::pair<std::string, std::string>> &subscriptions);

//! Sets TCP_NODELAY on roscpp's TCPROS listening socket, so that every connection it accepts
//! (a subscriber of one of our topics) inherits it (Linux copies it to accepted sockets).
//! roscpp itself sets it on a publisher's socket only when the subscriber asks. False when the
//! socket was not found.
bool setNoDelayOnListener();

} // namespace hatpic::ros::ros1
