// What bench_bridge's measuring peer takes its figures with: the knob → topic probe, the wrench
// round trip (its probe and its steps between ±kForce), a process's CPU over a window, and the
// table's rows (nearest-rank percentiles).
#pragma once

#include "ros/node.h"

#include <QtGlobal>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

namespace hatpic::bench {

using Clock = std::chrono::steady_clock;

constexpr double kForce = 0.5;         //!< wrench step: force.z alternates ±kForce [N]
constexpr double kGain = 0.154;        //!< hatpic-bridge's default gain [N·m/N]
constexpr double kTauTolerance = 1e-6; //!< τ_ext travels as float32 [N·m]

constexpr std::chrono::milliseconds kStepPeriod{100};   //!< a new wrench every 100 ms
constexpr std::chrono::milliseconds kEchoTimeout{1000}; //!< a step not seen by then counts as lost

inline double wallSeconds()
{
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
        .count();
}

inline double msBetween(Clock::time_point from, Clock::time_point to)
{
    return std::chrono::duration<double, std::milli>(to - from).count();
}

//! utime + stime of a process [s]; −1 when it cannot be read.
double cpuSeconds(qint64 pid);

//! Nearest-rank percentile of sorted values.
double percentile(const std::vector<double> &sorted, double p);

//! A row of the table: `values` [ms] counted, their p50, p95, p99 and maximum, then `note`.
void printRow(const char *what, std::vector<double> values, const char *note = "");

// The knob → topic figure: each JointState's arrival minus its stamp, while recording.
class KnobProbe
{
public:
    void onMessage(const ros::Message &message)
    {
        const double now = wallSeconds();
        const auto *joints = std::get_if<ros::JointState>(&message);
        if (!joints)
            return;
        m_seen.fetch_add(1);
        if (!m_recording.load())
            return;
        const std::lock_guard lock(m_mutex);
        m_latencies.push_back((now - ros::seconds(joints->header.stamp)) * 1e3);
    }
    std::uint64_t seen() const { return m_seen.load(); }
    void record(bool on, std::size_t expected = 0)
    {
        const std::lock_guard lock(m_mutex);
        if (on) {
            m_latencies.clear();
            m_latencies.reserve(expected);
        }
        m_recording.store(on);
    }
    std::vector<double> latencies() const
    {
        const std::lock_guard lock(m_mutex);
        return m_latencies;
    }

private:
    std::atomic<std::uint64_t> m_seen{0};
    std::atomic<bool> m_recording{false};
    mutable std::mutex m_mutex;
    std::vector<double> m_latencies; //!< [ms]
};

// The wrench round trip: waits for the first /hatpic/feedback that shows an expected τ_ext.
class FeedbackProbe
{
public:
    void onMessage(const ros::Message &message)
    {
        const auto now = Clock::now();
        const auto *wrench = std::get_if<ros::WrenchStamped>(&message);
        if (!wrench)
            return;
        const std::lock_guard lock(m_mutex);
        if (!m_seen && std::abs(wrench->wrench.torque.z - m_expected) < kTauTolerance) {
            m_seen = now;
            m_changed.notify_all();
        }
    }
    void expect(double tau)
    {
        const std::lock_guard lock(m_mutex);
        m_expected = tau;
        m_seen.reset();
    }
    //! When the expected τ_ext was first seen, waiting until `deadline`.
    std::optional<Clock::time_point> waitUntil(Clock::time_point deadline)
    {
        std::unique_lock lock(m_mutex);
        m_changed.wait_until(lock, deadline, [this] { return m_seen.has_value(); });
        return m_seen;
    }

private:
    std::mutex m_mutex;
    std::condition_variable m_changed;
    double m_expected = NAN;
    std::optional<Clock::time_point> m_seen;
};

ros::WrenchStamped wrenchOf(double force);

struct RoundTrips
{
    std::vector<double> ms; //!< publish → first /hatpic/feedback with the new τ_ext
    int lost = 0;           //!< steps not seen within kEchoTimeout
    bool warmedUp = false;
};

// Publishes kForce/2, a value no step uses, until the device's τ_ext shows it (the publisher
// is matched and the path works), then `steps` steps between ±kForce, kStepPeriod apart.
RoundTrips measureRoundTrips(ros::Publisher &publisher, FeedbackProbe &feedback, int steps);

struct CpuWindow
{
    qint64 pid;
    double cpu0;
    Clock::time_point t0 = Clock::now();
    explicit CpuWindow(qint64 p) : pid(p), cpu0(cpuSeconds(p)) {}
    //! % of one core since construction.
    double percent() const
    {
        return (cpuSeconds(pid) - cpu0) / (msBetween(t0, Clock::now()) * 1e-3) * 100;
    }
};

} // namespace hatpic::bench
