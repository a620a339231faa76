// What the robot bridge publishes and subscribes, and how a wrench becomes feedback (ros.md).
// Plain values with their defaults; no DDS, no Qt.
#pragma once

#include "model/axes.h"
#include "model/overloaded.h"
#include "model/params.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace hatpic::bridge {

//! One component of a twist or wrench: linear.x … angular.z (force.x … torque.z).
struct Component
{
    bool angular = false; //!< angular (torque) rather than linear (force)
    int index = 0;        //!< 0 = x, 1 = y, 2 = z

    //! "linear.x", "angular.z"; a wrench reads the same indices as "force.x", "torque.z".
    std::string twistName() const;
    std::string wrenchName() const;
    //! Accepts both spellings ("linear.x" or "force.x"); nullopt for anything else.
    static std::optional<Component> parse(const std::string &text);
    //! Its place in a twist's or wrench's six values: linear (force) x y z, angular (torque)
    //! x y z.
    constexpr int slot() const { return (angular ? 3 : 0) + index; }
    //! The component in that place (0 … 5); nullopt for any other number.
    static constexpr std::optional<Component> fromSlot(int slot)
    {
        if (slot < 0 || slot >= 6)
            return std::nullopt;
        return Component{slot >= 3, slot % 3};
    }

    friend bool operator==(const Component &, const Component &) = default;
};

//! The reliability of the bridge's publishers (its subscriptions take any: ros.md § QoS).
enum class QosProfile {
    Reliable,   //!< reliable, volatile, keep last `depth` (ROS 2's default)
    BestEffort, //!< best effort, volatile, keep last `depth` (ROS 2's sensor data reliability)
};
std::string qosProfileName(QosProfile profile); //!< "reliable", "best-effort"
std::optional<QosProfile> parseQosProfile(const std::string &text);

//! ROS topic names (a leading '/' as in `ros2 topic list`); an empty name is not used.
struct Topics
{
    std::string jointStates = "/hatpic/joint_states"; //!< out: sensor_msgs/JointState
    std::string twist = "/hatpic/twist";              //!< out: geometry_msgs/TwistStamped
    std::string twistUnstamped;                       //!< out: geometry_msgs/Twist (off)
    std::string pose = "/hatpic/pose";                //!< out: geometry_msgs/PoseStamped
    std::string feedback = "/hatpic/feedback";        //!< out: geometry_msgs/WrenchStamped
    std::string wrench = "/wrench_estimation";        //!< in: geometry_msgs/WrenchStamped
    std::string wrenchUnstamped;                      //!< in: geometry_msgs/Wrench (off)
    std::string enable;                               //!< in: std_msgs/Bool, dead man (off)
    std::string jointJog;                             //!< out: control_msgs/JointJog (off)
    std::string imu = "/hatpic/imu"; //!< out: sensor_msgs/Imu, a board's tilt (only then)
    //! in: std_msgs/String, the axis knob 1 is to drive ("linear.y"), by name (off)
    std::string axis;
    //! in: std_msgs/UInt8, the same by its place: 0 … 5 = linear x y z, angular x y z (off)
    std::string axisIndex;

    friend bool operator==(const Topics &, const Topics &) = default;
};

//! Wrench → τ_ext. The defaults reproduce the published driver: force.z × 350 load units,
//! clamped to ±350, where ±1000 load units are tau_limit (0.44 N·m): 0.154 N·m per N, ±0.154.
struct FeedbackSettings
{
    Component component{false, 2}; //!< force.z
    double gain = 0.154;           //!< τ_ext per unit of the component [N·m/N or N·m/(N·m)]
    double limit = 0.154;          //!< |τ_ext| at most [N·m]
    double staleAfter = 0.5;       //!< a wrench older than this gives τ_ext = 0 [s]

    friend bool operator==(const FeedbackSettings &, const FeedbackSettings &) = default;
};

