#include "ros/ros2/discovery.h"

#include <cstdlib>

namespace hatpic::ros::ros2 {

namespace {

// rmw's RMW_DISCOVERY_OPTIONS_STATIC_PEERS_MAX_LENGTH (256) less the terminating NUL.
constexpr std::size_t kMaxPeerLength = 255;

std::string environmentValue(const char *name)
{
    const char *value = std::getenv(name);
    return value ? value : "";
}

// rcutils_split(text, ';'): the entries between ';', empty ones dropped.
std::vector<std::string> splitPeers(const std::string &text)
{
    std::vector<std::string> peers;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find(';', start);
        if (end == std::string::npos)
            end = text.size();
        if (end > start)
            peers.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return peers;
}

} // namespace

DiscoveryEnvironment DiscoveryEnvironment::fromProcess()
{
    return {environmentValue("ROS_LOCALHOST_ONLY"),
            environmentValue("ROS_AUTOMATIC_DISCOVERY_RANGE"), environmentValue("ROS_STATIC_PEERS"),
            environmentValue("CYCLONEDDS_URI")};
}

const char *discoveryRangeName(DiscoveryRange range)
{
    switch (range) {
    case DiscoveryRange::Off:
        return "OFF";
    case DiscoveryRange::Localhost:
        return "LOCALHOST";
    case DiscoveryRange::Subnet:
        return "SUBNET";
    case DiscoveryRange::SystemDefault:
        return "SYSTEM_DEFAULT";
    }
    return "";
}

std::optional<Discovery> discoveryFrom(const DiscoveryEnvironment &environment, std::string *error)
{
    const auto fail = [&](const std::string &sentence) -> std::optional<Discovery> {
        if (error)
            *error = sentence;
        return std::nullopt;
    };
    Discovery discovery;
    if (environment.localhostOnly == "1") { // rcl: exactly "1"
        discovery.range = DiscoveryRange::Localhost;
        return discovery;
    }
    if (!environment.automaticRange.empty()) {
        bool known = false;
        for (const auto range : {DiscoveryRange::Off, DiscoveryRange::Localhost,
                                 DiscoveryRange::Subnet, DiscoveryRange::SystemDefault}) {
            if (environment.automaticRange == discoveryRangeName(range)) {
                discovery.range = range;
                known = true;
            }
        }
        if (!known)
            return fail("ROS_AUTOMATIC_DISCOVERY_RANGE must be SUBNET, LOCALHOST, OFF or "
                        "SYSTEM_DEFAULT (or unset), got '" +
                        environment.automaticRange + "'.");
    }
    if (discovery.range == DiscoveryRange::Off)
        return discovery; // rcl does not read the peers then
    for (const std::string &peer : splitPeers(environment.staticPeers)) {
        if (peer.size() > kMaxPeerLength)
            return fail("ROS_STATIC_PEERS: each address must be at most 255 characters, got one "
                        "of " +
                        std::to_string(peer.size()) + ".");
        if (peer.find_first_of("<>&\"'") != std::string::npos)
            return fail("ROS_STATIC_PEERS: an address must not contain < > & \" or ', got '" +
                        peer + "'.");
        discovery.staticPeers.push_back(peer);
    }
    return discovery;
}

std::string cycloneConfig(const Discovery &discovery, const std::string &cycloneUri, long pid)
{
    bool localhostPeer = false, staticPeers = false, noMulticast = false;
    switch (discovery.range) {
    case DiscoveryRange::Subnet:
        staticPeers = true;
        break;
    case DiscoveryRange::SystemDefault:
        break; // rmw warns that the static peers are ignored
    case DiscoveryRange::Localhost:
        localhostPeer = staticPeers = noMulticast = true;
        break;
    case DiscoveryRange::Off:
        noMulticast = true;
        break;
    }
    std::string config;
    if (localhostPeer || staticPeers || noMulticast) {
        config = "<CycloneDDS><Domain>";
        if (noMulticast)
            config += "<General><AllowMulticast>false</AllowMulticast></General>";
        if (noMulticast && !localhostPeer && !staticPeers) {
            // Off: a tag of this process alone, and no participant index (no fixed ports).
            config +=
                "<Discovery><ParticipantIndex>none</ParticipantIndex><Tag>ros_discovery_off_" +
                std::to_string(pid) + "</Tag>";
        } else {
            config += "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
                      "<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>";
        }
        const bool anyStatic = staticPeers && !discovery.staticPeers.empty();
        if (localhostPeer || anyStatic) {
            config += "<Peers>";
            if (localhostPeer)
                config += "<Peer address=\"localhost\"/>";
            if (staticPeers) {
                for (const std::string &peer : discovery.staticPeers)
                    config += "<Peer address=\"" + peer + "\"/>";
            }
            config += "</Peers>";
        }
        // An empty fragment is ignored, so the comma may always go in.
        config += "</Discovery></Domain></CycloneDDS>,";
    }
    return config + cycloneUri;
}

} // namespace hatpic::ros::ros2
