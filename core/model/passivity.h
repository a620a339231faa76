// The passivity controller (passivity.md): a one-port time-domain passivity observer and
// controller with an energy tank, run by the device core in its control cycle. It watches the
// energy the feedback port (τ_ext) delivers to the knob and, when the port has given back more
// than it absorbed, adds just enough damping to the admittance filter to take the excess out.
//
// Plain C++20, no Qt: the ESP32 (float) and the host (double) run the one implementation.
#pragma once

#include "params.h"

#include <algorithm>
#include <vector>

namespace hatpic {

//! The controller's tuning, in wire order (passivity.md, "Parameters"). The defaults turn it
//! on; they were chosen with the stability map and confirmed on the real teleoperation loop
//! (docs/teleop.md § The passivity controller, "Choosing the defaults").
struct PassivityParams
{
    double pc_damping_max = 0.7;  //!< β_max [N·m·s/rad]; 0 turns the controller off
    double pc_reserve_max = 0.02; //!< R_max, the tank's size [J]

    static constexpr int kFieldCount = 2;

    double field(int index) const;          //!< by wire index 0…1; NaN outside
    void setField(int index, double value); //!< by wire index; ignored outside

    //! β_max = 0: the controller off (the tank's size kept).
    static constexpr PassivityParams off() { return {0.0, 0.02}; }
    //! Whether the controller runs at all (β_max > 0).
    bool enabled() const { return pc_damping_max > 0; }

    friend bool operator==(const PassivityParams &, const PassivityParams &) = default;
};

std::string_view passivityFieldName(int index);
int passivityFieldIndex(std::string_view name);

//! Every violated rule of the table (finite, 0 … 1), in table order.
std::vector<Violation> validate(const PassivityParams &params);
//! Index of the first violating field (the device's reject reply), or -1; allocation-free.
int firstViolatingField(const PassivityParams &params);
//! The block as it travels (float32 fields, moved inward where rounding left a bound).
PassivityParams roundedForWire(const PassivityParams &params);
//! True when both blocks are the same float32 fields.
bool sameOnWire(const PassivityParams &a, const PassivityParams &b);
//! tidyDeviceParams() (params.h) for the passivity block.
PassivityParams tidyPassivityParams(const PassivityParams &params);

//! The law of one control cycle (passivity.md, "Per control cycle"): the energy tank R and
//! the damping β it asks of the admittance filter. Allocation-free, no exceptions.
template<typename T> class PassivityTank
{
public:
    //! What one cycle decided.
    struct Step
    {
        T beta{};    //!< β_k, the extra damping for this cycle's admittance step [N·m·s/rad]
        T tauPc{};   //!< τ_pc,k = −β_k·ω_k [N·m]
        T reserve{}; //!< R_k [J]
    };

    //! A new block: β_max and R_max in force from the next cycle. A smaller R_max caps the
    //! reserve at once.
    void configure(const PassivityParams &params)
    {
        m_betaMax = T(params.pc_damping_max);
        m_reserveMax = T(params.pc_reserve_max);
        m_reserve = std::min(m_reserve, m_reserveMax);
    }
    //! The tank full (R = R_max): at start and after a reset of the device.
    void fill() { m_reserve = m_reserveMax; }

    //! One cycle with the feedback rendered `tauExt` [N·m] and the filter's rate `omega`
    //! [rad/s], period `h` [s]. Does nothing (β = 0, R holds) when off, without τ_ext, or at
    //! rest (ω²·h ≤ 1e-12).
    Step step(T tauExt, T omega, T h)
    {
        Step s;
        if (!(m_betaMax > T(0)) || tauExt == T(0)) {
            s.reserve = m_reserve;
            return s;
        }
        const T w2h = omega * omega * h;
        const T candidate = m_reserve - tauExt * omega * h; // R*
        if (candidate < T(0) && w2h > T(1e-12))
            s.beta = std::min(m_betaMax, -candidate / w2h);
        m_reserve = std::min(m_reserveMax, candidate + s.beta * w2h);
        s.tauPc = -s.beta * omega;
        s.reserve = m_reserve;
        return s;
    }

    T reserve() const { return m_reserve; }

private:
    T m_betaMax{};
    T m_reserveMax{};
    T m_reserve{};
};

} // namespace hatpic
