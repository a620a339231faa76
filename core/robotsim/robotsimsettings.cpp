#include "robotsim/robotsimsettings.h"

#include <charconv>
#include <cmath>

namespace hatpic::robot {

namespace {

// kSettings' row of an option both programs have: the same name, value name, help and range.
RobotSimOption shared(std::string_view key, RobotSimPlace place)
{
    const bridge::SettingSpec &spec = bridge::settingSpec(key);
    return {spec.key, spec.valueName, spec.help, place, spec.range};
}

std::optional<double> number(const std::string &text)
{
    std::size_t begin = text.find_first_not_of(" \t");
    std::size_t end = text.find_last_not_of(" \t");
    if (begin == std::string::npos)
        return std::nullopt;
    double v = 0;
    const char *first = text.data() + begin;
    const char *last = text.data() + end + 1;
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || ptr != last)
        return std::nullopt;
    return v;
}

} // namespace

const std::vector<RobotSimOption> &robotSimOptions()
{
    using bridge::SettingRange;
    static const std::vector<RobotSimOption> table = {
        shared("ros", RosPlace{}),
        shared("domain", DomainPlace{}),
        shared("namespace", NamespacePlace{}),
        {"axis", "AXIS", "Twist component followed, and the wrench's (default linear.x).",
         AxisPlace{}, std::nullopt},
        {"twist-topic", "TOPIC", "Reference in: geometry_msgs/TwistStamped (/hatpic/twist).",
         TopicPlace{&RobotSimSettings::twistTopic, false}, std::nullopt},
        {"wrench-topic", "TOPIC",
         "Estimated wrench out, best effort (/wrench_estimation; empty: off).",
         TopicPlace{&RobotSimSettings::wrenchTopic, true}, std::nullopt},
        {"pose-topic", "TOPIC", "Pose out, reliable (/robot/pose; empty: off).",
         TopicPlace{&RobotSimSettings::poseTopic, true}, std::nullopt},
        {"rate", "HZ", "Outputs per second (default 200; 0.1 to 1000).", &RobotSimSettings::rateHz,
         SettingRange{kMinRobotRateHz, kMaxRobotRateHz, "Hz"}},
        {"stale", "S", "v_ref = 0 once the last twist is this old (default 0.5 s).",
         &RobotSimSettings::staleAfter, SettingRange{0, kMaxRobotStale, "s", true}},
        {"mass", "KG", "Robot mass m (default 1.5 kg).", &RobotParams::mass, std::nullopt},
        {"kv", "NS/M", "Velocity gain K_v (default 40 N·s/m).", &RobotParams::kv, std::nullopt},
        {"fmax", "N", "Controller force limit F_max (default 20 N).", &RobotParams::fMax,
         std::nullopt},
        {"wall", "M", "Wall position x_w (default 0.05 m).", &RobotParams::wall, std::nullopt},
        {"wall-stiffness", "N/M",
         "Wall stiffness k_w (default 200 N/m; below the 1 ms step's stability bound).",
         &RobotParams::wallStiffness, std::nullopt},
        {"wall-damping", "NS/M", "Wall damping b_w (default 5 N·s/m).", &RobotParams::wallDamping,
         std::nullopt},
        {"start", "M", "Position at the start (default 0 m).", &RobotParams::start, std::nullopt},
        {"delay", "S", "Added one-way latency, both directions (default 0 s).", &LinkFaults::delay,
         std::nullopt},
        {"jitter", "S", "Uniform extra latency, order kept (default 0 s).", &LinkFaults::jitter,
         std::nullopt},
        {"loss", "P", "Fraction of messages dropped, both directions (default 0).",
         &LinkFaults::loss, std::nullopt},
        {"seed", "N", "Seed of the faults' randomness (default 1).", SeedPlace{}, std::nullopt},
    };
    return table;
}

std::string applyOption(const RobotSimOption &option, RobotSimSettings &s, const std::string &text)
{
    const auto toNumber = [&](double &target) -> std::string {
        const auto v = number(text);
        if (!v)
            return "needs a number";
        target = *v;
        return {};
    };
    return std::visit(
        Overloaded{
            [&](const TopicPlace &p) -> std::string {
                s.*p.member = text;
                return {};
            },
            [&](double RobotSimSettings::*m) { return toNumber(s.*m); },
            [&](double RobotParams::*m) { return toNumber(s.robot.*m); },
            [&](double LinkFaults::*m) { return toNumber(s.faults.*m); },
            [&](RosPlace) -> std::string {
                if (text == "2")
                    s.node.version = ros::RosVersion::Ros2;
                else if (text == "1" && ros::Node::isAvailable(ros::RosVersion::Ros1))
                    s.node.version = ros::RosVersion::Ros1;
                else if (text == "1")
                    return "ROS 1 is not built into this program";
                else
                    return "needs 1 or 2";
                return {};
            },
            [&](DomainPlace) -> std::string {
                const auto v = number(text);
                if (!v || !bridge::rangeProblem(*option.range, *v, true).empty())
                    return "needs " + bridge::rangeRule(*option.range, true);
                s.node.domainId = int(*v);
                return {};
            },
            [&](AxisPlace) -> std::string {
                const auto c = bridge::Component::parse(text);
                if (!c)
                    return "needs linear.x, linear.y, linear.z, angular.x, angular.y or angular.z";
                s.axis = *c;
                return {};
            },
            [&](NamespacePlace) -> std::string {
                s.node.nameSpace = text;
                return {};
            },
            [&](SeedPlace) -> std::string {
                std::uint64_t v = 0;
                const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
                if (text.empty() || ec != std::errc() || ptr != text.data() + text.size())
                    return "needs a whole number ≥ 0";
                s.seed = v;
                return {};
            },
        },
        option.place);
}

std::vector<std::string> validate(const RobotSimSettings &s)
{
    std::vector<std::string> out;
    for (const Violation &v : validate(s.robot))
        out.push_back(v.message());
    for (const Violation &v : validate(s.faults))
        out.push_back(v.message());
    if (const std::string problem = bridge::namespaceProblem(s.node.nameSpace); !problem.empty())
        out.push_back("namespace: " + problem);
    for (const RobotSimOption &option : robotSimOptions()) {
        const std::string key(option.key);
        if (const auto *topic = std::get_if<TopicPlace>(&option.place)) {
            const std::string &name = s.*topic->member;
            if (!(topic->output && name.empty()))
                if (const std::string problem = bridge::topicNameProblem(name); !problem.empty())
                    out.push_back(key + ": " + problem);
        } else if (const auto *m = std::get_if<double RobotSimSettings::*>(&option.place);
                   m && option.range) {
            if (const std::string problem = bridge::rangeProblem(*option.range, s.*(*m), false);
                !problem.empty())
                out.push_back(key + ": " + problem);
        }
    }
    return out;
}

} // namespace hatpic::robot
