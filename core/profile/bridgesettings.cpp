#include "bridgesettings.h"

#include "model/paramtable.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace hatpic::bridge {

namespace {

constexpr const char *kAxisLetters[] = {"x", "y", "z"};

// "label: must be RULE, got VALUE" unless `value` is within the spec's range.
void checkRange(std::vector<std::string> &errors, const SettingSpec &spec, const std::string &label,
                double value, bool whole)
{
    if (const std::string problem = rangeProblem(spec.range, value, whole); !problem.empty())
        errors.push_back(label + ": " + problem);
}

void checkTopic(std::vector<std::string> &errors, const SettingSpec &spec, const std::string &topic)
{
    if (!topic.empty() && !isValidTopicName(topic))
        errors.push_back(std::string(spec.label) + ": " + topicNameProblem(topic));
}

void checkText(std::vector<std::string> &errors, const SettingSpec &spec, const std::string &text)
{
    if (text.size() < spec.range.low || text.size() > spec.range.high)
        errors.push_back(std::string(spec.label) + ": must be " +
                         (spec.range.low > 0 ? formatNumber(spec.range.low) + " to " : "at most ") +
                         formatNumber(spec.range.high) + " characters");
}

// Each topic its own name: an input that is one of the bridge's outputs would feed its own
// messages back as the robot's wrench (a loop); two outputs, or the two inputs, on one name
// would put two types on one topic (every pair of the bridge's topics differs in type).
void checkTopicsApart(std::vector<std::string> &errors, const BridgeSettings &s)
{
    const SettingSpec *seen[kSettings.size()] = {};
    std::size_t count = 0;
    for (const SettingSpec &spec : kSettings) {
        const auto *m = std::get_if<std::string Topics::*>(&spec.place);
        if (!m || (s.topics.*(*m)).empty())
            continue;
        const std::string &name = s.topics.*(*m);
        for (std::size_t i = 0; i < count; ++i) {
            const SettingSpec &other = *seen[i];
            if (s.topics.*std::get<std::string Topics::*>(other.place) != name)
                continue;
            const bool loop =
                isInputTopic(*m) != isInputTopic(std::get<std::string Topics::*>(other.place));
            errors.push_back(std::string(spec.label) + ": '" + echoedText(name) + "' is also the " +
                             std::string(other.label) +
                             (loop ? "; an input that is one of the bridge's own outputs would "
                                     "feed its messages back to it (a topic loop)"
                                   : "; two of the bridge's topics of different types cannot "
                                     "share a name"));
        }
        seen[count++] = &spec;
    }
}

constexpr SettingSpec setting(std::string_view key, std::string_view label, SettingPlace place,
                              SettingRange range, std::string_view valueName, std::string_view help,
                              bool inProfile = true)
{
    return {key, label, place, range, valueName, help, inProfile};
}

constexpr SettingSpec topic(std::string_view key, std::string_view label,
                            std::string Topics::*member, std::string_view help)
{
    return setting(key, label, member, {}, "NAME", help);
}

} // namespace

