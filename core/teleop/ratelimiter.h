// The rate the bridge's messages go out at (ros.md § Topics): at most `rateHz` per second by
// the samples' own clock. Plain C++; the bridge and the in-process loop (loopsimulation.h)
// both pace their twists with it.
#pragma once

#include <optional>

namespace hatpic::bridge {

//! Picks samples so that at most `rateHz` per second go out, on average exactly that many when
//! the samples come faster, by the samples' own clock (so batching on the host does not
//! change the rate).
class RateLimiter
{
public:
    explicit RateLimiter(double rateHz) { setRate(rateHz); }
    void setRate(double rateHz) { m_period = 1.0 / rateHz; }
    //! True when the sample at time `t` [s] is to be published.
    bool due(double t);
    void reset() { m_next.reset(); }

private:
    double m_period = 0.01;
    std::optional<double> m_next;
};

} // namespace hatpic::bridge
