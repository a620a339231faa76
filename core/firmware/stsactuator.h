// The knob's actuator over the STS3032 bus (servo.md § 3–4).
//
// Plain C++20: no Qt, no OS calls, no exceptions, no RTTI, no allocation. Used from the
// control context only.
#pragma once

#include "firmware/actuator.h"
#include "firmware/sts3032.h"
#include "firmware/stsbus.h"

#include <cstdint>

namespace hatpic::fw {

//! Actuator<T> over an StsBus. Each call is whole bus transactions; a failed one returns false
//! and leaves the caller's data untouched. It does not count consecutive failures: the control
//! cycle does (servo.md § 1, 100 in a row disable the torque).
template<typename T> class StsActuator : public Actuator<T>
{
public:
    struct Config
    {
        std::uint8_t id = 1;                                 //!< servo id on the bus
        std::int32_t centerTick = sts::kDefaultCenterTick;   //!< tick of θ = 0 [tick]
        T tauLimit = T(sts::kDefaultTauLimit);               //!< torque at load ±1000 [N·m]
        std::uint32_t timeoutUs = StsBus::kDefaultTimeoutUs; //!< reply timeout [µs]
    };

    //! Sets the bus's reply timeout to config.timeoutUs.
    StsActuator(StsBus &bus, const Config &config);

    //! PING, (model number for the log), WRITE mode 0, READ present position, WRITE goal =
    //! present position, WRITE torque enable 1. `theta` [rad] is written only on success.
    bool start(T &theta) override;
    //! One READ of 6 bytes at 56: position, speed, load → θ, ω, τ.
    bool measure(Measurement<T> &m) override;
    //! WRITE goal position centerTick + round(θ·4096/2π), clamped to 0…4095; `omega` ignored.
    bool command(T theta, T omega) override;
    //! WRITE torque enable 0 (the result is not checked: there is nothing left to do).
    void disable() override;

    const Config &config() const { return m_config; }
    //! Model number read at start (addresses 3–4), 0 when it could not be read. Only for the
    //! log: servo revisions and clones differ, and no value is refused.
    std::uint16_t modelNumber() const { return m_modelNumber; }

private:
    bool writeByte(std::uint8_t addr, std::uint8_t value);

    StsBus &m_bus;
    Config m_config;
    std::uint16_t m_modelNumber = 0;
};

extern template class StsActuator<float>;
extern template class StsActuator<double>;

} // namespace hatpic::fw
