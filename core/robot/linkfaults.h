// A worse network on purpose (robot.md § Topics and QoS): each message is delayed by a fixed
// latency plus a uniform extra, kept in order, or dropped at random — seeded, so a run
// repeats. Plain C++; the caller supplies the clock and serialises access.
#pragma once

#include "model/params.h"

#include <cstdint>
#include <deque>
#include <random>
#include <utility>
#include <vector>

namespace hatpic::robot {

struct LinkFaults
{
    double delay = 0;  //!< added one-way latency [s]
    double jitter = 0; //!< uniform extra latency in [0, jitter) [s]
    double loss = 0;   //!< fraction of messages dropped, 0 … 1

    bool any() const { return delay > 0 || jitter > 0 || loss > 0; }
    friend bool operator==(const LinkFaults &, const LinkFaults &) = default;
};

constexpr double kMaxLinkDelay = 10; //!< delay and jitter at most [s]

//! Every broken rule: finite values, 0 ≤ delay, jitter ≤ kMaxLinkDelay, 0 ≤ loss ≤ 1; fields
//! named as the options ("delay", "jitter", "loss"). Empty means valid.
std::vector<Violation> validate(const LinkFaults &faults);

template<typename T> class FaultyChannel
{
public:
    //! Messages in flight at most; beyond that the oldest is dropped (counted as overflow).
    static constexpr std::size_t kMaxInFlight = 16384;

    struct Counters
    {
        std::uint64_t sent = 0;     //!< messages handed in
        std::uint64_t lost = 0;     //!< … dropped by the loss fraction
        std::uint64_t overflow = 0; //!< … dropped because too many were in flight
        std::uint64_t delivered = 0;
    };

    FaultyChannel(const LinkFaults &faults, std::uint64_t seed) : m_faults(faults), m_rng(seed) {}

    //! A message sent at `now` [s]: due at now + delay + U(0, jitter), never before the one
    //! sent before it; or lost.
    void send(T message, double now)
    {
        ++m_counters.sent;
        if (m_faults.loss > 0 && m_uniform(m_rng) < m_faults.loss) {
            ++m_counters.lost;
            return;
        }
        double due = now + m_faults.delay;
        if (m_faults.jitter > 0)
            due += m_faults.jitter * m_uniform(m_rng);
        if (!m_inFlight.empty())
            due = std::max(due, m_inFlight.back().first); // order kept
        if (m_inFlight.size() >= kMaxInFlight) {
            m_inFlight.pop_front();
            ++m_counters.overflow;
        }
        m_inFlight.emplace_back(due, std::move(message));
    }

    //! Hands every message due at `now` [s] to `deliver`, oldest first.
    template<typename Deliver> void deliverDue(double now, Deliver &&deliver)
    {
        while (!m_inFlight.empty() && m_inFlight.front().first <= now) {
            T message = std::move(m_inFlight.front().second);
            m_inFlight.pop_front();
            ++m_counters.delivered;
            deliver(message);
        }
    }

    std::size_t inFlight() const { return m_inFlight.size(); }
    const Counters &counters() const { return m_counters; }
    const LinkFaults &faults() const { return m_faults; }

private:
    LinkFaults m_faults;
    std::mt19937_64 m_rng;
    std::uniform_real_distribution<double> m_uniform{0.0, 1.0};
    std::deque<std::pair<double, T>> m_inFlight; //!< (due [s], message), due never decreasing
    Counters m_counters;
};

} // namespace hatpic::robot
