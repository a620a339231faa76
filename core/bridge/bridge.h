// The robot bridge: a device's samples out as ROS messages, the robot's wrench back in as
// τ_ext (ros.md). The robot path never waits for the thread that owns the Bridge (the GUI's
// in the tuner): each sample is published on the session thread the moment it is decoded
// (a SampleListener), and each wrench becomes τ_ext on the middleware thread it arrives on
// and goes straight to the session. The owner's thread only starts, stops, retunes and reads
// the statistics, and checks staleness on a timer as a second line behind the samples.
#pragma once

#include "axisselector.h"
#include "enablegate.h"
#include "profile/bridgesettings.h"
#include "referencemessages.h"
#include "rosendpoints.h"
#include "teleop/ratelimiter.h"
#include "teleop/wrenchfeedback.h"
#include "wrenchtiming.h"

#include "analysis/passivityobserver.h"

#include "session/deviceclient.h"
#include "session/samplelisteners.h"

#include <QObject>
#include <QTimer>

#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace hatpic::bridge {

struct BridgeStats
{
    std::array<std::uint64_t, kOutTopicCount> published{}; //!< messages out, per OutTopic (total)
    std::uint64_t writeErrors = 0;                         //!< writes the middleware refused
    WrenchFeedback::Counters wrenches;                     //!< wrenches in, rejected, stale
    double lastWrench = 0;                                 //!< last component received (NaN: none)
    //! The last wrench received, whole: force x y z [N], torque x y z [N·m]; NaN: none yet.
    std::array<double, 6> lastWrenchValues{NAN, NAN, NAN, NAN, NAN, NAN};
    //! Wrenches in a row, up to the last, whose chosen component was 0 while another was not:
    //! a robot that sends its force on another axis (the Bridge panel warns).
    std::uint64_t otherComponentStreak = 0;
    //! Wrenches ignored as the bridge's own feedback come back (RosEndpoints::Wrench::echo).
    std::uint64_t echoes = 0;
    double tauExt = 0;          //!< τ_ext asked of the device's knob 1 [N·m]
    AxisTorques torques{};      //!< … and of every knob, knob 1's first [N·m]
    double publishedTauExt = 0; //!< torque.z of the last /hatpic/feedback message [N·m]
    //! τ_ext of the newest sample the bridge saw, the device's own figure (NaN before any): up
    //! to date to the sample, unlike the batches the owner's thread gets every 20 ms [N·m].
    double deviceTauExt = std::numeric_limits<double>::quiet_NaN();
    WrenchTiming::Stats timing; //!< the wrenches' age, delays and (estimated) losses
    //! The energy τ_ext has put into the knob since start(), and the contact warning.
    analysis::PassivityObserver::State passivity;
    bool engaged = true;      //!< the enable switch: the knob drives the robot (ros.md)
    bool localEngaged = true; //!< the local switch (setEngaged())
    // The operator's axis selection (ros.md § Choosing the knob's axis).
    Component axis;                       //!< the axis knob 1 drives
    std::optional<Component> pendingAxis; //!< asked for, driven once the knob is in its dead zone
    Component feltComponent;              //!< the wrench component knob 1 feels
    std::uint64_t axisSwitches = 0;       //!< selections that took effect since start()
    std::uint64_t axisRejected = 0;       //!< selections refused (not an axis)
    std::string lastAxisRejected;         //!< the last one refused, as it came (echoedText())
};

class Bridge : public QObject, private SampleListener
{
    Q_OBJECT
public:
    //! How often the owner's thread re-checks staleness (the samples check it at their own
    //! rate; this covers a device that stopped sending) [ms].
    static constexpr int kCheckIntervalMs = 20;

    explicit Bridge(DeviceClient &client, QObject *parent = nullptr);
    ~Bridge() override; //!< stop()

    //! Opens the ROS endpoints and starts publishing. Empty on success, else one sentence —
    //! also for a limit above the connected device's tau_limit (limitProblem()).
    QString start(const BridgeSettings &settings);
    //! From now on every wrench is ignored and the device is asked for τ_ext = 0; publishing
    //! goes on, so the robot sees the 0 on the feedback topic. stop() or start() end it.
    void releaseFeedback();
    //! Asks the device for τ_ext = 0, then closes the endpoints.
    void stop();
    bool isRunning() const;