const std::array<SettingSpec, 27> kSettings = {
    // The network's (withNetworkOf()): no profile holds them.
    setting("ros", "ROS version", &BridgeSettings::rosVersion, {1, 2}, "VERSION",
            "2: ROS 2 over Cyclone DDS (default); 1: ROS 1 through roscpp (ROS_MASTER_URI).",
            false),
    setting("domain", "domain id", &BridgeSettings::domainId, {0, kMaxDomainId}, "ID",
            "DDS domain (default: ROS_DOMAIN_ID, else 0).", false),
    topic("joint_states_topic", "joint states topic", &Topics::jointStates,
          "sensor_msgs/JointState out (default /hatpic/joint_states; empty: none)."),
    topic("twist_topic", "twist topic", &Topics::twist,
          "geometry_msgs/TwistStamped out (default /hatpic/twist)."),
    topic("twist_unstamped_topic", "unstamped twist topic", &Topics::twistUnstamped,
          "geometry_msgs/Twist out, the same twist unstamped (default: none)."),
    topic("pose_topic", "pose topic", &Topics::pose,
          "geometry_msgs/PoseStamped out (default /hatpic/pose)."),
    topic("feedback_topic", "feedback topic", &Topics::feedback,
          "geometry_msgs/WrenchStamped out (default /hatpic/feedback)."),
    topic("wrench_topic", "wrench topic", &Topics::wrench,
          "geometry_msgs/WrenchStamped in (default /wrench_estimation)."),
    topic("wrench_unstamped_topic", "unstamped wrench topic", &Topics::wrenchUnstamped,
          "geometry_msgs/Wrench in (default: none)."),
    topic("enable_topic", "enable topic", &Topics::enable,
          "std_msgs/Bool in, a dead man: references and τ_ext only while true, released 0.5 s "
          "after the last message (default: none, always enabled)."),
    topic("joint_jog_topic", "joint jog topic", &Topics::jointJog,
          "control_msgs/JointJog out, for MoveIt Servo; ROS 2 only (default: none)."),
    topic("imu_topic", "IMU topic", &Topics::imu,
          "sensor_msgs/Imu out: the orientation of a board with a tilt sensor, written only for "
          "one (default /hatpic/imu)."),
    topic("axis_topic", "axis topic", &Topics::axis,
          "std_msgs/String in: the axis the knob drives, linear.x … angular.z, switched when the "
          "knob is next in its dead zone (default: none)."),
    topic("axis_index_topic", "axis index topic", &Topics::axisIndex,
          "std_msgs/UInt8 in: the same by number, 0 … 5 = linear.x … angular.z (default: none)."),
    setting("namespace", "namespace", &BridgeSettings::nodeNamespace, {0, 200}, "NS",
            "The node's namespace; default and relative topics go under it (default: none; "
            "ROS 1: ROS_NAMESPACE)."),
    setting("rate", "publish rate", &BridgeSettings::publishRateHz,
            {0, kMaxPublishRateHz, "Hz", true}, "HZ",
            "Messages per topic per second, at most (default 100)."),
    setting("frame_id", "frame id", &BridgeSettings::frameId, {0, 256}, "ID",
            "header.frame_id (default hatpic)."),
    setting("joint_name", "joint name", &BridgeSettings::jointName, {1, 256}, "NAME[,NAME…]",
            "JointState's and JointJog's joint name, one per knob and ',' between them; a knob "
            "not named is the first name with _N (default hatpic_knob)."),
    setting("axis", "axis", AxisPlace{}, {}, "AXIS",
            "Twist/pose axis: linear.x … angular.z, or auto (default: linear.x, angular.z in "
            "rotation mode)."),
    setting("knob_axes", "knob axes", &BridgeSettings::knobAxes, {1, 64}, "C2,C3,C4",
            "A board's knobs 2, 3, 4: twist/pose axis and wrench component fed back, three "
            "different ones (default linear.y,linear.z,angular.z)."),
    setting("origin", "pose origin", OriginPlace{}, {-1e6, 1e6, "m"}, "X,Y,Z",
            "Pose position origin [m] (default 0,0,0; MAVROS: 0,0,0.5)."),
    setting("component", "component", ComponentPlace{}, {}, "COMPONENT",
            "Wrench component fed back: force.x … torque.z (default force.z)."),
    setting("gain", "gain", &FeedbackSettings::gain, {-kMaxFeedbackGain, kMaxFeedbackGain},
            "NM_PER_N", "τ_ext per unit of the component (default 0.154)."),
    setting("limit", "limit", &FeedbackSettings::limit, {0, kMaxFeedbackLimit, "N·m"}, "NM",
            "|τ_ext| at most [N·m] (default 0.154)."),
    setting("stale", "stale after", &FeedbackSettings::staleAfter, {0, kMaxStaleAfter, "s", true},
            "S", "A wrench older than this gives τ_ext 0 (default 0.5)."),
    setting("qos", "QoS", QosPlace{}, {}, "PROFILE",
            "Publishers' reliability: reliable (default) or best-effort; subscriptions take "
            "either."),
    setting("depth", "depth", &BridgeSettings::depth, {1, 1000}, "N",
            "Publishers' history depth, keep last N (default 10)."),
};

std::string rangeRule(const SettingRange &range, bool whole)
{
    const std::string low = formatNumber(range.low);
    const std::string high = formatNumber(range.high);
    // Appended, not `" " + std::string(...)`: GCC 12 at -O3 reports a false -Wrestrict on the
    // operator+ of a literal and a temporary string.
    std::string unit;
    if (!range.unit.empty())
        unit.append(" ").append(range.unit);
    if (range.aboveLow)
        return "above " + low + " and at most " + high + unit;
    if (whole && range.high == range.low + 1)
        return low + " or " + high;
    return (whole ? "a whole number from " : "from ") + low + " to " + high + unit;
}

std::string rangeProblem(const SettingRange &range, double value, bool whole)
{
    const bool ok = std::isfinite(value) &&
                    (range.aboveLow ? value > range.low : value >= range.low) &&
                    value <= range.high && (!whole || value == std::floor(value));
    return ok ? std::string()
              : "must be " + rangeRule(range, whole) + ", got " + formatNumber(value);
}

std::string topicNameProblem(const std::string &topic)
{
    if (isValidTopicName(topic))
        return {};
    return "'" + echoedText(topic) +
           "' is not a ROS topic name (letters, digits and '_' between single '/', not starting "
           "with a digit)";
}

const SettingSpec &settingSpec(std::string_view key)
{
    for (const SettingSpec &spec : kSettings) {
        if (spec.key == key)
            return spec;
    }
    throw std::logic_error("no bridge setting " + std::string(key));
}

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

