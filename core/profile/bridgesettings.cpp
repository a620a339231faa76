#include "bridgesettings.h"

#include <cmath>

namespace hatpic::bridge {

namespace {

constexpr const char *kAxisLetters[] = {"x", "y", "z"};

// "name: must be …, got VALUE" unless `ok`.
void check(std::vector<std::string> &errors, bool ok, const std::string &name,
           const std::string &rule, double value)
{
    if (!ok)
        errors.push_back(name + ": must be " + rule + ", got " + formatNumber(value));
}

bool within(double value, double low, double high)
{
    return std::isfinite(value) && value >= low && value <= high;
}

} // namespace

std::string Component::twistName() const
{
    return std::string(angular ? "angular." : "linear.") + kAxisLetters[index];
}

std::string Component::wrenchName() const
{
    return std::string(angular ? "torque." : "force.") + kAxisLetters[index];
}

std::optional<Component> Component::parse(const std::string &text)
{
    for (const bool angular : {false, true}) {
        for (int index = 0; index < 3; ++index) {
            const Component c{angular, index};
            if (text == c.twistName() || text == c.wrenchName())
                return c;
        }
    }
    return std::nullopt;
}

std::string qosProfileName(QosProfile profile)
{
    return profile == QosProfile::Reliable ? "reliable" : "best-effort";
}

std::optional<QosProfile> parseQosProfile(const std::string &text)
{
    for (const QosProfile p : {QosProfile::Reliable, QosProfile::BestEffort}) {
        if (text == qosProfileName(p))
            return p;
    }
    return std::nullopt;
}

Component BridgeSettings::axisFor(ReferenceMode mode) const
{
    if (referenceAxis)
        return *referenceAxis;
    return mode == ReferenceMode::Rotation ? Component{true, 2} : Component{false, 0};
}

bool isValidTopicName(const std::string &name)
{
    if (name.empty() || name.size() > 200)
        return false;
    std::size_t start = name.front() == '/' ? 1 : 0;
    if (start == name.size())
        return false;
    while (start <= name.size()) {
        std::size_t end = name.find('/', start);
        if (end == std::string::npos)
            end = name.size();
        if (end == start)
            return false; // "//" or a trailing '/'
        if (name[start] >= '0' && name[start] <= '9')
            return false;
        for (std::size_t i = start; i < end; ++i) {
            const char c = name[i];
            const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                            (c >= '0' && c <= '9') || c == '_';
            if (!ok)
                return false;
        }
        start = end + 1;
    }
    return true;
}

BridgeSettings withNetworkOf(BridgeSettings settings, const BridgeSettings &network)
{
    settings.domainId = network.domainId;
    settings.rosVersion = network.rosVersion;
    return settings;
}

std::vector<std::string> validate(const BridgeSettings &s)
{
    std::vector<std::string> errors;
    const std::pair<const char *, const std::string *> topics[] = {
        {"joint states topic", &s.topics.jointStates},
        {"twist topic", &s.topics.twist},
        {"unstamped twist topic", &s.topics.twistUnstamped},
        {"pose topic", &s.topics.pose},
        {"feedback topic", &s.topics.feedback},
        {"wrench topic", &s.topics.wrench},
        {"unstamped wrench topic", &s.topics.wrenchUnstamped}};
    for (const auto &[what, topic] : topics) {
        if (!topic->empty() && !isValidTopicName(*topic))
            errors.push_back(std::string(what) + ": '" + echoedText(*topic) +
                             "' is not a ROS topic name (letters, digits and '_' between single "
                             "'/', not starting with a digit)");
    }
    check(errors, within(s.publishRateHz, 0, kMaxPublishRateHz) && s.publishRateHz > 0,
          "publish rate", "above 0 and at most " + formatNumber(kMaxPublishRateHz) + " Hz",
          s.publishRateHz);
    check(errors, within(s.feedback.gain, -kMaxFeedbackGain, kMaxFeedbackGain), "gain",
          "a finite number from -" + formatNumber(kMaxFeedbackGain) + " to " +
              formatNumber(kMaxFeedbackGain),
          s.feedback.gain);
    check(errors, within(s.feedback.limit, 0, kMaxFeedbackLimit), "limit",
          "from 0 to " + formatNumber(kMaxFeedbackLimit) + " N·m", s.feedback.limit);
    check(errors, within(s.feedback.staleAfter, 0, kMaxStaleAfter) && s.feedback.staleAfter > 0,
          "stale after", "above 0 and at most " + formatNumber(kMaxStaleAfter) + " s",
          s.feedback.staleAfter);
    for (int i = 0; i < 3; ++i) {
        check(errors, within(s.poseOrigin[i], -kMaxPoseOrigin, kMaxPoseOrigin),
              std::string("pose origin ") + kAxisLetters[i],
              "a finite number of metres within ±" + formatNumber(kMaxPoseOrigin), s.poseOrigin[i]);
    }
    check(errors, s.depth >= 1 && s.depth <= kMaxDepth, "depth",
          "a whole number from 1 to " + std::to_string(kMaxDepth), s.depth);
    check(errors, s.domainId >= 0 && s.domainId <= kMaxDomainId, "domain id",
          "a whole number from 0 to " + std::to_string(kMaxDomainId), s.domainId);
    check(errors, s.rosVersion == 1 || s.rosVersion == 2, "ROS version", "1 or 2", s.rosVersion);
    if (s.frameId.size() > 256)
        errors.push_back("frame id: must be at most 256 characters");
    if (s.jointName.empty() || s.jointName.size() > 256)
        errors.push_back("joint name: must be 1 to 256 characters");
    return errors;
}

} // namespace hatpic::bridge