    //! Gain, limit, component and staleness take effect at once, while running. A limit above
    //! the connected device's tau_limit is refused (the sentence; nothing changes).
    QString setFeedbackSettings(const FeedbackSettings &feedback);
    //! Messages per topic per second from the next sample on, while running. A rate
    //! validate() refuses is ignored (false).
    bool setPublishRate(double rateHz);
    //! The local enable switch (the tuner's key or toggle), with the enable topic's if there
    //! is one: released, the twist, the joint jog and τ_ext are zero and the pose holds; engaged
    //! again, the pose goes on from where it held (ros.md § Enable switch). Engaged until
    //! released; start() keeps it as it is.
    void setEngaged(bool engaged);
    //! The reference mode picks the default axis (linear.x, or angular.z in rotation); an axis
    //! the operator chose (selectAxis()) stays.
    void setReferenceMode(ReferenceMode mode);
    //! The operator's choice, as the axis topics' (ros.md § Choosing the knob's axis): knob 1
    //! drives `axis` from the first sample in its dead zone, the references going on without a
    //! jump, and feels its wrench component. False while stopped (start() begins from the
    //! settings' axis).
    bool selectAxis(Component axis);

    BridgeSettings settings() const;
    BridgeStats stats() const;
    //! Where the endpoints are, for people ("ROS 1, master http://…"); empty when stopped.
    QString where() const;

private:
    void sampleDecoded(const Sample &sample) override;     //!< the session thread
    void onWrench(const RosEndpoints::Wrench &wrench);     //!< a middleware thread
    void onEnable(bool value);                             //!< a middleware thread
    void onAxis(const RosEndpoints::AxisRequest &request); //!< a middleware thread
    //! With m_mutex held: the component knob 1 feels (the chosen axis's, else the settings').
    Component feltComponent() const;
    //! With m_mutex held: the τ_ext the wrench asks of each knob at `t`, or 0 when released
    //! (by the enable switch, or by a limit above the device's).
    AxisTorques torquesAt(double t);
    void checkStale(); //!< any thread
    //! The connected device's tau_limit; NaN while not known (not connected) [N·m].
    double deviceTauLimit() const;
    //! With m_mutex held: τ_ext becomes `torques`; the device is told when it changed.
    void applyTorques(const AxisTorques &torques);
    //! The monotonic clock wrenches are dated on [s].
    static double now() { return double(sampleClockNs()) * 1e-9; }

    DeviceClient &m_client;
    QTimer m_checkTimer;

    // Publishing holds m_publishMutex, never m_mutex: a middleware may hand a message to a
    // subscription of the same process inside publish() (Cyclone DDS does, on the publishing
    // thread), and a wrench handler takes m_mutex. The order is m_publishMutex, then m_mutex;
    // m_endpoints changes only with both held, so stop() knows no write is under way once it
    // has taken the endpoints.
    std::mutex m_publishMutex;
    // Shared by the owner's, the session's and the middleware's threads: everything below is
    // read and written with m_mutex held.
    mutable std::mutex m_mutex;
    BridgeSettings m_settings;
    ReferenceMode m_mode = ReferenceMode::Translation;
    KnobComponents m_axes{}; //!< each knob's axis: m_settings' for m_mode
    std::unique_ptr<RosEndpoints> m_endpoints;
    WrenchFeedback m_feedback;
    WrenchTiming m_timing;
    analysis::PassivityObserver m_passivity;
    RateLimiter m_rate{100};
    AxisTorques m_torques{}; //!< asked of the device
    double m_publishedTauExt = 0;
    double m_deviceTauExt = std::numeric_limits<double>::quiet_NaN();
    bool m_released = false; //!< releaseFeedback(): wrenches ignored, τ_ext held at 0
    std::array<double, 6> m_lastWrench{NAN, NAN, NAN, NAN, NAN, NAN};
    std::uint64_t m_otherComponentStreak = 0;
    EnableGate m_gate;
    AxisSelector m_selector;
    std::uint64_t m_axisRejected = 0;
    std::string m_lastAxisRejected;
    std::uint64_t m_echoes = 0;
    std::array<std::uint64_t, kOutTopicCount> m_publishedBefore{}; //!< by endpoints now closed
    std::uint64_t m_writeErrorsBefore = 0;
};

} // namespace hatpic::bridge