namespace {

//! `text` split at ','.
std::vector<std::string> splitAtCommas(const std::string &text)
{
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find(',', start);
        parts.push_back(text.substr(start, end == std::string::npos ? end : end - start));
        if (end == std::string::npos)
            return parts;
        start = end + 1;
    }
}

} // namespace

std::optional<std::array<Component, kMaxAxes - 1>> parseKnobAxes(const std::string &text)
{
    const std::vector<std::string> parts = splitAtCommas(text);
    if (parts.size() != kMaxAxes - 1)
        return std::nullopt;
    std::array<Component, kMaxAxes - 1> axes;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const auto c = Component::parse(parts[i]);
        if (!c || std::find(axes.begin(), axes.begin() + long(i), *c) != axes.begin() + long(i))
            return std::nullopt;
        axes[i] = *c;
    }
    return axes;
}

std::vector<std::string> jointNames(const std::string &text, int count)
{
    std::vector<std::string> names = splitAtCommas(text);
    for (const std::string &name : names) {
        if (name.empty() || std::count(names.begin(), names.end(), name) > 1)
            return {};
    }
    for (int n = int(names.size()) + 1; n <= count; ++n) {
        std::string added = names.front() + "_" + std::to_string(n);
        if (std::find(names.begin(), names.end(), added) != names.end())
            return {};
        names.push_back(std::move(added));
    }
    names.resize(std::size_t(count));
    return names;
}

std::string limitProblem(const FeedbackSettings &feedback, double tauLimit)
{
    if (!std::isfinite(tauLimit) || !(tauLimit > 0) ||
        atMostAsDeviceFloat(feedback.limit, tauLimit))
        return {};
    // The device's figure is a float32: its shortest float form ("0.44", not 0.4399999…).
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, float(tauLimit)).ptr;
    return "limit: must be at most the device's tau_limit (" + std::string(text, end) +
           " N·m), got " + formatNumber(feedback.limit);
}

bool isInputTopic(std::string Topics::*topic)
{
    return topic == &Topics::wrench || topic == &Topics::wrenchUnstamped ||
           topic == &Topics::enable || topic == &Topics::axis || topic == &Topics::axisIndex;
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

bool isValidNamespace(const std::string &name)
{
    return name.empty() || name == "/" ||
           isValidTopicName(name.front() == '/' ? name.substr(1) : name);
}

std::string namespaceProblem(const std::string &name)
{
    if (isValidNamespace(name))
        return {};
    return "'" + echoedText(name) +
           "' is not a ROS namespace (letters, digits and '_' between single '/', not starting "
           "with a digit)";
}

std::string topicInNamespace(const std::string &topic, const std::string &defaultTopic,
                             const std::string &ns)
{
    const std::string stripped = ns.starts_with('/') ? ns.substr(1) : ns;
    if (stripped.empty() || topic.empty())
        return topic;
    if (topic == defaultTopic || !topic.starts_with('/'))
        return "/" + stripped + (topic.starts_with('/') ? "" : "/") + topic;
    return topic;
}

BridgeSettings panelDefaults()
{
    BridgeSettings s;
    s.feedback.component = Component{false, 0};
    return s;
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
    for (const SettingSpec &spec : kSettings) {
        const std::string label(spec.label);
        std::visit(
            Overloaded{
                [&](std::string Topics::*m) { checkTopic(errors, spec, s.topics.*m); },
                [&](std::string BridgeSettings::*m) { checkText(errors, spec, s.*m); },
                [&](double BridgeSettings::*m) { checkRange(errors, spec, label, s.*m, false); },
                [&](double FeedbackSettings::*m) {
                    checkRange(errors, spec, label, s.feedback.*m, false);
                },
                [&](int BridgeSettings::*m) { checkRange(errors, spec, label, s.*m, true); },
                [&](OriginPlace) {
                    for (std::size_t i = 0; i < 3; ++i)
                        checkRange(errors, spec, label + " " + kAxisLetters[i], s.poseOrigin[i],
                                   false);
                },
                [](auto) {}, // an axis, a component or a QoS profile is valid by its type
            },
            spec.place);
    }
    if (const std::string problem = namespaceProblem(s.nodeNamespace); !problem.empty())
        errors.push_back("namespace: " + problem);
    if (!s.jointName.empty() && jointNames(s.jointName).empty())
        errors.push_back("joint name: must be names separated by ',', none empty and no two "
                         "alike, got '" +
                         echoedText(s.jointName) + "'");
    if (!s.knobAxes.empty() && !parseKnobAxes(s.knobAxes))
        errors.push_back("knob axes: must be three different components (linear.x … angular.z) "
                         "separated by ',', got '" +
                         echoedText(s.knobAxes) + "'");
    checkTopicsApart(errors, s);
    return errors;
}

} // namespace hatpic::bridge
