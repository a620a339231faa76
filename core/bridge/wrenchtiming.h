// How the robot's wrenches travel (ros.md § In the tuner: the Bridge panel): the age of the
// last one, the one-way delay its stamp tells, the time until the device shows the τ_ext it
// asked for, and how many were lost on the way — an estimate from the gaps between arrivals,
// since neither ROS tells a subscriber what it missed. Plain C++; the Bridge calls it with its
// mutex held, from the middleware's and the session's threads. Nothing allocates after
// construction.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace hatpic::bridge {

//! The recent values of a measurement: their median and 95th percentile (nearest rank).
struct Spread
{
    double median = std::numeric_limits<double>::quiet_NaN(); //!< NaN: none measured
    double p95 = std::numeric_limits<double>::quiet_NaN();
    std::uint64_t count = 0; //!< measured since the start (the spread is of the last kRecent)
};

//! The last kRecent values of a measurement, in a fixed ring.
class RecentValues
{
public:
    static constexpr std::size_t kRecent = 128;

    void add(double value);
    Spread spread() const;

private:
    std::array<double, kRecent> m_values{};
    std::size_t m_next = 0;
    std::size_t m_size = 0;
    std::uint64_t m_count = 0;
};

class WrenchTiming
{
public:
    //! A gap longer than this many typical intervals counts round(gap / interval) − 1 lost.
    static constexpr double kGapFactor = 1.5;
    //! Intervals needed before the typical one is known (and losses are counted).
    static constexpr std::uint64_t kMinIntervals = 8;
    //! A τ_ext the device has not shown within this is forgotten, not measured [s].
    static constexpr double kEchoTimeout = 1.0;
    //! τ_ext changes waiting for the device's echo, at most (the oldest goes first).
    static constexpr std::size_t kPendingEchoes = 16;

    struct Stats
    {
        //! Since the last wrench arrived [s]; NaN before the first.
        double age = std::numeric_limits<double>::quiet_NaN();
        //! The bridge's wall clock when it applied a wrench − the wrench's header stamp [s]:
        //! the one-way delay when both clocks agree (one machine, or NTP/PTP).
        Spread stampDelay;
        //! A wrench's arrival → the first telemetry sample whose τ_ext shows the value it asked
        //! for (only wrenches that changed τ_ext) [s].
        Spread echoDelay;
        double interval = std::numeric_limits<double>::quiet_NaN(); //!< median between arrivals [s]
        std::uint64_t lost = 0;      //!< estimated from arrival gaps (kGapFactor)
        std::uint64_t pauses = 0;    //!< silences longer than pauseAfter: not counted as lost
        std::uint64_t unstamped = 0; //!< wrenches without a stamp (not in stampDelay)
    };

    //! A silence longer than `seconds` is the robot pausing, not wrenches lost (the bridge
    //! uses its staleAfter: the feedback has gone to 0 and counted it stale by then).
    void setPauseAfter(double seconds) { m_pauseAfter = seconds; }

    //! A wrench arrived at monotonic time `now` [s], when the wall clock read `wallNow`;
    //! `stamp` is its header stamp, NaN when it has none [s since the Unix epoch].
    void arrived(double now, double wallNow, double stamp);
    //! The wrench that arrived at `now` [s] changed the τ_ext asked of the device to `tau`.
    void torqueAsked(double tau, double now);
    //! A telemetry sample decoded at monotonic time `at` [s] shows `tauExt` [N·m] (as float32,
    //! as it travels).
    void sampleShows(double tauExt, double at);

    //! At monotonic time `now` [s].
    Stats stats(double now) const;

private:
    struct Pending
    {
        float tau;
        double asked;
    };

    double m_pauseAfter = 0.5;
    double m_lastArrival = std::numeric_limits<double>::quiet_NaN();
    RecentValues m_intervals;
    RecentValues m_stampDelays;
    RecentValues m_echoDelays;
    std::uint64_t m_lost = 0;
    std::uint64_t m_pauses = 0;
    std::uint64_t m_unstamped = 0;
    std::array<Pending, kPendingEchoes> m_pending{}; //!< oldest first
    std::size_t m_pendingCount = 0;
};

} // namespace hatpic::bridge
