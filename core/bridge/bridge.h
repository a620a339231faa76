// The robot bridge: a device's samples out as ROS 2 messages, the robot's wrench back in as
// τ_ext (ros.md). Lives on the thread of the DeviceClient it serves (the GUI's or a headless
// program's); the wrench arrives on a DDS thread and is handed over through one slot, so a
// flood of wrenches never queues more than one event.
#pragma once

#include "profile/bridgesettings.h"
#include "referencemessages.h"
#include "rosendpoints.h"
#include "wrenchfeedback.h"

#include "session/deviceclient.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <deque>
#include <memory>
#include <mutex>

namespace hatpic::bridge {

struct BridgeStats
{
    std::array<std::uint64_t, kOutTopicCount> published{}; //!< messages out, per OutTopic (total)
    std::uint64_t writeErrors = 0;                         //!< writes DDS refused
    std::uint64_t overflow = 0; //!< wrenches dropped unread (a flood while this thread was busy)
    WrenchFeedback::Counters wrenches; //!< wrenches in, rejected, stale
    double lastWrench = 0;             //!< last component received (NaN: none)
    double tauExt = 0;                 //!< τ_ext asked of the device [N·m]
    double publishedTauExt = 0;        //!< torque.z of the last /hatpic/feedback message [N·m]
};

class Bridge : public QObject
{
    Q_OBJECT
public:
    //! How often staleness is checked, and the longest a changed τ_ext waits [ms].
    static constexpr int kCheckIntervalMs = 20;
    //! Wrenches that may wait for this object's thread; beyond that the oldest is dropped.
    static constexpr std::size_t kMaxArrivals = 64;

    explicit Bridge(DeviceClient &client, QObject *parent = nullptr);
    ~Bridge() override; //!< stop()

    //! Opens the DDS endpoints and starts publishing. Empty on success, else one sentence.
    QString start(const BridgeSettings &settings);
    //! From now on every wrench is ignored and the device is asked for τ_ext = 0; publishing
    //! goes on, so the robot sees the 0 on the feedback topic. stop() or start() end it.
    void releaseFeedback();
    //! Asks the device for τ_ext = 0, then closes the endpoints.
    void stop();
    bool isRunning() const { return m_endpoints != nullptr; }

    //! Gain, limit, component and staleness take effect at once, while running.
    void setFeedbackSettings(const FeedbackSettings &feedback);
    //! Messages per topic per second from the next sample on, while running. A rate
    //! validate() refuses is ignored (false).
    bool setPublishRate(double rateHz);
    //! The reference mode picks the default axis (linear.x, or angular.z in rotation).
    void setReferenceMode(ReferenceMode mode) { m_mode = mode; }

    const BridgeSettings &settings() const { return m_settings; }
    BridgeStats stats() const;
    //! Where the endpoints are, for people ("ROS 1, master http://…"); empty when stopped.
    QString where() const;

Q_SIGNALS:
    //! τ_ext asked of the device changed (a wrench, its staleness, or stop()).
    void feedbackChanged(double tauExt);

private:
    void onSamples(const SampleBatch &batch);
    void onWrench(const RosEndpoints::Wrench &wrench); //!< a DDS thread
    void takeWrench();                                 //!< this object's thread
    void applyTorque(double tau);
    double now() const { return double(m_clock.nsecsElapsed()) * 1e-9; }

    DeviceClient &m_client;
    BridgeSettings m_settings;
    ReferenceMode m_mode = ReferenceMode::Translation;
    std::unique_ptr<RosEndpoints> m_endpoints;
    WrenchFeedback m_feedback;
    RateLimiter m_rate{100};
    QElapsedTimer m_clock;
    QTimer m_checkTimer;
    double m_tauExt = 0;
    double m_publishedTauExt = 0;
    bool m_released = false; //!< releaseFeedback(): wrenches ignored, τ_ext held at 0
    std::array<std::uint64_t, kOutTopicCount> m_publishedBefore{}; //!< by endpoints now closed
    std::uint64_t m_writeErrorsBefore = 0;

    // Handed over from the DDS thread: wrenches with their arrival time, and whether an event
    // to take them is on its way.
    struct Arrival
    {
        RosEndpoints::Wrench wrench;
        double time = 0; //!< [s] on m_clock
    };
    mutable std::mutex m_mutex;
    std::deque<Arrival> m_arrivals; //!< at most kMaxArrivals
    bool m_takePosted = false;
    std::uint64_t m_overflow = 0; //!< arrivals dropped (oldest first) while none was taken
};

} // namespace hatpic::bridge
