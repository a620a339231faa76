// An actuator for the benchmarks of the device's control cycle: it hands back a canned
// measurement (θ from a caller's function of the cycle count, fixed ω and τ) and keeps what it
// is commanded, so that the model's work is measured without a servo or a bus.
#pragma once

#include "firmware/actuator.h"

#include <cstddef>

namespace hatpic::bench {

//! `angleAt(k)` gives θ for the k-th measurement [rad].
template<typename T, typename AngleAt> class CannedActuator : public fw::Actuator<T>
{
public:
    explicit CannedActuator(AngleAt angleAt) : m_angleAt(angleAt) {}

    bool start(T &theta) override
    {
        theta = T(0);
        return true;
    }
    bool measure(fw::Measurement<T> &m) override
    {
        m.theta = T(m_angleAt(m_k++));
        m.omega = T(0.3);
        m.tau = T(-0.02);
        return true;
    }
    bool command(T theta, T omega) override
    {
        m_sink = theta + omega; // keeps the cycle's result alive
        return true;
    }
    void disable() override {}
    T sink() const { return m_sink; }

private:
    AngleAt m_angleAt;
    std::size_t m_k = 0;
    T m_sink{};
};

} // namespace hatpic::bench
