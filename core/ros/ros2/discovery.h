// ROS 2's discovery settings for our DDS participant, meaning what they mean for a node on
// rmw_cyclonedds (ros.md § Discovery): rcl reads ROS_LOCALHOST_ONLY,
// ROS_AUTOMATIC_DISCOVERY_RANGE and ROS_STATIC_PEERS (rcl/init.c, discovery_options.c), and
// rmw_cyclonedds turns the result into a Cyclone DDS configuration put before the user's
// CYCLONEDDS_URI (rmw_node.cpp, check_create_domain), so what the user's file sets wins.
// Plain C++, no DDS: the configuration is text for dds_create_domain().
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace hatpic::ros::ros2 {

//! The variables as the environment has them (unset and empty alike: "").
struct DiscoveryEnvironment
{
    std::string localhostOnly;  //!< ROS_LOCALHOST_ONLY (deprecated since Jazzy, still honoured)
    std::string automaticRange; //!< ROS_AUTOMATIC_DISCOVERY_RANGE
    std::string staticPeers;    //!< ROS_STATIC_PEERS: addresses separated by ';'
    std::string cycloneUri;     //!< CYCLONEDDS_URI

    static DiscoveryEnvironment fromProcess();
};

enum class DiscoveryRange {
    Off,           //!< no discovery beyond this process
    Localhost,     //!< this machine: no multicast, unicast to localhost's participant ports
    Subnet,        //!< the default: multicast as Cyclone DDS does it
    SystemDefault, //!< Cyclone DDS's own defaults, untouched
};
const char *discoveryRangeName(DiscoveryRange range); //!< "OFF", "LOCALHOST", …

struct Discovery
{
    DiscoveryRange range = DiscoveryRange::Subnet;
    std::vector<std::string> staticPeers; //!< used with Subnet and Localhost only

    friend bool operator==(const Discovery &, const Discovery &) = default;
};

//! Jazzy's rcl rules: ROS_LOCALHOST_ONLY starting with '1' means Localhost and no static
//! peers, whatever the other two say; else the range ("" is Subnet) and, unless it is Off,
//! the static peers (empty entries dropped). Where rcl would warn and guess (a range it does
//! not know: Localhost; a peer over 255 characters: skipped) this refuses instead: nullopt
//! with `*error` one sentence naming the variable, the rule and the value. A peer must also
//! not hold an XML special character (<>&"'), as it goes into the configuration.
std::optional<Discovery> discoveryFrom(const DiscoveryEnvironment &environment, std::string *error);

//! The configuration rmw_cyclonedds creates the domain with: its fragment for `discovery`
//! (none for SystemDefault), then `cycloneUri`, comma-separated; `pid` names the domain tag
//! that keeps a participant with range Off undiscoverable.
std::string cycloneConfig(const Discovery &discovery, const std::string &cycloneUri, long pid);

} // namespace hatpic::ros::ros2