struct BridgeSettings
{
    Topics topics;
    double publishRateHz = 100;     //!< messages per topic per second, at most [Hz]
    std::string frameId = "hatpic"; //!< header.frame_id of every message out
    //! JointState's and JointJog's joint names, ',' between knobs' (knob 1 first): jointNames().
    std::string jointName = "hatpic_knob";
    //! The node's namespace ("knob1", "lab/knob1"; empty: the root, or ROS_NAMESPACE on ROS 1).
    //! The node and every topic at its default value, or relative, go under it.
    std::string nodeNamespace;
    std::optional<Component> referenceAxis; //!< unset: linear.x, angular.z in rotation mode
    //! The components of knobs 2, 3, 4 on a board with several (the IMU branch's), ','
    //! between them: their references on the twist and pose, their wrench component fed back
    //! (parseKnobAxes()). The published ROS script's y, z and yaw.
    std::string knobAxes = "linear.y,linear.z,angular.z";
    std::array<double, 3> poseOrigin{};    //!< added to the pose's position [m]
    FeedbackSettings feedback;             //!< the wrench that comes back
    QosProfile qos = QosProfile::Reliable; //!< of the publishers (topics out)
    int depth = 10;                        //!< keep last N, of the publishers
    int domainId = 0;                      //!< DDS domain (ROS_DOMAIN_ID)
    int rosVersion = 2;                    //!< 2: ROS 2 over Cyclone DDS; 1: ROS 1 (roscpp)

    //! The axis the references go on for the given reference mode.
    Component axisFor(ReferenceMode mode) const;

    friend bool operator==(const BridgeSettings &, const BridgeSettings &) = default;
};

//! What the tuner's Bridge panel starts from: the defaults, with the feedback on force.x, the
//! component the project's own robot (hatpic-robot-sim, scripts/teleop-demo) sends its force
//! on. (hatpic-bridge keeps force.z, the published driver's.)
BridgeSettings panelDefaults();

//! `settings` with the network settings of `network`: the ROS version and the DDS domain. They
//! describe the network a machine is on, not a tuning, so a profile holds neither and opening
//! one keeps those in use (profile.md).
BridgeSettings withNetworkOf(BridgeSettings settings, const BridgeSettings &network);

// Bounds (checked by validate()).
constexpr double kMaxPublishRateHz = 1000; //!< the fastest telemetry there is
constexpr double kMaxFeedbackGain = 100;   //!< |gain| [N·m per unit]
constexpr double kMaxFeedbackLimit = 10;   //!< model.md's largest tau_limit [N·m]
constexpr double kMaxStaleAfter = 10;      //!< [s]
constexpr int kMaxDomainId = 232;          //!< DDS's port mapping allows 0…232
//! With an enable topic, the switch counts as released when no message came for this long [s]
//! (ros.md § Enable switch): a dead man that stops talking must fail safe.
constexpr double kEnableTimeout = 0.5;

// The settings held in types of their own.
struct AxisPlace
{}; //!< referenceAxis: "auto" or a twist component
struct ComponentPlace
{}; //!< feedback.component: a wrench component
struct QosPlace
{}; //!< qos
struct OriginPlace
{}; //!< poseOrigin: x, y, z [m]

//! Where a setting lives, and so how it is held: a topic name, other text, a number, a whole
//! number, or one of the four above.
using SettingPlace =
    std::variant<std::string Topics::*, std::string BridgeSettings::*, double BridgeSettings::*,
                 double FeedbackSettings::*, int BridgeSettings::*, AxisPlace, ComponentPlace,
                 QosPlace, OriginPlace>;

//! A number's or whole number's range ("must be RULE"); for text, its length.
struct SettingRange
{
    constexpr SettingRange(double low = 0, double high = 0, std::string_view unit = {},
                           bool aboveLow = false)
        : low(low), high(high), aboveLow(aboveLow), unit(unit)
    {}
    double low;
    double high;
    bool aboveLow;         //!< low itself is outside
    std::string_view unit; //!< after the range in messages: "Hz"
};

//! One setting, described once: the profile's JSON (profile.md), hatpic-bridge's options and
//! config file (ros.md) and validate() all follow from it. Defaults are BridgeSettings' own.
struct SettingSpec
{
    std::string_view key;   //!< in a profile's host.bridge; with '-' for '_' the option's name
    std::string_view label; //!< what a message calls it: "publish rate"
    SettingPlace place;
    //! Topics, the axis, the component and the QoS profile are valid by their form; the
    //! origin's range is each coordinate's.
    SettingRange range;
    std::string_view valueName; //!< in --help: "HZ"
    std::string_view help;      //!< --help's sentence
    bool inProfile = true;      //!< false: the network's (withNetworkOf()), no profile holds it
};

//! Every setting, in --help's order; a profile writes those it holds in the same order.
extern const std::array<SettingSpec, 27> kSettings;
//! The row of kSettings with this key (a program error when there is none).
const SettingSpec &settingSpec(std::string_view key);

//! The components of knobs 2 … kMaxAxes in `text` ("linear.y,linear.z,angular.z"; "force.y"
//! alike): nullopt unless it names kMaxAxes − 1 different ones.
std::optional<std::array<Component, kMaxAxes - 1>> parseKnobAxes(const std::string &text);
//! Each knob's joint name from the joint_name setting `text`: its names split at ',', knob 1
//! first; a knob it does not name is the first name with "_N" (its number) appended
//! ("hatpic_knob" → hatpic_knob, hatpic_knob_2, …). Empty when a name is empty or two are alike.
std::vector<std::string> jointNames(const std::string &text, int count = kMaxAxes);

//! A range's rule in words: "above 0 and at most 1000 Hz", "from 0 to 10 N·m", "a whole number
//! from 1 to 1000", "1 or 2". The one wording of every setting's and option's range (the
//! bridge's settings, hatpic-robot-sim's options).
std::string rangeRule(const SettingRange &range, bool whole);
//! Empty when `value` is within `range` (a whole number when `whole`), else "must be RULE, got
//! VALUE".
std::string rangeProblem(const SettingRange &range, double value, bool whole);
//! Empty for a valid topic name, else "'NAME' is not a ROS topic name (RULE)", the name cut as
//! echoedText() cuts it.
std::string topicNameProblem(const std::string &topic);

//! Every broken rule, one sentence each ("publish rate: must be above 0 and at most 1000 Hz,
//! got 0"), including: no two of the topics share a name (an input that is an output is a topic
//! loop; any two others differ in type). Empty means valid. The one check of the CLI, the
//! config file, a profile and the tuner's Bridge panel.
std::vector<std::string> validate(const BridgeSettings &settings);
//! Empty when the feedback's limit is within the device's tau_limit (as the device's float32,
//! atMostAsDeviceFloat()), else "limit: must be at most the device's tau_limit (0.44 N·m), got
//! 10": the device renders no more, so the feedback topic and the energy would report a torque
//! never felt. A tau_limit that is not known (NaN) or not above 0 (its own rule refuses it)
//! checks nothing. The one check of a profile (its host tau_limit), and of the bridge once it knows
//! the device's (Bridge::start(), a device that connects).
std::string limitProblem(const FeedbackSettings &feedback, double tauLimit);
//! Whether the bridge subscribes to that topic (the wrench, stamped or not, the enable switch
//! and the axis selection) rather than publishing it.
bool isInputTopic(std::string Topics::*topic);
//! A topic name rmw would accept: '/'-separated tokens of [A-Za-z0-9_], not starting with a
//! digit, no "//", no trailing '/'.
bool isValidTopicName(const std::string &name);
//! A namespace rmw and roscpp would accept: a topic name's form, with or without a leading '/'.
bool isValidNamespace(const std::string &name);
//! Empty for a valid namespace, else "'NS' is not a ROS namespace (RULE)", cut as echoedText().
std::string namespaceProblem(const std::string &name);
//! The name `topic` (the setting of `defaultTopic`'s place) has on the network under the
//! namespace `ns`: unchanged when `ns` is empty or `topic` is empty; "/NS/…" for a topic at its
//! default value (`defaultTopic`) or a relative one; any other absolute name as given.
std::string topicInNamespace(const std::string &topic, const std::string &defaultTopic,
                             const std::string &ns);

} // namespace hatpic::bridge
